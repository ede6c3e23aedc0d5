"""Benchmark: triangle-mesh hole filling, HoleFill (Hu et al.: minimum-angle triangulation,
refinement, bilateral fairing) against CGAL PMP triangulate_refine_and_fair_hole (Liepa, CGAL's
defaults) and FreeCAD Mesh fillupHoles (FreeCAD's defaults), side by side in one run on the same
inputs.

Cases
  real   meshes with holes as they come: CGAL's demo data (Debian libcgal-demo: holes.off,
         mech-holes-shark.off, elephant-with-holes.off with its duplicated seam vertices) and
         assimp's sphereWithHole.stl (Debian assimp-testmodels; STL, so corners are welded by
         position, leaving non-manifold boundary vertices).
  truth  holes cut from closed meshes, the cut triangles kept as ground truth: the Stanford bunny
         (CGAL's bunny00.off) and CGAL's elephant (smooth), fandisk, couplingdown and anchor
         (CAD-like: creases and blends) with holes centred on a sharp edge so they cross it.
Every output is measured by the same function (HoleFillApp.measureMeshFill), which finds what a
filler added by position: holes left (boundary edges, coincident vertices welded), non-manifold
or misoriented edges added, Field's quality q = 2 r_in/R_circ of the new triangles, and the
distance of the new surface (new vertices and new-triangle centroids) to the cut-away truth,
RMS and max, over the bounding-box diagonal. ok = no boundary edge left, nothing non-manifold,
misoriented or degenerate added, input kept. Times, fastest of REPEATS runs: "fill" is the
filling alone on a built mesh structure (ours: the per-hole times), "total" starts from index
arrays (CGAL: polygon soup to Surface_mesh + fill, in its own process; FreeCAD: Mesh.Mesh from
the topology + fillupHoles; ours: the whole call, detection and topology included).
Run by scripts/bench.sh inside freecadcmd; writes $BENCH_OUT/bench_meshfill.json and .md."""
import json
import os
import sys

import numpy as np

import HoleFillApp

HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else "tests/bench"
sys.path[:0] = [HERE, os.path.join(os.path.dirname(HERE), "corpus")]
from freecadcmd_main import run  # noqa: E402
from meshfill_runners import adds_no_defect, measure, run_cgal, run_freecad, run_ours  # noqa: E402
from mesh_holes import ball, mean_edge, sharp_vertices, split  # noqa: E402  (the corpus's cuts: one way to cut)

OUT = os.environ.get("BENCH_OUT", "/tmp")
CGAL_DATA = os.environ.get("CGAL_DATA", os.path.join(OUT, "cgal-data"))
ASSIMP_STL = "/usr/share/assimp/models/STL/sphereWithHole.stl"


def off_path(name):
    return os.path.join(CGAL_DATA, "meshes", name)


def truth_case(name, file, picks, radius_edges, sharp):
    v, t = HoleFillApp.readMesh(off_path(file))
    t = np.asarray(t, np.int64)
    h = radius_edges * mean_edge(v, t)
    pool = list(sharp_vertices(v, t)) if sharp else list(range(len(v)))
    centres = [v[pool[int(f * (len(pool) - 1))]] for f in picks]
    (iv, it), (gv, gt) = split(v, t, np.any([ball(v, t, c, h) for c in centres], axis=0))
    it, gt = it.astype(np.int32), gt.astype(np.int32)
    holes = json.loads(HoleFillApp.meshHoles(iv, it))["holes"]
    return dict(name=name, kind="truth, " + ("crosses a feature" if sharp else "smooth"), v=iv, t=it, gv=gv, gt=gt,
                holes=len(holes))


