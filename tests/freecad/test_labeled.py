"""Headless FreeCAD tests of labeled fitting from Python: a Mesh region with a cut corner,
labeled on four sides, becomes one valid trimmed face; the mesh stays as it was; bad labels
raise clear errors."""
import math

import FreeCAD
import Mesh

import fcharness
import HoleFill


def cut_region():
    """A wavy 6×3 sheet of 0.25 cells with its north-east corner cut away; labels on its sides."""
    nx, ny, h = 24, 12, 0.25
    pts, facets, vid = [], [], {}

    def v(i, j):
        if (i, j) not in vid:
            vid[(i, j)] = len(pts)
            x, y = i * h, j * h
            pts.append(FreeCAD.Vector(x, y, 0.3 * math.sin(0.5 * x) * math.cos(0.7 * y)))
        return vid[(i, j)]

    for j in range(ny):
        for i in range(nx):
            if (i + .5) * h > 4.5 and (j + .5) * h > 2.0:
                continue
            a, b, c, d = v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)
            facets += [(a, b, c), (a, c, d)]
    labels = [("S", [vid[(i, 0)] for i in range(nx + 1)]), ("E", [vid[(nx, j)] for j in range(9)]),
              ("N", [vid[(i, ny)] for i in range(18, -1, -1)]), ("W", [vid[(0, j)] for j in range(ny, -1, -1)])]
    return Mesh.Mesh((pts, facets)), labels


def test_a_labeled_region_becomes_one_trimmed_face():
    m, labels = cut_region()
    before = m.Topology
    face, surface, rep = HoleFill.fitLabeled(m, labels, controlPoints=(10, 8))
    assert face.isValid() and face.ShapeType == "Face", face.ShapeType
    assert rep["weak_control_points"] == 0 and rep["data_max"] < 5e-3 and rep["flipped_triangles"] == 0, rep
    assert abs(rep["width"] - 6) < 0.1 and abs(rep["height"] - 3) < 0.1, rep
    assert len(rep["uv"]) == m.CountPoints
    # The trimmed face is smaller than its untrimmed surface (the cut corner is trimmed away).
    assert face.Area < surface.Area, (face.Area, surface.Area)
    assert m.Topology[0] == before[0], "the mesh was modified"
    alone = HoleFill.fitLabeled(m, labels, controlPoints=(10, 8), extension="none")[2]
    # The condition of the points' own normal matrix; singular (null in JSON) without the extension.
    aloneCond = float("inf") if alone["log10_condition"] is None else alone["log10_condition"]
    assert alone["weak_control_points"] > 0 and aloneCond > rep["log10_condition"], alone
    # The paper's mesh fairness (E_Mesh) through the Python door: it changes the extension and
    # keeps the fit sound; a negative weight is refused.
    g2 = HoleFill.fitLabeled(m, labels, controlPoints=(10, 8), extension="G2")[2]
    fair = HoleFill.fitLabeled(m, labels, controlPoints=(10, 8), extension="G2", meshFairness=1e-2)[2]
    assert fair["weak_control_points"] == 0 and fair["data_max"] < 5e-3, fair
    assert fair["extended"][0].tolist() != g2["extended"][0].tolist(), "meshFairness changed nothing"
    # On the default extension (sampled from a thin-plate fit) it would change nothing: refused.
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, labels, meshFairness=1e-2), "ask for extension G2 or G1")
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, labels, meshFairness=-1), "zero or positive")
    # Control points chosen by the data through the Python door; exactly the given ones with
    # maxControl=0; a maximum below the start is refused.
    refined = HoleFill.fitLabeled(m, labels, controlPoints=(5, 5), maxControl=30, relativeTolerance=1e-4)[2]
    assert refined["control_points_u"] > 5 and len(refined["refinements"]) >= 2, refined
    assert refined["weak_control_points"] == 0 and refined["data_max"] < 1e-3, refined
    exact = HoleFill.fitLabeled(m, labels, controlPoints=(5, 5), maxControl=0)[2]
    assert exact["control_points_u"] == 5 and len(exact["refinements"]) == 1, exact
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, labels, controlPoints=(10, 8), maxControl=6), "maxControl")


