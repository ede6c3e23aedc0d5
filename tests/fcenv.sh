# Source me. A throwaway HOME/XDG for FreeCAD runs (never the real home), a user.cfg
# that skips the Start page (QtWebEngine aborts FreeCAD as root), and the HoleFill addon
# linked into FreeCAD 0.20's user Mod folder ($XDG_DATA_HOME/FreeCAD/Mod).
# Usage: . tests/fcenv.sh MOD_DIR   (MOD_DIR = the build's assembled Mod/HoleFill)
HF_MOD_SRC=${1:?assembled Mod/HoleFill folder}
export HOME=$(mktemp -d -t holefill-home.XXXXXX)
export XDG_CONFIG_HOME="$HOME/.config" XDG_DATA_HOME="$HOME/.local/share" XDG_CACHE_HOME="$HOME/.cache"
export XDG_RUNTIME_DIR="$HOME/run"
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
export QTWEBENGINE_DISABLE_SANDBOX=1
mkdir -p "$XDG_CONFIG_HOME/FreeCAD" "$XDG_DATA_HOME/FreeCAD/Mod"
cat > "$XDG_CONFIG_HOME/FreeCAD/user.cfg" <<'XML'
<?xml version="1.0" encoding="UTF-8" standalone="no" ?>
<FCParameters>
  <FCParamGroup Name="Root">
    <FCParamGroup Name="BaseApp">
      <FCParamGroup Name="Preferences">
        <FCParamGroup Name="General">
          <FCText Name="AutoloadModule">PartWorkbench</FCText>
        </FCParamGroup>
        <FCParamGroup Name="View">
          <FCBool Name="ShowNaviCube" Value="0"/>
        </FCParamGroup>
      </FCParamGroup>
    </FCParamGroup>
  </FCParamGroup>
</FCParameters>
XML
ln -sfn "$(cd "$HF_MOD_SRC" && pwd)" "$XDG_DATA_HOME/FreeCAD/Mod/HoleFill"
export HF_RESULT="$HOME/result.json"