def cases():
    out = []
    for name in ("holes.off", "mech-holes-shark.off", "elephant-with-holes.off"):
        v, t = HoleFillApp.readMesh(off_path(name))
        out.append(dict(name=name, kind="real", v=v, t=t, gv=np.zeros((0, 3)), gt=np.zeros((0, 3), np.int32),
                        holes=len(json.loads(HoleFillApp.meshHoles(v, t))["holes"])))
    if os.path.exists(ASSIMP_STL):
        v, t = HoleFillApp.readMesh(ASSIMP_STL)
        out.append(dict(name="sphereWithHole.stl", kind="real", v=v, t=t, gv=np.zeros((0, 3)),
                        gt=np.zeros((0, 3), np.int32), holes=len(json.loads(HoleFillApp.meshHoles(v, t))["holes"])))
    out.append(truth_case("bunny (3 holes)", "bunny00.off", (0.13, 0.5, 0.81), 4.0, False))
    out.append(truth_case("elephant (2 holes)", "elephant.off", (0.3, 0.7), 3.0, False))
    out.append(truth_case("fandisk (2 holes)", "fandisk.off", (0.25, 0.6), 4.0, True))
    out.append(truth_case("anchor_dense (2 holes)", "anchor_dense.off", (0.3, 0.7), 4.0, True))
    out.append(truth_case("cube-meshed (2 holes)", "cube-meshed.off", (0.2, 0.6), 2.5, True))
    # Long sliver triangles around the cut: a boundary edge longer than the hole is wide
    # bounds every filler's worst triangle (the input's edges may not be split).
    out.append(truth_case("couplingdown, slivers (2 holes)", "couplingdown.off", (0.2, 0.7), 3.0, True))
    return out


def fmt(x, spec):
    return "-" if x is None or x != x or x < 0 else format(x, spec)


def main():
    work = os.path.join(OUT, "meshfill")
    os.makedirs(work, exist_ok=True)
    rows = []
    for c in cases():
        safe = c["name"].split()[0].replace(".", "_").rstrip(",")
        HoleFillApp.writeMesh(c["v"], c["t"], os.path.join(work, "%s_in.off" % safe))
        for method, runner in (("HoleFill", run_ours),
                               ("HoleFill C2", lambda c: run_ours(c, shapeOrder=3, fairIterations=0)),
                               ("HoleFill C2 auto", lambda c: run_ours(c, shapeOrder=3, fairIterations=0,
                                                                       triangulation="auto")),
                               ("CGAL Liepa", lambda c: run_cgal(c, work)),
                               ("FreeCAD fillupHoles", run_freecad)):
            r = runner(c)
            if r is None:
                continue
            ov, ot, dt, note = r
            if ov is None:
                rows.append(dict(case=c["name"], kind=c["kind"], method=method, ok=False, note=note, seconds=dt[0], total=dt[1]))
                continue
            m = measure(c, ov, ot)
            ok = m["boundary_edges_after"] == 0 and adds_no_defect(m)
            rows.append(dict(case=c["name"], kind=c["kind"], method=method, ok=ok, note=note, seconds=dt[0], total=dt[1],
                             holes=c["holes"], **m))
            HoleFillApp.writeMesh(ov, ot, os.path.join(work, "%s_%s.off" % (safe, method.replace(" ", "_").lower())))
    json.dump(rows, open(os.path.join(OUT, "bench_meshfill.json"), "w"), indent=1)
    head = ("| case | kind | holes | method | ok | left open (bnd edges) | +nonmanif/misor | +V | +T | q min | q mean "
            "| q>=0.7 | RMS/diag | max/diag | fill s | total s | note |")
    lines = [head, "|" + "---|" * 17]
    for r in rows:
        if "new_triangles" not in r:
            lines.append("| %s | %s | | %s | no | | | | | | | | | | %s | %s | %s |" % (
                r["case"], r["kind"], r["method"], fmt(r["seconds"], ".4f"), fmt(r["total"], ".4f"), r["note"]))
            continue
        lines.append("| %s | %s | %d | %s | %s | %d | %d/%d | %d | %d | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["case"], r["kind"], r["holes"], r["method"], "yes" if r["ok"] else "no", r["boundary_edges_after"],
            r["non_manifold_edges_added"], r["misoriented_edges_added"], r["new_vertices"], r["new_triangles"],
            fmt(r["min_quality"], ".3f"), fmt(r["mean_quality"], ".3f"), fmt(r["share_quality_0_7"], ".2f"),
            fmt(r["rms_distance"], ".2e"), fmt(r["max_distance"], ".2e"), fmt(r["seconds"], ".4f"), fmt(r["total"], ".4f"),
            r["note"]))
    text = "\n".join(lines)
    open(os.path.join(OUT, "bench_meshfill.md"), "w").write(text + "\n")
    print(text)


run(main)
