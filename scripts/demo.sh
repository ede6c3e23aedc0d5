#!/usr/bin/env bash
# The main job on a fresh Debian 12 or 13 machine: install what is missing, build, install the
# workbench, fill the bundled sample holes headless with freecadcmd, and write to demo-out/:
# the filled models (.FCStd, .step), a continuity report per hole (.json + the printed
# table) and a picture of each result (.png, rendered by FreeCAD under Xvfb); and G² G-NURBS
# surfaces over the bundled quad cages in demo-out/gnurbs/ (.step, .faces.json, .json, zebra .png);
# a THB fit of the bundled bare point cloud in demo-out/pointcloud/ (BIDGCN and shape-preserving
# parameters; the shape-preserving fit also as one face per hierarchical cell, rendered);
# a labeled fit of the bundled torus region in demo-out/labeled/ (with and without extension:
# trimmed .step, untrimmed .brep, .json report, mean-curvature .png of the untrimmed surface).
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
  for doc in "$out"/*.FCStd; do
    [ -f "${doc%.FCStd}.png" ] || { echo "[demo] rendering $(basename "$doc") failed:" >&2; tail -20 "$HOME/render.log" >&2; exit 1; }
  done
  rm -rf "$HOME"
)
# G² G-NURBS surfaces over the bundled quad cages (CLI): shells, face sidecars, reports, zebra pictures.
mkdir -p "$out/gnurbs"
cages=$(mktemp -d)
"$build/App/holefill" samples "$cages" | grep 'cage_.*\.obj$' | while read -r cage; do
  name=$(basename "$cage" .obj)
  "$build/App/holefill" gnurbs "$cage" --out "$out/gnurbs/$name.step" --json >"$out/gnurbs/$name.json"
  "$build/App/holefill" render "$out/gnurbs/$name.step" --mode zebra --out "$out/gnurbs/$name.png" --size 800x600 >/dev/null
  /usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); c=r["continuity"]; print("[demo] G-NURBS %-18s %3d faces, EPs %s: spokes G1 %.1e rad G2 %.1e, %.2f s" % (sys.argv[2], r["brep"]["faces"], r["extraordinary_points"], c["g1_spokes"], c["g2_spokes"], r["seconds"]))' "$out/gnurbs/$name.json" "$name"
done
cp "$cages"/cage_*.obj "$out/gnurbs/"
# Labeled fitting of the bundled L-shaped torus region (labels on its four straight sides).
mkdir -p "$out/labeled"
cp "$cages"/labeled_region.obj "$cages"/labeled_region.labels.json "$out/labeled/"
for ext in G2 none; do
  "$build/App/holefill" fit "$out/labeled/labeled_region.obj" --labels "$out/labeled/labeled_region.labels.json" --ctrl 24x8 \
    --extension $ext --out "$out/labeled/fit_$ext.step" --untrimmed-out "$out/labeled/untrimmed_$ext.brep" --json >"$out/labeled/fit_$ext.json"
  "$build/App/holefill" render "$out/labeled/untrimmed_$ext.brep" --mode curvature --quantity mean --view top \
    --out "$out/labeled/untrimmed_$ext.png" --size 800x600 >/dev/null
  /usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print("[demo] labeled fit, extension %-4s data max %.1e, %d weak control points, log10 condition %.1f, %d extension vertices, %.2f s" % (sys.argv[2], r["data_max"], r["weak_control_points"], float("inf") if r["log10_condition"] is None else r["log10_condition"], r["extended_vertices"], r["seconds"]))' "$out/labeled/fit_$ext.json" "$ext"
done
mkdir -p "$out/pointcloud"
cp "$cages"/scan_patch.xyz "$out/pointcloud/"
for param in bidgcn shape; do
  "$build/App/holefill" fit-points "$out/pointcloud/scan_patch.xyz" --method $param --relative-tolerance 5e-4 \
    --out "$out/pointcloud/scan_fit_$param.step" --json >"$out/pointcloud/scan_fit_$param.json" 2>/dev/null || true
  /usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); it=r["iterations"]; print("[demo] point cloud, %-6s parameters (%.3f s): %d levels, %d functions, max error %.1e of the diagonal, tolerance %s, %d folded samples" % (sys.argv[2], r["parameterization"]["seconds"], r["levels"], it[-1]["dof"], it[-1]["max_error"], "met" if r["met_tolerance"] else "NOT met", r["folds"]))' "$out/pointcloud/scan_fit_$param.json" "$param"
done
"$build/App/holefill" fit-points "$out/pointcloud/scan_patch.xyz" --method shape --relative-tolerance 5e-4 --faces \
  --out "$out/pointcloud/scan_fit_cells.brep" >/dev/null 2>&1 || true
"$build/App/holefill" render "$out/pointcloud/scan_fit_cells.brep" --mode curvature --quantity mean --view top \
  --out "$out/pointcloud/scan_fit_cells.png" --size 800x600 >/dev/null
rm -rf "$cages"
echo "[demo] results in $out:"
ls -1 "$out"
