"""Benchmark: a fill through a point (issue 25: Surface Filling's vertex constraints), ours
(HoleFill.fillHole(points=)) against FreeCAD Surface Filling with the same point in its Points
list, side by side on the same holes of the B-rep corpus (every BENCH_POINTS_EVERY-th, 23). The
point is a point of the removed face (corpus truth.brep) near its middle, so a fill through it
should come closer to the removed face. Per filler: distance of the result to the point, the
removed face's deviation from the result (mean of 200 sample distances, over the hole's scale)
without and with the point, the G0/G1 tiers at G1, and time.

  BENCH_CORPUS=DIR (corpus-out/brep). Run inside freecadcmd; prints a Markdown table."""
import json
import os
import statistics
import sys
import time

import FreeCAD
import Part

import HoleFill

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else "tests/bench")
from freecadcmd_main import run  # noqa: E402
from geomplate import surface_filling  # noqa: E402

CORPUS = os.environ.get("BENCH_CORPUS", "corpus-out/brep")
EVERY = int(os.environ.get("BENCH_POINTS_EVERY", "23"))


def middle_point(face):
    """A point of `face` near the middle of its parameter box, inside its trim."""
    u0, u1, v0, v1 = face.ParameterRange
    for f in (0.5, 0.45, 0.55, 0.4, 0.6):
        p = face.Surface.value(u0 + f * (u1 - u0), v0 + f * (v1 - v0))
        if face.isInside(p, 1e-7, True):
            return p
    return face.Vertexes[0].Point if not face.Vertexes else face.CenterOfMass


def deviation(truth, result, scale):
    """Mean distance from points of the removed face (a 14 x 14 parameter grid, those inside its
    trim) to the result, over the scale."""
    u0, u1, v0, v1 = truth.ParameterRange
    pts = [truth.Surface.value(u0 + (i + 0.5) / 14 * (u1 - u0), v0 + (j + 0.5) / 14 * (v1 - v0)) for i in range(14) for j in range(14)]
    pts = [p for p in pts if truth.isInside(p, 1e-7, True)] or [truth.CenterOfMass]
    return statistics.mean(result.distToShape(Part.Vertex(p))[0] for p in pts) / scale


def main():
    index = json.load(open(os.path.join(CORPUS, "index.json")))["holes"][::EVERY]
    doc = FreeCAD.newDocument("BenchPoints")
    rows = {"ours": [], "GeomPlate": []}
    for h in index:
        shape, truth = Part.Shape(), Part.Shape()
        shape.read(os.path.join(CORPUS, h["id"], "hole.brep"))
        truth.read(os.path.join(CORPUS, h["id"], "truth.brep"))
        holes = HoleFill.findHoles(shape)
        if not holes or not truth.Faces:
            continue
        hole, face = holes[0], truth.Faces[0]
        p = middle_point(face)
        scale = hole["scale"]
        try:
            t = time.perf_counter()
            plain = HoleFill.fillHole(shape, hole, continuity="G1", sewn=False)
            t = time.perf_counter()
            ours = HoleFill.fillHole(shape, hole, continuity="G1", sewn=False, points=[p])
            dt = time.perf_counter() - t
            rows["ours"].append(dict(gap=ours.face.distToShape(Part.Vertex(p))[0] / scale, before=deviation(face, plain.face, scale),
                                     after=deviation(face, ours.face, scale), g0=ours.report["g0_relative"] <= 1e-6, s=dt))
        except Exception as e:  # a refused or failed fill is counted, never stops the run
            rows["ours"].append(dict(failed=str(e)[:80]))
        try:
            f, _ = surface_filling(doc, shape, hole, 1)
            before = deviation(face, f.Shape, scale)
            mark = doc.addObject("Part::Feature", "Mark")
            mark.Shape = Part.Vertex(p)
            f.Points = [(mark, "Vertex1")]
            t = time.perf_counter()
            doc.recompute()
            dt = time.perf_counter() - t
            ok = f.isValid() and not f.Shape.isNull()
            if not ok:
                raise RuntimeError("recompute failed")
            c = HoleFill.continuityReport(f.Shape.Faces[0], shape, hole)
            rows["GeomPlate"].append(dict(gap=f.Shape.distToShape(Part.Vertex(p))[0] / scale, before=before,
                                          after=deviation(face, f.Shape, scale), g0=c["g0_relative"] <= 1e-6, s=dt))
        except Exception as e:
            rows["GeomPlate"].append(dict(failed=str(e)[:80]))
        for o in list(doc.Objects):
            doc.removeObject(o.Name)
    med = lambda rs, k: statistics.median([r[k] for r in rs if "failed" not in r]) if any("failed" not in r for r in rs) else float("nan")
    lines = ["%d corpus holes (every %d-th), a point of the removed face near its middle; at G1." % (len(rows["ours"]), EVERY), "",
             "| filler | failed | distance to the point / scale (median, max) | deviation from the removed face without the point -> with it (median) | strict G0 | time s (median) |",
             "|---|---|---|---|---|---|"]
    for name, rs in rows.items():
        ok = [r for r in rs if "failed" not in r]
        lines.append("| %s | %d | %.1e, %.1e | %.2e -> %.2e | %d of %d | %.3f |" % (
            name, len(rs) - len(ok), med(rs, "gap"), max(r["gap"] for r in ok), med(rs, "before"), med(rs, "after"),
            sum(r["g0"] for r in ok), len(rs), med(rs, "s")))
    print("\n".join(lines))


run(main)
