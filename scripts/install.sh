#!/usr/bin/env bash
# Installs the workbench for the current user: FreeCAD 0.20.2 on Debian reads user addons
# from $XDG_DATA_HOME/FreeCAD/Mod (default ~/.local/share/FreeCAD/Mod; ~/.FreeCAD/Mod is
# NOT read). A symlink to the build's assembled Mod/HoleFill keeps it current on rebuilds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HOLEFILL_BUILD_DIR:-$root/build}
mods="${XDG_DATA_HOME:-$HOME/.local/share}/FreeCAD/Mod"
mkdir -p "$mods"
ln -sfn "$build/Mod/HoleFill" "$mods/HoleFill"
echo "[install] HoleFill workbench -> $mods/HoleFill"
