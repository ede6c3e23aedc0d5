#!/usr/bin/env bash
# Installs the workbench for the current user, as an addon folder of its own: the build's
# assembled Mod/HoleFill (Python package, compiled module, learned library, weights, icons)
# copied into the user Mod folder of the FreeCAD found on PATH, asked of FreeCAD itself
# (0.20 and 1.0 on Debian: $XDG_DATA_HOME/FreeCAD/Mod; 1.1: a versioned folder under it).
# A copy, not a link into the build tree: rebuilding or deleting the checkout leaves the
# installed workbench as it was; run this again to update it.
#   ./scripts/install.sh               install (or replace an earlier install)
#   ./scripts/install.sh --uninstall   remove it again (only a folder this script installed)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HOLEFILL_BUILD_DIR:-$root/build}
marker=.holefill-installed

user_mod_dir() {
  local data=""
  if command -v freecadcmd >/dev/null; then
    # FreeCAD prints its banner too; the line we ask for is marked.
    data=$(timeout 60 freecadcmd -c 'import FreeCAD; print("HOLEFILL_DATA=" + FreeCAD.getUserAppDataDir())' 2>/dev/null |
      sed -n 's/^HOLEFILL_DATA=//p' | tail -1) || true
  fi
  [ -n "$data" ] || data="${XDG_DATA_HOME:-$HOME/.local/share}/FreeCAD/"
  echo "${data%/}/Mod"
}

mods=$(user_mod_dir)
dest="$mods/HoleFill"
if [ "${1:-}" = "--uninstall" ]; then
  if [ -L "$dest" ]; then
    rm "$dest"  # a link left by an older install.sh
  elif [ -d "$dest" ]; then
    [ -f "$dest/$marker" ] || { echo "[install] $dest was not installed by this script; left as it is" >&2; exit 1; }
    rm -rf --one-file-system "$dest"
  else
    echo "[install] nothing installed at $dest"
    exit 0
  fi
  echo "[install] HoleFill workbench removed from $mods"
  exit 0
fi

src="$build/Mod/HoleFill"
[ -f "$src/Init.py" ] && ls "$src"/HoleFillApp*.so >/dev/null 2>&1 ||
  { echo "[install] no assembled addon in $src: build first (./scripts/build.sh)" >&2; exit 1; }
if [ -e "$dest" ] && [ ! -L "$dest" ] && [ ! -f "$dest/$marker" ]; then
  echo "[install] $dest exists and was not installed by this script; left as it is" >&2
  exit 1
fi
mkdir -p "$mods"
# Copied beside, then swapped in: a failed copy leaves the earlier install whole.
tmp=$(mktemp -d "$mods/.HoleFill.XXXXXX")
trap 'rm -rf --one-file-system "$tmp"' EXIT
chmod 755 "$tmp"
cp -R "$src/." "$tmp/"
echo "installed by HoleFill's scripts/install.sh from $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo "a source tree") on $(date -u +%F)" >"$tmp/$marker"
rm -rf --one-file-system "$dest"
mv "$tmp" "$dest"
trap - EXIT
echo "[install] HoleFill workbench -> $dest"
