#!/usr/bin/env bash
# Fuzz every reader and verb with libFuzzer under ASan+UBSan (issue 22, docs/fuzzing.md):
#   ./scripts/fuzz.sh [SECONDS] [HARNESS ...]      SECONDS per harness (default 600); all harnesses
# Each harness starts from its committed seeds (tests/fuzz/corpus/NAME) and grows a working corpus in
# build-fuzz/fuzz/NAME/corpus; a crash, a sanitizer report, an input slower than 120 s (ASan and
# UBSan make the verbs 20-40 times slower than a release build: a fill of 0.5 s takes 20) or one using
# more than 4 GB lands in build-fuzz/fuzz/NAME/ as crash-*, timeout-*, oom-* or leak-*. The table
# at the end gives executions, corpus size and findings per harness; the exit is 1 when anything
# was found. A finding becomes a regression input: copy it into tests/fuzz/corpus/NAME/ (the smoke
# in ./scripts/test.sh replays it) and give it a named test where the class is new.
set -euo pipefail
seconds=${1:-600}
shift || true
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(brep_text model_file mesh_obj mesh_off mesh_ply mesh_stl cage json cloud mesh_fill gnurbs fit fill points)
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
. "$(dirname "$0")/sanitized_build.sh" "${targets[@]}" holefill_step
# FUZZ_JOBS harnesses at a time (default: half the cores; each is one process).
jobs=${FUZZ_JOBS:-$(( $(nproc) > 1 ? $(nproc) / 2 : 1 ))}
run_one() {
  local h=$1 dir="$fuzz_build/fuzz/$1"
  mkdir -p "$dir/corpus"
  local rc=0  # (a plain `$?` never comes: set -e would end this subshell at a finding)
  "$fuzz_build/tests/fuzz/fuzz_$h" -max_total_time="$seconds" -timeout=120 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$dir/" "$dir/corpus" "$root/tests/fuzz/corpus/$h" > "$dir/fuzz.log" 2>&1 || rc=$?
  echo "$rc" > "$dir/rc"
}
for h in "${harnesses[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  echo "[fuzz] $h: $seconds s"
  run_one "$h" &
done
wait
found=0
printf '%-11s %10s %12s %8s %9s %4s\n' harness time executions corpus findings rc
for h in "${harnesses[@]}"; do
  dir="$fuzz_build/fuzz/$h"
  rc=$(cat "$dir/rc")
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$dir/fuzz.log" | grep -o '[0-9]*$' || echo "?")
  size=$(find "$dir/corpus" -type f | wc -l)
  findings=$(find "$dir" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) | wc -l)
  if [ "$rc" -ne 0 ] || [ "$findings" -ne 0 ]; then found=1; fi
  printf '%-11s %8s s %12s %8s %9s %4s\n' "$h" "$seconds" "$execs" "$size" "$findings" "$rc"
done
exit $found
