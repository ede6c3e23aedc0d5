"""Issue 22 through the Python door: every class of bad input the CLI refuses (and the ones the
fuzzers found) gives HoleFill.HoleFillError with a message here too, in FreeCAD's own process,
and leaves the document as it was. The inputs are the committed fuzz regressions where there is
one (tests/fuzz/corpus), so the door and the harnesses check the same bytes."""
import math
import os
import shutil
import tempfile

import FreeCAD
import Mesh

import fcharness
import HoleFill

CORPUS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "fuzz", "corpus")
TMP = tempfile.mkdtemp()


def corpus_file(harness, name, ext):
    """A committed corpus input under a name with the extension the reader goes by."""
    path = os.path.join(TMP, "%s_%s.%s" % (harness, name, ext))
    shutil.copy(os.path.join(CORPUS, harness, name), path)
    return path


def write(name, text):
    path = os.path.join(TMP, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def test_mesh_files_found_by_fuzzing_are_refused():
    fcharness.expect_error(lambda: HoleFill.readMesh(corpus_file("mesh_off", "count_overflow", "off")),
                           "needs vertex, face and edge counts")  # a count past 2^63 is no count
    fcharness.expect_error(lambda: HoleFill.readMesh(corpus_file("mesh_ply", "float_index_overflow", "ply")), "not a valid mesh file")
    fcharness.expect_error(lambda: HoleFill.readMesh(corpus_file("mesh_ply", "body_outruns_header", "ply")),
                           "more data than the header")


def test_cages_past_the_limits_are_refused_and_add_nothing():
    # Coordinates past the core's bound (issue 22: these crashed gnurbs).
    cage = HoleFill.sampleCage("cage_valence5")
    far = [[c * 1e300 for c in p] for p in cage["vertices"]]
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(far, cage["quads"]), "coordinate")
    # A valence-50 vertex (issue 22: gnurbs did not return): a fan of 50 quads around vertex 0.
    n = 50
    v = [(0.0, 0.0, 0.0)]
    for k in range(2 * n):  # the fan's rim: corners of the quads, then their far corners
        a = math.pi * k / n
        r = 1.0 if k % 2 == 0 else 1.2
        v.append((r * math.cos(a), r * math.sin(a), 0.1 * (k % 2)))
    quads = [(0, 1 + 2 * i, 1 + (2 * i + 1) % (2 * n), 1 + (2 * i + 2) % (2 * n)) for i in range(n)]
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(v, quads), "valence")
    # A cage file that is no cage: importCage raises and the document keeps its objects.
    doc = FreeCAD.newDocument("BadCage")
    count = len(doc.Objects)
    fcharness.expect_error(lambda: HoleFill.importCage(write("bad_cage.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9 4\n"), doc), "bad_cage.obj")
    assert len(doc.Objects) == count
    FreeCAD.closeDocument(doc.Name)


def test_a_hole_past_the_default_limit_stays_open_and_the_document_unchanged():
    n = 5001
    pts, facets = [], []
    for r in (1.0, 1.1):
        pts += [FreeCAD.Vector(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n), 0) for k in range(n)]
    for k in range(n):
        a, b = k, (k + 1) % n
        facets += [(a, b, a + n), (b, b + n, a + n)]
    band = Mesh.Mesh([[pts[i] for i in f] for f in facets])
    fcharness.expect_error(lambda: HoleFill.fillMeshHoles(band), "exceed the limit of 5000")
    assert HoleFill.defaultMaxBoundary() == 5000
    doc = FreeCAD.newDocument("LongHole")
    src = doc.addObject("Mesh::Feature", "Band")
    src.Mesh = band
    doc.recompute()
    count = len(doc.Objects)
    fcharness.expect_error(lambda: HoleFill.makeMeshFill(src), "no hole was filled", "maxBoundary")
    assert len(doc.Objects) == count and src.Mesh.CountFacets == band.CountFacets
    FreeCAD.closeDocument(doc.Name)


def test_brep_text_that_crashes_occt_is_refused_in_a_child():
    # Found by fuzzing (tests/fuzz/corpus/brep_text/offset_curve_null_basis): OCCT's reader crashes
    # on it. FreeCAD's signal handlers, inherited by the throwaway child, once made the crash look
    # like a read error, and the in-process read then took FreeCAD down.
    import HoleFillApp
    with open(os.path.join(CORPUS, "brep_text", "box_minus_face")) as f:
        text = f.read()
    at = text.index("Curve2ds ")
    first = text.index("\n", at) + 1
    bad = text[:first] + "9" + text[first + 1:]
    fcharness.expect_error(lambda: HoleFillApp.findHoles(bad, False, 5.0), "crashed")


def test_brep_text_that_hangs_occt_is_refused_in_seconds():
    # Found by fuzzing (tests/fuzz/corpus/brep_text/edge_representation_hang): OCCT's reader loops
    # for ever on it. Through the Python door it costs FreeCAD 5 s (and 1 s per MB of text).
    import time
    import HoleFillApp
    with open(os.path.join(CORPUS, "brep_text", "edge_representation_hang")) as f:
        text = f.read()
    t0 = time.time()
    fcharness.expect_error(lambda: HoleFillApp.findHoles(text, False, 5.0), "took longer than 5 s")
    assert time.time() - t0 < 15, time.time() - t0


def test_labels_that_are_not_labels_are_refused():
    m = Mesh.createSphere(1.0, 20)
    for bad in ("{", '{"segments": 3}', '{"segments": [{"label": "Q", "vertices": [0, 1]}]}'):
        fcharness.expect_error(lambda: HoleFill.fitLabeled(m, bad))


def test_inspection_is_bounded_and_cancellable():
    import Part
    shape = Part.makeSphere(5.0)
    bounded = HoleFill.inspectionMesh(shape, maxNormalAngle=0.2, maxVertices=20000)
    assert bounded["stoppedByBudget"] and len(bounded["points"]) <= 20000, len(bounded["points"])
    assert any("vertex budget of 20000" in w for w in bounded["warnings"]), bounded["warnings"]
    fcharness.expect_error(lambda: HoleFill.inspectionMesh(shape, progress=lambda f: False), "cancelled")


fcharness.run(globals())
