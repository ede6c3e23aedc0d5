# Sourced by the CLI test scripts: $H (the holefill binary), $T (a fresh scratch folder), $PY,
# pass/fail counters, and a check that a refused command exits 1 with one "holefill: ..." line
# naming the problem and writes none of its outputs.
set -u
H=${HOLEFILL:?}
T=$1
PY=${PYTHON:-/usr/bin/python3}
rm -rf "$T"; mkdir -p "$T"
fail=0; pass=0
ok() { pass=$((pass+1)); echo "ok   $1"; }
bad() { fail=$((fail+1)); echo "FAIL $1"; }
# expect_refusal NAME WANTED "OUTPUT FILES" holefill-arguments...
expect_refusal() {
  local name=$1 want=$2 outputs=$3 written=""; shift 3
  "$H" "$@" >"$T/out" 2>"$T/err"; local rc=$?
  for f in $outputs; do [ -e "$f" ] && written="$written $f"; done
  if [ "$rc" = 1 ] && grep -q "^holefill: .*$want" "$T/err" && [ -z "$written" ]; then
    ok "$name: $(head -1 "$T/err")"
  else
    bad "$name: rc=$rc, written:${written:- nothing}, stderr: $(cat "$T/err")"
  fi
  rm -f $outputs
}
finish() {
  echo "$pass passed, $fail failed"
  [ "$fail" = 0 ]
}
