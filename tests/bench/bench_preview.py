"""Benchmark of the Fill task panel's Preview on real holes (issue 20, the precompute/solve split):
a Fill document object is recomputed once, then again after each change of its continuity
(G1 -> G0 -> G2 -> G1), as a user trying settings in the panel does. Ours with the prepared hole
the Fill keeps (HoleFill.PreparedHole: the model, hole, samples and parameterizations reused),
ours with it thrown away before every recompute (each Preview a fresh fillHole), and FreeCAD's
Surface Filling (OCCT GeomPlate, neighbours as supports) recomputed with its BoundaryOrder changed
the same way; side by side in one run on the same holes of the B-rep corpus.

  BENCH_CORPUS=DIR (corpus-out/brep)  BENCH_PREVIEW_EVERY=k (every k-th hole of the index, 23)
Run inside freecadcmd with the HoleFill addon (scripts/bench.sh, BENCH_ONLY=preview);
writes $BENCH_OUT/bench_preview.md."""
import json
import os
import statistics
import sys
import time

import FreeCAD
import Part

import HoleFill

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else "tests/bench")
from geomplate import surface_filling  # noqa: E402

OUT = os.environ.get("BENCH_OUT", "/tmp")
CORPUS = os.environ.get("BENCH_CORPUS", "corpus-out/brep")
EVERY = int(os.environ.get("BENCH_PREVIEW_EVERY", "23"))
CHANGES = ("G0", "G2", "G1")


def timed_recompute(doc):
    t = time.perf_counter()
    doc.recompute()
    return time.perf_counter() - t


def ours(doc, shape, edges, reuse):
    """(first recompute, [recompute after each continuity change]) of a Fill of the hole of `edges`
    (names)."""
    src = doc.addObject("Part::Feature", "Model")
    src.Shape = shape
    doc.recompute()
    t = time.perf_counter()
    fill = HoleFill.makeFill(src, [edges[0]], continuity="G1")
    first = time.perf_counter() - t
    again = []
    for c in CHANGES:
        fill.Continuity = c
        if not reuse:
            fill.Proxy._prepared = None
        again.append(timed_recompute(doc))
    ok = fill.isValid() and fill.Status in ("ok", "tolerance_not_met")
    for o in list(doc.Objects):
        doc.removeObject(o.Name)
    return first, again, ok


def geomplate(doc, shape, hole):
    f, first = surface_filling(doc, shape, hole, 1)
    again = []
    for c in CHANGES:
        f.BoundaryOrder = [int(c[1])] * len(hole["edges"])
        again.append(timed_recompute(doc))
    ok = f.isValid() and not f.Shape.isNull()
    for o in list(doc.Objects):
        doc.removeObject(o.Name)
    return first, again, ok


def main():
    index = json.load(open(os.path.join(CORPUS, "index.json")))["holes"][::EVERY]
    doc = FreeCAD.newDocument("BenchPreview")
    rows = {"ours, prepared hole kept": ([], []), "ours, fresh fill each time": ([], []), "GeomPlate": ([], [])}
    failures = {k: 0 for k in rows}
    sizes = []
    for k, h in enumerate(index):
        path = os.path.join(CORPUS, h["id"], "hole.brep")
        shape = Part.Shape()
        shape.read(path)
        holes = HoleFill.findHoles(shape)
        if not holes:
            continue
        hole = holes[0]
        sizes.append(os.path.getsize(path))
        for name, run in (("ours, prepared hole kept", lambda: ours(doc, shape, hole["edges"], True)),
                          ("ours, fresh fill each time", lambda: ours(doc, shape, hole["edges"], False)),
                          ("GeomPlate", lambda: geomplate(doc, shape, hole))):
            try:
                first, again, ok = run()
            except Exception as e:  # a failed recompute is counted, never stops the run
                print("%s %s: %s" % (h["id"], name, str(e)[:120]))
                failures[name] += 1
                continue
            rows[name][0].append(first)
            rows[name][1].extend(again)
            failures[name] += 0 if ok else 1
        print("%3d/%d %s" % (k + 1, len(index), h["id"]))
        sys.stdout.flush()
    FreeCAD.closeDocument(doc.Name)
    ms = lambda xs: "%.1f" % (1e3 * statistics.median(xs)) if xs else "-"
    mx = lambda xs: "%.1f" % (1e3 * max(xs)) if xs else "-"
    lines = ["Preview on %d corpus holes (every %d-th of the index; models %.0f-%.0f kB, median %.0f kB): one "
             "Fill recompute, then one after each continuity change (%s)." %
             (len(sizes), EVERY, min(sizes) / 1e3, max(sizes) / 1e3, statistics.median(sizes) / 1e3, " -> ".join(("G1",) + CHANGES)),
             "", "| | first Preview median ms | max ms | Preview after a change median ms | max ms | failed |",
             "|---|---|---|---|---|---|"]
    for name, (first, again) in rows.items():
        lines.append("| %s | %s | %s | %s | %s | %d |" % (name, ms(first), mx(first), ms(again), mx(again), failures[name]))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(OUT, "bench_preview.md"), "w") as f:
        f.write(text + "\n")


main()