def test_an_isolated_fit_is_the_same_and_a_crash_in_it_is_an_error_not_the_end_of_freecad():
    import os
    m, labels = cut_region()
    here = HoleFill.fitLabeled(m, labels, controlPoints=(10, 8))
    there = HoleFill.fitLabeled(m, labels, controlPoints=(10, 8), isolated=True)
    assert there[2]["data_max"] == here[2]["data_max"] and there[0].isValid(), (there[2]["data_max"], here[2]["data_max"])
    assert there[2]["extended"][0].shape == here[2]["extended"][0].shape
    # The core's own errors cross as themselves.
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, labels, controlPoints=(10, 8), maxControl=6, isolated=True), "maxControl")
    # The child dies of SIGSEGV, as a crash in CGAL would: this process lives on and says so.
    os.environ["HOLEFILL_TEST_CRASH_CHILD"] = "fitLabeled"
    try:
        fcharness.expect_error(lambda: HoleFill.fitLabeled(m, labels, isolated=True), "crashed (SIGSEGV)", "FreeCAD and the document are untouched")
    finally:
        del os.environ["HOLEFILL_TEST_CRASH_CHILD"]
    # Cancelled at once: the child is stopped.
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, labels, isolated=True, progress=lambda f: False), "cancelled")
    assert HoleFill.fitLabeled(m, labels, controlPoints=(10, 8), isolated=True)[2]["data_max"] == here[2]["data_max"]


def test_four_corners_label_the_sides_of_the_smallest_bounding_rectangle_anticlockwise():
    from HoleFill.labeled import boundaryLoop, fourCorners
    m, _ = cut_region()  # 6 x 3, its north-east corner cut away
    loop, points = boundaryLoop(m)
    from HoleFill.labeled import segmentsOf
    for normal in ((0, 0, 1), (0, 0, -1)):
        corners = fourCorners(points, normal)
        assert len(corners) == 4 and sorted(corners.values()) == ["E", "N", "S", "W"], corners
        splits = sorted(corners)
        labels = [corners[k] for k in splits]
        start = labels.index("S")
        assert labels[start:] + labels[:start] in (["S", "E", "N", "W"], ["S", "W", "N", "E"]), labels
        # Seen from +z the S side is the bottom one (y = 0), seen from -z the top one (y = 3).
        side = {corners[k]: seg for k, seg in zip(splits, segmentsOf(len(loop), splits))}
        meanY = {lab: sum(points[k][1] for k in seg) / len(seg) for lab, seg in side.items()}
        assert (meanY["S"] < meanY["N"]) == (normal[2] > 0), (normal, meanY)
    # A labeled fit of the four corners' labels gives a valid face.
    from HoleFill.labeled import labelsJsonOf, segmentsOf
    corners = fourCorners(points, (0, 0, 1))
    splits = sorted(corners)
    face, _, rep = HoleFill.fitLabeled(m, labelsJsonOf(loop, splits, [corners[k] for k in splits]))
    assert face.isValid() and rep["weak_control_points"] == 0, rep["warnings"]
    fcharness.expect_error(lambda: fourCorners(points[:3], (0, 0, 1)), "fewer than 4")


def test_bad_labels_give_clear_errors():
    m, labels = cut_region()
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, [("N", labels[0][1]), ("S", labels[0][1])]), "labeled both")
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, [("Q", labels[0][1]), labels[1]]), "not N, E, S or W")
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, [labels[0]]), "at least two")
    fcharness.expect_error(lambda: HoleFill.fitLabeled(m, labels, extension="G7"), "extension must be one of fit, G2, G1, none")
    fcharness.expect_error(lambda: HoleFill.fitLabeled(Mesh.Mesh(), labels), "empty")


