#!/usr/bin/env bash
# Runs one GUI test: the real FreeCAD under Xvfb, addon installed in a throwaway HOME.
# Pass = exit 0 and the result file says ok. Screenshots go to $HOLEFILL_SHOTS (default build/shots).
set -u
test=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")/.." && pwd)
. "$here/fcenv.sh" "$2"
export HOLEFILL_SHOTS=${HOLEFILL_SHOTS:-$(cd "$2/../.." && pwd)/shots}
export PYTHONPATH="$here/gui${PYTHONPATH:+:$PYTHONPATH}"
mkdir -p "$HOLEFILL_SHOTS"
# -dpi 96: otherwise Qt scales and GL viewport pixels differ from widget pixels (clicks miss).
# timeout inside xvfb-run so a hung FreeCAD is killed and Xvfb still reaped.
xvfb-run -a -s "-screen 0 1280x1024x24 -dpi 96 -nolisten tcp" \
  timeout -k 10 ${HF_GUI_TIMEOUT:-240} freecad "$test" > "$HOME/log.txt" 2>&1
rc=$?
grep '^\[guitest\]\|Traceback\|Error\|error' "$HOME/log.txt" | tail -n 40
ok=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("ok"))' "$HF_RESULT" 2>/dev/null || echo missing)
echo "rc=$rc result=$ok"
[ -n "${HF_KEEP_HOME:-}" ] && echo "home kept: $HOME" || rm -rf "$HOME"
[ "$rc" = 0 ] && [ "$ok" = True ]
