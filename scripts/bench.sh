#!/usr/bin/env bash
# Peer benchmarks (not part of ctest): builds, then runs tests/bench/bench_fill.py in freecadcmd,
# HoleFill NP/MVC vs FreeCAD Surface Filling (GeomPlate) on the same holes, in one run.
# Prints the table; results in bench-out/. Paste the printed table into docs/benchmarks.md.
set -euo pipefail
. "$(dirname "$0")/prepare.sh"
export BENCH_OUT="$root/bench-out"
mkdir -p "$BENCH_OUT"
(
  . tests/fcenv.sh "$build/Mod/HoleFill"
  freecadcmd tests/bench/bench_fill.py 2>&1 | grep -v '^ *#\|^$\|Juergen\|licensed\|wouldn.t be possible\|Libs:\|Recompute\|(100 %)\|(50 %)'
  rm -rf "$HOME"
)
echo "machine: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), $(date -u +%Y-%m-%d)"
