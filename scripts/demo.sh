#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: install what is missing, build, install the
# workbench, fill the bundled sample holes headless with freecadcmd, and write to demo-out/:
# the filled models (.FCStd, .step), a continuity report per hole (.json + the printed
# table) and a picture of each result (.png, rendered by FreeCAD under Xvfb).
set -euo pipefail
. "$(dirname "$0")/prepare.sh"
./scripts/install.sh
out="$root/demo-out"
rm -rf "$out" && mkdir -p "$out"
# Headless job in a throwaway FreeCAD home (the user's own settings stay untouched).
(
  . tests/fcenv.sh "$build/Mod/HoleFill"
  export HOLEFILL_DEMO_OUT="$out" HOLEFILL_SAMPLES="$root/Resources/samples"
  freecadcmd scripts/demo_job.py 2>&1 | grep -v '^ *#\|^$\|Juergen\|licensed\|wouldn.t be possible\|Libs:'
  test -f "$out/summary.json" || { echo "[demo] the fill job did not finish" >&2; exit 1; }
  # Pictures: the real FreeCAD GUI under Xvfb renders each saved document.
  xvfb-run -a -s "-screen 0 1280x1024x24 -dpi 96 -nolisten tcp" \
    timeout -k 10 300 freecad scripts/demo_render.py >"$HOME/render.log" 2>&1 || true
  ls "$out"/*.png >/dev/null 2>&1 || { echo "[demo] rendering failed:"; tail -20 "$HOME/render.log"; exit 1; }
  rm -rf "$HOME"
)
echo "[demo] results in $out:"
ls -1 "$out"
