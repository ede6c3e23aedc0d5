"""GUI test of "Label boundary" and "Fit labeled surface" in the real FreeCAD: an L-shaped wavy
mesh region (its north-east corner cut away) is selected with a real click; the panel splits its
boundary at the six corners; real clicks (xdotool) near boundary edges cycle four segments to S,
E, N and W (drawn in colour with letters), a click on a boundary vertex splits a segment and a
second click merges it again; OK stores a BoundaryLabels object. "Fit labeled surface" previews
the frame, the extended mesh and the surface, and OK makes a LabeledFit object: a valid trimmed
face with no weak control point that recomputes when a label changes; undo removes it. Bad
selections (nothing, a closed mesh, a mesh without labels) answer with a message and change
nothing. Screenshots are saved."""
import json
import math

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

import guiharness as h

NX, NY, H = 24, 12, 0.25


def wave(x, y):
    return 0.3 * math.sin(0.5 * x) * math.cos(0.7 * y)


def region_mesh():
    import Mesh
    vid, pts, facets = {}, [], []

    def v(i, j):
        if (i, j) not in vid:
            vid[(i, j)] = len(pts)
            pts.append(FreeCAD.Vector(i * H, j * H, wave(i * H, j * H)))
        return vid[(i, j)]
    for j in range(NY):
        for i in range(NX):
            if (i + .5) * H > 4.5 and (j + .5) * H > 2.0:
                continue  # the north-east corner is cut away
            a, b, c, d = v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)
            facets += [(a, b, c), (a, c, d)]
    return Mesh.Mesh((pts, facets))


def click(view, x, y):
    """A real click at the screen position of the surface point over (x, y)."""
    h.click_at(view, FreeCAD.Vector(x, y, wave(x, y)))


def segment_texts(lst):
    return [lst.item(i).text() for i in range(lst.count())]


