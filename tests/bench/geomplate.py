"""FreeCAD's Surface Filling (OCCT GeomPlate) on one hole, as a FreeCAD user sets it up: the hole's
edges as boundary, each neighbour face as its support, one BoundaryOrder for all edges. Shared by
the B-rep benchmarks (bench_fill.py, bench_corpus.py, corpus_pictures.py)."""
import time


def surface_filling(doc, shape, hole, order=1):
    """(Filling object after recompute, seconds of that recompute); the caller clears `doc`."""
    src = doc.addObject("Part::Feature", "Model")
    src.Shape = shape
    doc.recompute()
    f = doc.addObject("Surface::Filling", "Filling")
    f.BoundaryEdges = [(src, e) for e in hole["edges"]]
    f.BoundaryFaces = ["Face%d" % i for i in hole["supportFaces"]]
    f.BoundaryOrder = [order] * len(hole["edges"])
    t = time.time()
    doc.recompute()
    return f, time.time() - t
