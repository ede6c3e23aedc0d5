#!/usr/bin/env bash
# Orientation check on the B-rep hole corpus: every fill that closes its part must give a solid of
# positive volume (outward normals). Sewing decides the orientation by rays from the new face's
# neighbours and falls back to OCCT's whole-model classifier (App/brep/face_building.cpp).
#   tests/bench/corpus_orientation.sh [CORPUS_DIR (corpus-out/brep)] [EVERY (1)] [OFFSET (0)]
# Prints one line per inside-out result and a summary; exits 1 when there is any.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
corpus=${1:-$root/corpus-out/brep}
every=${2:-1}
offset=${3:-0}
cli=${HOLEFILL_CLI:-$root/build/App/holefill}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0 closed=0 inverted=0
for d in $(ls "$corpus" | grep -v index.json | awk -v k="$every" -v o="$offset" '(NR - 1) % k == o'); do
  out=$("$cli" fill "$corpus/$d/hole.brep" --out "$tmp/o.brep" --volume --json 2>/dev/null) || true
  r=$(echo "$out" | /usr/bin/python3 -c "import json,sys; r=json.load(sys.stdin)[0]; print(int(r['closed_solid']), r['volume'])" 2>/dev/null) || continue
  n=$((n + 1))
  set -- $r
  [ "$1" = 1 ] || continue
  closed=$((closed + 1))
  if ! /usr/bin/python3 -c "import sys; sys.exit(0 if $2 > 0 else 1)"; then
    inverted=$((inverted + 1))
    echo "inside out: $d (volume $2)"
  fi
done
echo "holes $n, closed solids $closed, inside out $inverted"
[ "$inverted" = 0 ]
