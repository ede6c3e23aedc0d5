#!/usr/bin/env bash
# Trains the BIDGCN weights on this machine's CPU the way the shipped ones were made:
# checkpoints every few minutes, and running it again resumes where it stopped.
#   ./scripts/train_bidgcn.sh [OUT_DIR] [extra holefill train options, e.g. --init Resources/models/bidgcn.pt]
# Then: cp OUT_DIR/bidgcn.pt Resources/models/ and update Resources/models/bidgcn.md.
# Never run by CI.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/prepare.sh"
out="${1:-$root/runs/bidgcn}"
shift || true
mkdir -p "$out"
# The recipe of the shipped weights (Resources/models/bidgcn.md); options given later win.
"$build/App/holefill" train bidgcn --out "$out" --steps 6000 --batch 4 --lr 1e-3 --supervision 1 \
  --validate-every 250 --validation-clouds 32 --threads 2 --checkpoint-minutes 5 "$@" 2>&1 | tee -a "$out/train.log"
/usr/bin/python3 "$root/scripts/plot_training.py" "$out/log.csv" "$out/training.png"
