#!/usr/bin/env bash
# Runs one headless FreeCAD test (freecadcmd) with the addon installed in a throwaway HOME.
# Pass = exit 0 and the result file says ok (freecadcmd does not always propagate exit codes).
set -u
test=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")/.." && pwd)
. "$here/fcenv.sh" "$2"
export PYTHONPATH="$here/freecad${PYTHONPATH:+:$PYTHONPATH}"
timeout -k 10 500 freecadcmd "$test" > "$HOME/log.txt" 2>&1
rc=$?
grep -v '^ *#\|^$\|FreeCAD\|(c) Juergen\|licensed\|^\s*[#]' "$HOME/log.txt" | grep -v '^ *$' | tail -n 60
ok=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("ok"))' "$HF_RESULT" 2>/dev/null || echo missing)
rm -rf "$HOME"
[ "$rc" = 0 ] && [ "$ok" = True ]
