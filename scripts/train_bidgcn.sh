#!/usr/bin/env bash
# Trains the BIDGCN weights on this machine's CPU the way the shipped ones were made: a chain of
# phases, each fine-tuning the previous one's weights on fresh clouds with a lower learning rate
# (Resources/models/bidgcn.md, "Training"). Every phase checkpoints every few minutes, and running
# the script again resumes the phase that was interrupted and skips the finished ones.
#   ./scripts/train_bidgcn.sh [OUT_DIR] [extra holefill train options for every phase, e.g. --threads 1]
# Then: cp OUT_DIR/bidgcn.pt Resources/models/ and update Resources/models/bidgcn.md.
# Hours on 2 cores; never run by CI.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/prepare.sh"
out="${1:-$root/runs/bidgcn}"
shift || true
mkdir -p "$out"
init=""
# phase NAME OPTIONS...: one `holefill train bidgcn` run in OUT_DIR/NAME, started from the
# previous phase's weights; options given later (the script's extra ones) win.
phase() {
  local dir="$out/$1"
  shift
  mkdir -p "$dir"
  if [ ! -f "$dir/bidgcn.pt" ]; then
    "$build/App/holefill" train bidgcn --out "$dir" ${init:+--init "$init"} --batch 4 --validate-every 500 \
      --validation-clouds 32 --threads 2 --checkpoint-minutes 5 "$@" "${extra[@]}" 2>&1 | tee -a "$dir/train.log"
  fi
  init="$dir/bidgcn.pt"
}
extra=("$@")
phase 1 --steps 6000 --lr 1e-3 --supervision 1 --first-cloud 0
phase 2 --steps 2931 --lr 5e-4 --supervision 1 --first-cloud 24000
phase 3 --steps 9000 --lr 3e-4 --supervision 0.1 --first-cloud 40000
phase 4 --steps 6000 --lr 1.5e-4 --supervision 0.01 --first-cloud 80000
cp "$init" "$out/bidgcn.pt"
"$build/App/holefill" eval bidgcn --weights "$out/bidgcn.pt" --clouds 100 --threads 2
for p in 1 2 3 4; do /usr/bin/python3 "$root/scripts/plot_training.py" "$out/$p/log.csv" "$out/$p/training.png"; done
