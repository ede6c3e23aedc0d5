#!/usr/bin/env bash
# Builds the B-rep hole corpus (tests/corpus/brep_holes.py) from the real models that ship in
# Debian's packages, in ${CORPUS_OUT:-corpus-out/brep} (generated, not committed), and copies its
# index to tests/corpus/brep_holes_index.json (committed) when CORPUS_COMMIT_INDEX=1.
set -euo pipefail
. "$(dirname "$0")/prepare.sh"
export CORPUS_OUT=${CORPUS_OUT:-$root/corpus-out/brep}
mkdir -p "$CORPUS_OUT"
(
  . tests/fcenv.sh "$build/Mod/HoleFill"
  freecadcmd tests/corpus/brep_holes.py 2>&1 | grep -v '^ *#\|^$\|Juergen\|licensed\|wouldn.t be possible\|Libs:'
  rm -rf "$HOME"
)
if [ "${CORPUS_COMMIT_INDEX:-0}" = 1 ]; then cp "$CORPUS_OUT/index.json" tests/corpus/brep_holes_index.json; fi
