#!/usr/bin/env bash
# The CLI on good inputs: holes are listed, a hole named by one FreeCAD edge name is filled, the
# sewn model (.step) and the face alone (.brep) are written, --json parses and reports G1 reached.
set -u
H=${HOLEFILL:?}
T=$1
rm -rf "$T"; mkdir -p "$T"
fail=0; pass=0
check() { if eval "$2"; then pass=$((pass+1)); echo "ok   $1"; else fail=$((fail+1)); echo "FAIL $1"; fi; }
"$H" samples "$T" >/dev/null
"$H" holes "$T/panel_6_sided.brep" --json >"$T/holes.json"
check "holes --json lists one 6-sided hole" \
  "/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); h=d[\"holes\"]; assert len(h)==1 and h[0][\"corners\"]==6' $T/holes.json"
edge=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["holes"][0]["edges"][2])' "$T/holes.json")
"$H" fill "$T/panel_6_sided.brep" --edges "$edge" --out "$T/out.step" --face-out "$T/face.brep" --json >"$T/fill.json"
rc=$?
check "fill by one edge name ($edge) exits 0" "[ $rc = 0 ]"
check "sewn model and face written" "[ -s $T/out.step ] && [ -s $T/face.brep ] && ! ls $T/*.tmp* >/dev/null 2>&1"
check "report: G1 reached at the strict tier" \
  "/usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))[0]; assert r[\"status\"]==\"ok\" and r[\"achieved\"] in (\"G1\",\"G2\") and r[\"str\"][\"g0_strict\"] and r[\"str\"][\"g1_strict\"] and r[\"shape_valid\"]' $T/fill.json"
"$H" holes "$T/out.step" >"$T/after.txt"
check "the written model has no hole left" "grep -q 'no holes' $T/after.txt"
"$H" fill "$T/sheet_two_holes.brep" --hole all --out "$T/both.brep" >"$T/both.txt"
check "--hole all fills both holes of a sheet" "[ \$(grep -c '^hole' $T/both.txt) = 2 ] && \"$H\" holes $T/both.brep | grep -q 'no holes'"
"$H" fill "$T/panel_6_sided.brep" --edges "$edge" --edge-continuity "$edge=G0" --out "$T/ec.brep" --json >"$T/ec.json"
check "--edge-continuity asks G0 of $edge, G1 of the others, and says so per edge" \
  "/usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))[0]; p={\"Edge%d\" % e[\"edge\"]: e for e in r[\"edge_continuity\"]}; assert r[\"status\"]==\"ok\" and p[sys.argv[2]][\"asked\"]==\"G0\" and p[sys.argv[2]][\"source\"]==\"override\" and all(e[\"asked\"]==\"G1\" for k, e in p.items() if k != sys.argv[2])' $T/ec.json $edge"
# Points to pass through: the open box's top through a point 2 above it; one beside the hole is
# refused (exit 2, nothing written).
"$H" fill "$T/box_minus_face.brep" --continuity G0 --points "15,10,12" --out "$T/pts.brep" --json >"$T/pts.json"
check "--points: the face passes through the point within the G0 tolerance" \
  "/usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))[0]; assert r[\"status\"]==\"ok\" and len(r[\"point_distances\"])==1 and r[\"point_distances\"][0] <= r[\"g0_tolerance\"]' $T/pts.json"
"$H" fill "$T/box_minus_face.brep" --continuity G0 --method np --points "45,10,10" --out "$T/pts_out.brep" >/dev/null 2>"$T/pts_out.err"
rc=$?
check "--points beside the hole: exit 2, says why, writes nothing" "[ $rc = 2 ] && grep -q 'not over the hole' $T/pts_out.err && [ ! -e $T/pts_out.brep ]"
# Per edge, the model's own accuracy beside the errors; --no-model-accuracy judges by the tiers alone.
"$H" fill "$T/panel_6_sided.brep" --edges "$edge" --no-model-accuracy --out "$T/nma.brep" --json >"$T/nma.json"
check "per_edge reports tolerance_before and g1_floor; --no-model-accuracy is accepted" \
  "/usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))[0]; assert r[\"status\"]==\"ok\" and all(e[\"g1_floor\"] < 1e-6 and e[\"tolerance_before\"] > 0 for e in r[\"per_edge\"])' $T/nma.json"
# Regression: `render --faces 1` (space form) is a face list, not fit-points' --faces flag.
"$H" render "$T/panel_6_sided.brep" --out "$T/faces.png" --size 160x120 --faces 1 >/dev/null 2>"$T/faces.err"
check "render --faces 1 (space form) draws the listed face" "[ -s $T/faces.png ] && [ ! -s $T/faces.err ]"
# Two adjacent holes: the loop split by the divider file, two faces sharing it, G1 across.
"$H" fill "$T/filleted_box_adjacent_holes.brep" --divide "$T/filleted_box_adjacent_holes.divider.brep" \
  --out "$T/adj.brep" --face-out "$T/adj_faces.brep" --json >"$T/adj.json"
rc=$?
check "fill --divide exits 0 and writes the model and both faces" "[ $rc = 0 ] && [ -s $T/adj.brep ] && [ -s $T/adj_faces.brep ]"
check "fill --divide: two fills, G0/G1 strict across the shared edge, the model closed" \
  "/usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); a=r[\"across\"]; assert r[\"status\"]==\"ok\" and len(r[\"fills\"])==2 and r[\"shared_edge\"]>0 and a[\"g0_relative\"]<=1e-6 and a[\"g1\"]<=1e-3 and r[\"fills\"][1][\"closed_solid\"]' $T/adj.json"
"$H" fill "$T/filleted_box_adjacent_holes.brep" --divide "$T/panel_6_sided.brep" --out "$T/adj_bad.brep" >/dev/null 2>"$T/adj_bad.err"
rc=$?
check "fill --divide with a file of many edges exits 1, says why, writes nothing" \
  "[ $rc = 1 ] && grep -q 'must hold one edge' $T/adj_bad.err && [ ! -e $T/adj_bad.brep ]"
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
