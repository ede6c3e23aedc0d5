"""HoleFill demo job (run by scripts/demo.sh inside freecadcmd): fills the hole of each
bundled sample with NP, MVC and UVTran at G1, and at G2 with NP and UVTran, keeps the NP/G1 fill as a
parametric Fill object in a FreeCAD document, and writes to $HOLEFILL_DEMO_OUT:
<sample>.FCStd, <sample>.step (the sewn model), <sample>.json (reports) and summary.json,
zebra pictures of the sewn NP fills at G1 and G2 (<sample>_zebra_G1.png, _G2.png) and a mean
curvature map of the G2 one (<sample>_mean_G2.png), rendered headless by the core,
then prints the continuity table."""
import json
import os
import sys

import FreeCAD
import Part

import HoleFill

# Our tables only: OCCT's STEP writer prints its transfer statistics and FreeCAD's console
# sequencer its "Recompute..." progress straight to file descriptor 1, below Python. The job
# writes its own lines to a copy of that descriptor and points descriptor 1 at /dev/null;
# errors still reach stderr, and Python's traceback with them.
sys.stdout.flush()
_ours = os.fdopen(os.dup(1), "w", buffering=1)
_null = os.open(os.devnull, os.O_WRONLY)
os.dup2(_null, 1)
sys.stdout = _ours

OUT = os.environ["HOLEFILL_DEMO_OUT"]
SAMPLES = os.environ["HOLEFILL_SAMPLES"]
NAMES = ["cc_valence5", "filleted_box_corner", "panel_6_sided"]
RUNS = [("np", "G1"), ("mvc", "G1"), ("uvtran", "G1"), ("np", "G2"), ("uvtran", "G2")]

rows = []
summary = {}
for name in NAMES:
    shape = Part.Shape()
    shape.read(os.path.join(SAMPLES, name + ".brep"))
    reports = {}
    for method, cont in RUNS:
        try:
            face, sewn, rep = HoleFill.fillHole(shape, 1, method=method, continuity=cont, sewn=True)
        except HoleFill.HoleFillError as e:
            rep = {"status": "failed", "message": str(e), "requested": cont, "achieved": "none", "method": method}
        reports["%s_%s" % (method, cont)] = rep
        rows.append((name, rep))
        if (method, cont) == ("np", "G1") and rep["status"] != "failed":
            sewn.exportStep(os.path.join(OUT, name + ".step"))
        if method == "np" and rep["status"] != "failed":
            HoleFill.renderImage(sewn, os.path.join(OUT, "%s_zebra_%s.png" % (name, cont)), mode="zebra", stripes=20)
            if cont == "G2":
                HoleFill.renderImage(sewn, os.path.join(OUT, "%s_mean_G2.png" % name), mode="curvature", quantity="mean")
    doc = FreeCAD.newDocument(name)
    src = doc.addObject("Part::Feature", "Model")
    src.Shape = shape
    doc.recompute()
    fill = HoleFill.makeFill(src, HoleFill.findHoles(shape)[0].edges[:1], method="np", continuity="G1")
    doc.saveAs(os.path.join(OUT, name + ".FCStd"))
    FreeCAD.closeDocument(doc.Name)
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump(reports, f, indent=1)
    summary[name] = {k: {"status": r["status"], "achieved": r["achieved"], "g0_relative": r.get("g0_relative"),
                         "g1": r.get("g1"), "g2": r.get("g2")} for k, r in reports.items()}

# Triangle-mesh holes: the bundled scan-like sphere with three holes, filled into a new mesh.
mesh_doc = FreeCAD.newDocument("scan_with_holes")
scan = mesh_doc.addObject("Mesh::Feature", "Scan")
scan.Mesh = HoleFill.readMesh(os.path.join(SAMPLES, "scan_with_holes.obj"))
mesh_doc.recompute()
filled = HoleFill.makeMeshFill(scan)
mesh_report = json.loads(filled.HoleFillReport)
HoleFill.writeMesh(filled.Mesh, os.path.join(OUT, "scan_with_holes_filled.stl"))
mesh_doc.saveAs(os.path.join(OUT, "scan_with_holes.FCStd"))
FreeCAD.closeDocument(mesh_doc.Name)
with open(os.path.join(OUT, "scan_with_holes.json"), "w") as f:
    json.dump(mesh_report, f, indent=1)
summary["scan_with_holes"] = {"filled": mesh_report["filled"], "closed": mesh_report["closed"],
                              "min_quality": min(h["min_quality"] for h in mesh_report["hole_fills"]),
                              "mean_quality": [round(h["mean_quality"], 4) for h in mesh_report["hole_fills"]]}

with open(os.path.join(OUT, "summary.json"), "w") as f:
    json.dump(summary, f, indent=1)

print()
hdr = "%-20s %-4s %-10s %-4s %-18s %-10s %-10s %-10s %-9s %-7s %s" % (
    "sample", "N", "meth", "req", "status", "G0/scale", "G1 [rad]", "G2 [rel]", "poles", "time s", "achieved")
print(hdr)
print("-" * len(hdr))
for name, r in rows:
    if r["status"] == "failed":
        print("%-20s %-4s %-10s %-4s %-18s %s" % (name, "", r["method"], r["requested"], "failed", r["message"]))
        continue
    print("%-20s %-4d %-10s %-4s %-18s %-10.2e %-10.2e %-10.2e %-9s %-7.2f %s" % (
        name, r["corners"], r["method"], r["requested"], r["status"], r["g0_relative"], r["g1"], r["g2"],
        "%dx%d" % (r["poles_u"], r["poles_v"]), r["timings"]["total"], r["achieved"]))
print("DESIGN tiers: G0 <= 1e-6 x scale (strict), G1 <= 1e-3 rad (strict), G2 <= 0.1")
print()
print("mesh: scan_with_holes.obj -> scan_with_holes_filled.stl (%s)" % ("closed" if mesh_report["closed"] else "still open"))
print("%-5s %-9s %-7s %-7s %-7s %-7s %s" % ("hole", "boundary", "+verts", "+tris", "q min", "q mean", "seconds"))
for h in mesh_report["hole_fills"]:
    print("%-5d %-9d %-7d %-7d %-7.3f %-7.3f %.3f" % (h["hole"], h["boundary_vertices"], h["new_vertices"], h["new_triangles"],
                                                     h["min_quality"], h["mean_quality"], h["seconds"]))