def body():
    import Mesh
    from PySide2.QtTest import QTest
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc = FreeCAD.newDocument("GuiLabeled")
    doc.UndoMode = 1
    region = doc.addObject("Mesh::Feature", "Region")
    region.Mesh = region_mesh()
    closed = doc.addObject("Mesh::Feature", "Closed")
    closed.Mesh = Mesh.createSphere(1.0, 16)
    closed.Placement.Base = FreeCAD.Vector(20, 0, 0)
    doc.recompute()
    closed.ViewObject.Visibility = False
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewTop()
    view.fitAll()
    h.pump(500)
    points_before = region.Mesh.Topology

    # Bad selections: nothing; a closed mesh; a mesh without labels for the fit.
    FreeCADGui.Selection.clearSelection()
    msg = h.run_expecting_message("HoleFill_LabelBoundary")
    assert "Select one mesh region" in msg, msg
    FreeCADGui.Selection.addSelection(closed)
    msg = h.run_expecting_message("HoleFill_LabelBoundary")
    assert "no open boundary" in msg, msg
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(region)
    msg = h.run_expecting_message("HoleFill_FitLabeled")
    assert "no boundary labels yet" in msg, msg
    count = len(doc.Objects)

    # Select the region with a real click inside it, then label its boundary.
    FreeCADGui.Selection.clearSelection()
    click(view, 2.0, 1.5)
    assert [o.Name for o in FreeCADGui.Selection.getSelection()] == ["Region"], FreeCADGui.Selection.getSelection()
    FreeCADGui.runCommand("HoleFill_LabelBoundary")
    h.pump(800)
    h.assert_panel_fits()
    mw = FreeCADGui.getMainWindow()
    segs = mw.findChild(QtWidgets.QListWidget, "HoleFillLabelSegments")
    assert segs is not None and segs.isVisible()
    assert segs.count() == 6, segment_texts(segs)  # split at the six corners of the L
    assert all("unlabeled" in t for t in segment_texts(segs))

    # Real clicks 6 pixels inside the boundary (where a user clicks "on" it), at the middle of four
    # sides: N → E → S → W cycle.
    a, b = view.getPointOnScreen(FreeCAD.Vector(0, 0, wave(0, 0))), view.getPointOnScreen(FreeCAD.Vector(1, 0, wave(1, 0)))
    inset = 6.0 / math.hypot(b[0] - a[0], b[1] - a[1])
    for (x, y), times in (((3.125, inset), 3), ((6.0 - inset, 1.125), 2), ((2.125, 3.0 - inset), 1), ((inset, 1.625), 4)):
        for _ in range(times):
            click(view, x, y)
    texts = segment_texts(segs)
    labels = sorted(t.split(": ")[1].split(",")[0] for t in texts)
    assert labels == ["E", "N", "S", "W", "unlabeled", "unlabeled"], texts
    view.saveImage(h.shot("gui_labeled_1_labels.png"), 1024, 768, "White")

    # A click on a boundary vertex splits the south segment; a second click merges it again.
    click(view, 3.0, 0.0)
    assert segs.count() == 7, segment_texts(segs)
    assert sorted(t.split(": ")[1].split(",")[0] for t in segment_texts(segs)).count("S") == 2
    click(view, 3.0, 0.0)
    assert segs.count() == 6, segment_texts(segs)

    QTest.mouseClick(h.task_ok_button(), QtCore.Qt.LeftButton)
    h.pump(1000)
    labels_obj = [o for o in doc.Objects if hasattr(o, "LabelsJson")]
    assert len(labels_obj) == 1, [o.Name for o in doc.Objects]
    lab = labels_obj[0]
    got = json.loads(lab.LabelsJson)
    assert sorted(s["label"] for s in got["segments"]) == ["E", "N", "S", "W"], got
    assert lab.Shape.isValid() and len(lab.Shape.Wires) == 6
    assert sorted(lab.Labels) == ["-", "-", "E", "N", "S", "W"], lab.Labels

    # Fit labeled surface: preview, then OK.
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(lab)
    FreeCADGui.runCommand("HoleFill_FitLabeled")
    h.pump(300)
    status = mw.findChild(QtWidgets.QLabel, "HoleFillFitStatus")
    h.wait_for(lambda: status is not None and "weak control points" in status.text())
    h.assert_panel_fits()
    assert status is not None and "0 weak control points" in status.text(), status.text() if status else None
    view.viewIsometric()
    view.fitAll()
    h.pump(300)
    view.saveImage(h.shot("gui_labeled_2_preview.png"), 1024, 768, "White")
    # A crash inside the fit (its process dies of SIGSEGV, as it did in CGAL) fails the Preview
    # with a message and leaves FreeCAD, the document and the panel as they were.
    import os
    objects = len(doc.Objects)
    preview = mw.findChild(QtWidgets.QPushButton, "HoleFillFitPreview")
    os.environ["HOLEFILL_TEST_CRASH_CHILD"] = "fitLabeled"
    try:
        h.click_button(preview)
        h.wait_for(lambda: "crashed" in status.text())
    finally:
        del os.environ["HOLEFILL_TEST_CRASH_CHILD"]
    assert "crashed (SIGSEGV)" in status.text() and "untouched" in status.text(), status.text()
    assert len(doc.Objects) == objects
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_labeled_2b_crash_contained.png"))
    h.click_button(preview)
    h.wait_for(lambda: "0 weak control points" in status.text())
    assert "0 weak control points" in status.text(), status.text()
    QTest.mouseClick(h.task_ok_button(), QtCore.Qt.LeftButton)
    h.pump(1500)
    fits = [o for o in doc.Objects if hasattr(o, "Untrimmed")]
    assert len(fits) == 1, [o.Name for o in doc.Objects]
    fit = fits[0]
    rep = json.loads(fit.Report)
    assert fit.Shape.isValid() and len(fit.Shape.Faces) == 1, fit.Shape
    assert rep["weak_control_points"] == 0 and rep["data_max"] < 5e-3 and rep["face_valid"], rep
    assert abs(fit.Shape.Area - region.Mesh.Area) < 0.01 * region.Mesh.Area, (fit.Shape.Area, region.Mesh.Area)
    view.saveImage(h.shot("gui_labeled_3_fit.png"), 1024, 768, "White")

    # The fit follows its labels: drop the West label.
    before = fit.Report
    doc.openTransaction("Unlabel West")
    lab.Labels = ["-" if l == "W" else l for l in lab.Labels]
    doc.commitTransaction()
    doc.recompute()
    assert fit.Report != before and fit.Shape.isValid(), fit.Report
    doc.undo()  # the label change
    doc.recompute()
    doc.undo()  # the fit
    doc.undo()  # the labels
    h.pump(300)
    assert len(doc.Objects) == count, [o.Name for o in doc.Objects]
    assert region.Mesh.Topology == points_before, "the mesh was modified"
    h.finish(True, data_max=rep["data_max"], weak=rep["weak_control_points"], log10_condition=rep["log10_condition"])


h.run(body, 500)
