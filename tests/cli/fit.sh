#!/usr/bin/env bash
# holefill fit: a labeled region with a cut corner is fitted with its extension (no weak control
# points, the data met) and without (for comparison); bad labels exit 1 and write nothing.
. "$(dirname "$0")/checks.sh"
"$PY" - "$T" <<'PY'
import json, math, sys
t = sys.argv[1]
nx, ny, h = 24, 12, 0.25
verts, tris, vid = [], [], {}
def v(i, j):
    if (i, j) not in vid:
        vid[(i, j)] = len(verts)
        x, y = i * h, j * h
        verts.append((x, y, 0.3 * math.sin(0.5 * x) * math.cos(0.7 * y)))
    return vid[(i, j)]
for j in range(ny):
    for i in range(nx):
        if (i + .5) * h > 4.5 and (j + .5) * h > 2.0:
            continue  # the north-east corner is cut away
        a, b, c, d = v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)
        tris += [(a, b, c), (a, c, d)]
with open(t + "/region.obj", "w") as f:
    for p in verts: f.write("v %.12g %.12g %.12g\n" % p)
    for q in tris: f.write("f %d %d %d\n" % (q[0] + 1, q[1] + 1, q[2] + 1))
S = [vid[(i, 0)] for i in range(nx + 1)]
E = [vid[(nx, j)] for j in range(0, 9)]
N = [vid[(i, ny)] for i in range(18, -1, -1)]
W = [vid[(0, j)] for j in range(ny, -1, -1)]
json.dump({"segments": [{"label": "S", "vertices": S}, {"label": "E", "vertices": E}, {"label": "N", "vertices": N},
                        {"label": "West", "vertices": W}]}, open(t + "/labels.json", "w"))
json.dump({"segments": [{"label": "N", "vertices": S}, {"label": "S", "vertices": S}]}, open(t + "/contradictory.json", "w"))
json.dump({"segments": [{"label": "Q", "vertices": S}, {"label": "S", "vertices": E}]}, open(t + "/badlabel.json", "w"))
open(t + "/broken.json", "w").write('{"segments": [{"label": "N", "vertices": [1, 2')
PY
expect_error() {  # name, wanted text, arguments after the verb (--out goes to $T/o.brep)
  local name=$1 want=$2; shift 2
  expect_refusal "$name" "$want" "$T/o.brep" fit "$@" --out "$T/o.brep"
}
expect_error "no labels" "labels" "$T/region.obj"
expect_error "contradictory labels" "labeled both North and South" "$T/region.obj" --labels "$T/contradictory.json"
expect_error "unknown label" "not N, E, S or W" "$T/region.obj" --labels "$T/badlabel.json"
expect_error "broken JSON" "not valid JSON" "$T/region.obj" --labels "$T/broken.json"
expect_error "bad --ctrl" "ctrl" "$T/region.obj" --labels "$T/labels.json" --ctrl 12
expect_error "bad --extension" "--extension: extension must be one of fit, G2, G1, none" "$T/region.obj" --labels "$T/labels.json" --extension G3
expect_error "mesh fairness on the fitted extension" "ask for extension G2 or G1" "$T/region.obj" --labels "$T/labels.json" --mesh-fairness 0.01
expect_error "negative --mesh-fairness" "--mesh-fairness: meshFairness must be zero or positive" "$T/region.obj" --labels "$T/labels.json" --mesh-fairness -1
if "$H" fit "$T/region.obj" --labels "$T/labels.json" --ctrl 10x8 --extension G2 --mesh-fairness 0.01 --out "$T/fit_emesh.brep" --json \
     >"$T/fit_emesh.json" 2>"$T/err"; then ok "fit with mesh fairness (E_Mesh)"; else bad "fit --mesh-fairness: $(cat "$T/err")"; fi
