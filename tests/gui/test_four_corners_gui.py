"""GUI test (issue 25, item 4): a scan-like region cut as scans are (the triangles of a jittered grid
inside an ellipse: a staircase boundary) is cut by corner angles into many segments; one
real click on "Four corners (S, E, N, W)" labels it at the corners of its smallest bounding
rectangle, S, E, N, W anticlockwise; OK stores the labels, and "Fit labeled surface" fits them
with a valid face. Screenshot saved."""
import math
import random

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import guiharness as h

NX, NY, H = 30, 16, 0.2


def jagged_region():
    import Mesh
    rng = random.Random(7)
    pts, facets = [], []
    for j in range(NY + 1):
        for i in range(NX + 1):
            x, y = i * H + rng.uniform(-H / 3, H / 3), j * H + rng.uniform(-H / 3, H / 3)
            pts.append(FreeCAD.Vector(x, y, 0.25 * math.sin(0.6 * x) * math.cos(0.8 * y) + rng.gauss(0, 0.01)))
    # Cut as a scan region is: the triangles whose centre lies in an ellipse, a staircase boundary.
    for j in range(NY):
        for i in range(NX):
            a, b = j * (NX + 1) + i, j * (NX + 1) + i + 1
            c, d = b + NX + 1, a + NX + 1
            for t in ((a, b, c), (a, c, d)):
                cx, cy = (sum(pts[k].x for k in t) / 3 - 3.0) / 2.9, (sum(pts[k].y for k in t) / 3 - 1.6) / 1.5
                if cx * cx + cy * cy < 1:
                    facets.append([pts[k] for k in t])
    return Mesh.Mesh(facets)


def body():
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc = FreeCAD.newDocument("GuiFourCorners")
    region = doc.addObject("Mesh::Feature", "Scan")
    region.Mesh = jagged_region()
    doc.recompute()
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewTop()
    view.fitAll()
    h.pump(400)
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(region)
    FreeCADGui.runCommand("HoleFill_LabelBoundary")
    h.pump(800)
    h.assert_panel_fits()
    mw = FreeCADGui.getMainWindow()
    segs = mw.findChild(QtWidgets.QListWidget, "HoleFillLabelSegments")
    before = segs.count()
    h.log("segments at the default corner angle: %d" % before)
    assert before > 4, before  # what a user met: no four sides to label
    h.click_button(mw.findChild(QtWidgets.QPushButton, "HoleFillLabelFourCorners"))
    h.pump(800)
    texts = [segs.item(i).text() for i in range(segs.count())]
    assert len(texts) == 4, texts
    labels = [t.split(": ")[1].split(",")[0] for t in texts]
    assert sorted(labels) == ["E", "N", "S", "W"], texts
    # Anticlockwise seen from the region's normal (+z here, top view): S, E, N, W follow each other.
    start = labels.index("S")
    assert labels[start:] + labels[:start] in (["S", "E", "N", "W"], ["S", "W", "N", "E"]), labels
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_four_corners.png"))
    h.click_button(h.task_ok_button())
    h.pump(1000)
    lab = [o for o in doc.Objects if hasattr(o, "LabelsJson")]
    assert len(lab) == 1, [o.Name for o in doc.Objects]
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(lab[0])
    FreeCADGui.runCommand("HoleFill_FitLabeled")
    h.pump(3000)
    status = mw.findChild(QtWidgets.QLabel, "HoleFillFitStatus").text()
    assert "face valid" in status, status
    h.finish(True, segments_before=before, labels=labels)


h.run(body, 500)