def test_labels_and_fit_objects_follow_each_other_and_refuse_bad_input():
    m, _ = cut_region()
    doc = FreeCAD.newDocument("LabeledObjects")
    doc.UndoMode = 1
    region = doc.addObject("Mesh::Feature", "Region")
    region.Mesh = m
    doc.recompute()
    loop, points = HoleFill.boundaryLoop(region.Mesh)
    splits = HoleFill.cornerSplits(points)
    assert len(splits) == 6, splits  # the L's six corners
    lab = HoleFill.makeBoundaryLabels(region)
    assert list(lab.Labels) == ["-"] * 6 and len(lab.Shape.Wires) == 6
    # Label the four outer sides by where their middles are.
    names = []
    for wire in lab.Shape.Wires:
        c = wire.CenterOfMass
        names.append("S" if c.y < 0.1 else "W" if c.x < 0.1 else "N" if c.y > 2.9 else "E" if c.x > 5.9 else "-")
    doc.openTransaction("label")
    lab.Labels = names
    doc.commitTransaction()
    doc.recompute()
    assert sorted(n for n in names if n != "-") == ["E", "N", "S", "W"], names
    fit = HoleFill.makeLabeledFit(lab, controlPoints=(10, 8))
    assert fit.MeshFairness == 0.0
    # The doors' defaults are the core's (LabeledFitOptions, through optionSchema), not copies:
    # tests/freecad/test_option_schema.py checks every one of them.
    fields = HoleFill.optionSchema("labeled_fit")
    assert fields["maxControl"]["default"] == 60
    assert fit.MaxControlPoints == 60 and fit.RelativeTolerance == 1e-3 and fit.Tolerance == 0 and fit.ReleaseDepth == 0.05 and fit.Isocurves == "grid"
    import json
    rep = json.loads(fit.Report)
    assert fit.Shape.isValid() and rep["weak_control_points"] == 0 and rep["data_max"] < 5e-3, rep
    assert fit.Untrimmed.Area > fit.Shape.Area
    # A label change recomputes the fit; G1 and no extension are options of the same object.
    before = fit.Report
    lab.Labels = ["-" if n == "W" else n for n in names]
    doc.recompute()
    assert fit.Report != before and fit.Shape.isValid()
    fit.Extension = "none"
    doc.recompute()
    assert json.loads(fit.Report)["extended_vertices"] == 0
    # Bad input: a closed mesh, a labels object with a bad label (nothing added, error said).
    closed = doc.addObject("Mesh::Feature", "Closed")
    closed.Mesh = Mesh.createSphere(1.0, 16)
    doc.recompute()
    count = len(doc.Objects)
    fcharness.expect_error(lambda: HoleFill.makeBoundaryLabels(closed), "no open boundary")
    fcharness.expect_error(lambda: HoleFill.makeBoundaryLabels(region, labels=["Q"] * 6), "not N, E, S, W")
    fcharness.expect_error(lambda: HoleFill.makeLabeledFit(region), "BoundaryLabels")
    assert len(doc.Objects) == count, [o.Name for o in doc.Objects]
    FreeCAD.closeDocument(doc.Name)


def test_a_fit_saved_with_a_relative_tolerance_reads_it_as_the_relative_tolerance():
    # Documents saved before the tolerance took model units hold Tolerance as a float of the
    # region's diagonal: restored, that value is RelativeTolerance, and Tolerance is 0 mm.
    from HoleFill import labeled
    doc = FreeCAD.newDocument("old_fit")
    try:
        obj = doc.addObject("Part::FeaturePython", "Fit")
        labeled.LabeledFitFeature(obj)
        obj.removeProperty("RelativeTolerance")
        obj.removeProperty("Tolerance")
        obj.addProperty("App::PropertyFloat", "Tolerance", "Fit", "as saved before")
        obj.Tolerance = 2e-3
        obj.Proxy.onDocumentRestored(obj)
        assert obj.RelativeTolerance == 2e-3 and obj.Tolerance == 0, (obj.RelativeTolerance, obj.Tolerance)
        assert obj.getTypeIdOfProperty("Tolerance") == "App::PropertyLength", obj.getTypeIdOfProperty("Tolerance")
    finally:
        FreeCAD.closeDocument(doc.Name)


fcharness.run(globals())