for ext in fit G2 none; do
  if "$H" fit "$T/region.obj" --labels "$T/labels.json" --ctrl 10x8 --extension $ext --out "$T/fit_$ext.brep" \
       --untrimmed-out "$T/untrimmed_$ext.brep" --json >"$T/fit_$ext.json" 2>"$T/err"; then ok "fit with extension $ext"; else bad "fit $ext: $(cat "$T/err")"; fi
done
"$PY" - "$T" <<'PY' && ok "extension: no weak control points, data met, better conditioned" || bad "fit reports: $(cat "$T/fit_G2.json") $(cat "$T/fit_none.json")"
import json, sys
t = sys.argv[1]
g2, none = json.load(open(t + "/fit_G2.json")), json.load(open(t + "/fit_none.json"))
fit = json.load(open(t + "/fit_fit.json"))  # the default: extension sampled from a thin-plate fit
# The condition of the points' own normal matrix; JSON has no infinity, a singular one is null.
cond = lambda r: float("inf") if r["log10_condition"] is None else r["log10_condition"]
assert fit["face_valid"] and fit["extended_vertices"] > 0 and fit["weak_control_points"] == 0 and fit["data_max"] < 5e-3, fit
assert cond(fit) < cond(none), (fit, none)
assert g2["face_valid"] and none["face_valid"], (g2, none)
assert g2["flipped_triangles"] == 0 and g2["extended_vertices"] > 0, g2
assert g2["weak_control_points"] == 0 and none["weak_control_points"] > 0, (g2, none)
assert cond(g2) < cond(none), (g2, none)
assert g2["data_max"] < 5e-3, g2
assert abs(g2["width"] - 6.0) < 0.1 and abs(g2["height"] - 3.0) < 0.1, g2
PY
[ -s "$T/untrimmed_G2.brep" ] && ok "untrimmed surface written" || bad "no untrimmed surface"
# Control points chosen by the data: from 5x5, refined while the data max exceeds the tolerance.
expect_error "an unknown --isocurves" "--isocurves" "$T/region.obj" --labels "$T/labels.json" --isocurves wiggly
if "$H" fit "$T/region.obj" --labels "$T/labels.json" --extension G2 --isocurves paper --out "$T/fit_paper_iso.brep" >/dev/null 2>"$T/err" && [ -s "$T/fit_paper_iso.brep" ]; then
  ok "fit with the paper's isocurve fairness"; else bad "fit --isocurves paper: $(cat "$T/err")"; fi
expect_error "--max-ctrl below --ctrl" "at least the larger of controlU" "$T/region.obj" --labels "$T/labels.json" --ctrl 10x8 --max-ctrl 6
expect_error "zero --relative-tolerance" "--relative-tolerance: relativeTolerance" "$T/region.obj" --labels "$T/labels.json" --relative-tolerance 0
expect_error "negative --tolerance" "--tolerance: tolerance" "$T/region.obj" --labels "$T/labels.json" --tolerance -1
expect_error "negative --reach" "--reach: reach must be between 0 and 10" "$T/region.obj" --labels "$T/labels.json" --reach -0.1
# (--reach 0: the domain is the rectangle, 6 x 3 units; the default reach widens it by 0.05 of 6 a side.)
if "$H" fit "$T/region.obj" --labels "$T/labels.json" --ctrl 5x5 --max-ctrl 30 --relative-tolerance 1e-4 --reach 0 --out "$T/fit_refined.brep" --json \
     >"$T/fit_refined.json" 2>"$T/err"; then ok "fit with refined control points"; else bad "fit --max-ctrl: $(cat "$T/err")"; fi
"$PY" - "$T" <<'PY' && ok "refinement: more control points, the data closer, each try reported" || bad "refined: $(cat "$T/fit_refined.json")"
import json, sys
t = sys.argv[1]
r = json.load(open(t + "/fit_refined.json"))
assert r["control_points_u"] > 5 and len(r["refinements"]) >= 2, r
assert r["refinements"][0].startswith("5x4"), r  # cells start square: 6 x 3 units
assert r["data_max"] < 1e-3 and r["weak_control_points"] == 0, r
PY
finish
