#!/usr/bin/env bash
# scripts/install.sh and --uninstall in a throwaway HOME: the addon lands as a folder of its own
# (not a link into the build) in the user Mod folder FreeCAD itself names, FreeCAD loads the
# workbench's compiled module from that copy, a folder the script did not install is never
# replaced or removed, and --uninstall leaves no trace.
# Usage: install_uninstall.sh SOURCE_ROOT BUILD_DIR
set -euo pipefail
src=$1 build=$2
export HOME=$(mktemp -d -t holefill-install.XXXXXX)
unset XDG_DATA_HOME XDG_CONFIG_HOME
trap 'rm -rf "$HOME"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
mods="$HOME/.local/share/FreeCAD/Mod"
HOLEFILL_BUILD_DIR=$build "$src/scripts/install.sh"
[ -d "$mods/HoleFill" ] && [ ! -L "$mods/HoleFill" ] || fail "no installed folder at $mods/HoleFill"
for f in Init.py InitGui.py package.xml LICENSE holefill libholefill_step.so HoleFillGui Resources .holefill-installed; do
  [ -e "$mods/HoleFill/$f" ] || fail "the install lacks $f"
done
ls "$mods/HoleFill"/HoleFillApp*.so >/dev/null || fail "the install lacks the compiled module"
# The addon's metadata as FreeCAD's Addon Manager reads it: every file it names is in the folder.
/usr/bin/python3 - "$mods/HoleFill" <<'PY' || fail "package.xml"
import sys, os, xml.etree.ElementTree as ET
d = sys.argv[1]; ns = {"p": "https://wiki.freecad.org/Package_Metadata"}
root = ET.parse(os.path.join(d, "package.xml")).getroot()
for tag in ("name", "description", "version", "date", "license", "icon"):
    assert root.find("p:" + tag, ns) is not None and root.find("p:" + tag, ns).text, "no " + tag
assert os.path.isfile(os.path.join(d, root.find("p:license", ns).get("file"))), "no license file"
wb = root.find("p:content/p:workbench", ns)
assert wb.find("p:freecadmin", ns).text == "0.20" and wb.find("p:freecadmax", ns) is not None
for icon in (root.find("p:icon", ns).text, wb.find("p:icon", ns).text):
    assert os.path.isfile(os.path.join(d, icon)) and os.path.getsize(os.path.join(d, icon)) <= 10240, icon
print("package.xml ok: version", root.find("p:version", ns).text)
PY
where=$(timeout 120 freecadcmd -c 'import HoleFillApp; print("HOLEFILL_AT=" + HoleFillApp.__file__)' 2>&1 | sed -n 's/^HOLEFILL_AT=//p')
case "$where" in
  "$mods/HoleFill/"*) echo "FreeCAD loads $where" ;;
  *) fail "FreeCAD did not load the installed module (got '$where')" ;;
esac
# The running FreeCAD accepts the workbench by its metadata (FreeCAD 1.0 skips an addon whose
# freecadmin/freecadmax leave it out; 0.20 has no such check).
supported=$(timeout 120 freecadcmd -c '
import os, FreeCAD
md = FreeCAD.Metadata(os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "HoleFill", "package.xml"))
wb = md.Content["workbench"][0]
print("HOLEFILL_SUPPORTED=%s" % (wb.supportsCurrentFreeCAD() if hasattr(wb, "supportsCurrentFreeCAD") else "unchecked"))' 2>&1 |
  sed -n 's/^HOLEFILL_SUPPORTED=//p')
case "$supported" in True|unchecked) echo "FreeCAD's metadata check: $supported" ;; *) fail "FreeCAD refuses the workbench's package.xml (got '$supported')" ;; esac
HOLEFILL_BUILD_DIR=$build "$src/scripts/install.sh" >/dev/null || fail "a second install did not replace the first"
HOLEFILL_BUILD_DIR=$build "$src/scripts/install.sh" --uninstall
[ ! -e "$mods/HoleFill" ] || fail "--uninstall left $mods/HoleFill"
ls -A "$mods" | grep -q . && fail "--uninstall left $(ls -A "$mods")"
mkdir -p "$mods/HoleFill" && touch "$mods/HoleFill/mine.py"
if HOLEFILL_BUILD_DIR=$build "$src/scripts/install.sh" 2>/dev/null; then fail "installed over a folder it did not make"; fi
if HOLEFILL_BUILD_DIR=$build "$src/scripts/install.sh" --uninstall 2>/dev/null; then fail "removed a folder it did not make"; fi
[ -f "$mods/HoleFill/mine.py" ] || fail "a foreign folder was touched"
echo "install/uninstall ok"
