#!/usr/bin/env bash
# Trains the UVTran weights on this machine's CPU, in the background-friendly way the shipped
# weights were made: checkpoints every few minutes, and running it again resumes where it stopped.
#   ./scripts/train_uvtran.sh [OUT_DIR] [extra holefill train options]
# Then: cp OUT_DIR/uvtran.pt Resources/models/ and update Resources/models/uvtran.md.
# Never run by CI.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/prepare.sh"
out="${1:-$root/runs/uvtran}"
shift || true
mkdir -p "$out"
# The recipe of the shipped weights (Resources/models/uvtran.md); options given later win.
"$build/App/holefill" train uvtran --out "$out" \
  --width 96 --feed-forward 192 --layers 2 --heads 4 --batch 32 \
  --stage1-steps 2500 --stage2-steps 3000 --validate-every 250 --validation-samples 256 \
  --threads 2 --checkpoint-minutes 5 "$@" 2>&1 | tee -a "$out/train.log"
/usr/bin/python3 "$root/scripts/plot_training.py" "$out/log.csv" "$out/training.png"
