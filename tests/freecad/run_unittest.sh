#!/usr/bin/env bash
# The headless tests through FreeCAD's own test runner, as a user runs them: `freecadcmd -t
# HoleFillTests` with the addon installed in a throwaway HOME. Pass: every test module of
# tests/freecad is there, every test ran, and unittest says OK.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
. "$here/fcenv.sh" "$1"
timeout -k 10 900 freecadcmd -t HoleFillTests > "$HOME/log.txt" 2>&1
rc=$?
grep -E "^(FAIL|ERROR):|^Ran |^OK|^FAILED|Error" "$HOME/log.txt" | tail -n 40
expected=$(grep -h "^def test_" "$here"/freecad/test_*.py | wc -l)
ran=$(sed -n 's/^Ran \([0-9]*\) tests\? in.*/\1/p' "$HOME/log.txt" | tail -1)
ok=$(grep -c "^OK" "$HOME/log.txt")
rm -rf "$HOME"
echo "rc=$rc ran=${ran:-0} expected=$expected"
[ "$rc" = 0 ] && [ "$ok" -ge 1 ] && [ "${ran:-0}" = "$expected" ]
