"""GUI test (issue 25, item 4): a scan-like region cut as scans are (the triangles of a jittered grid
inside an ellipse: a staircase boundary) is cut by corner angles into many segments; one
real click on "Four corners (S, E, N, W)" labels it at the corners of its smallest bounding
rectangle, S, E, N, W anticlockwise, with arrows along the boundary showing that way; a click 6
pixels inside an edge cycles its segment's label, the keys S and Delete set it directly; OK
stores the labels, and "Fit labeled surface" fits them with a valid face. Screenshot saved."""
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
    # Arrows along the boundary show the way S, E, N, W go: one arrowhead (two strokes) a segment.
    from pivy import coin
    root = view.getSceneGraph()
    found = coin.SoSearchAction()
    found.setName("HoleFillLabels_arrows")
    found.apply(root)
    assert found.getPath() is not None, "no direction arrows"
    arrows = found.getPath().getTail()
    lines = [arrows.getChild(i) for i in range(arrows.getNumChildren()) if isinstance(arrows.getChild(i), coin.SoLineSet)][0]
    assert lines.numVertices.getNum() == 8, lines.numVertices.getNum()
    # A label set by its key: click the S side 6 pixels inside (it cycles to W), then press S;
    # Delete unlabels it; S again.
    import subprocess
    from HoleFill.labeled import boundaryLoop, fourCorners, segmentsOf
    loop, points = boundaryLoop(region.Mesh)
    corners = fourCorners(points, (0, 0, 1))
    south = dict(zip(sorted(corners), segmentsOf(len(loop), sorted(corners))))[[k for k, v in corners.items() if v == "S"][0]]
    # Its longest edge on screen, clicked 6 pixels inside across its middle.
    scr = [view.getPointOnScreen(FreeCAD.Vector(*q)) for q in points]
    e = max(range(len(south) - 1), key=lambda i: math.hypot(scr[south[i + 1]][0] - scr[south[i]][0], scr[south[i + 1]][1] - scr[south[i]][1]))
    a, b = scr[south[e]], scr[south[e + 1]]
    c = view.getPointOnScreen(FreeCAD.Vector(3.0, 1.6, 0))  # the region's middle
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    across = (-(b[1] - a[1]), b[0] - a[0])
    if across[0] * (c[0] - mid[0]) + across[1] * (c[1] - mid[1]) < 0:
        across = (-across[0], -across[1])
    norm = math.hypot(*across)
    sx, sy = mid[0] + 6 * across[0] / norm, mid[1] + 6 * across[1] / norm
    vp = view.graphicsView().viewport()
    from PySide2 import QtCore
    g = vp.mapToGlobal(QtCore.QPoint(int(round(sx)), int(round(vp.height() - 1 - sy))))
    subprocess.run(["xdotool", "mousemove", str(g.x()), str(g.y())], check=True)
    h.pump(200)
    subprocess.run(["xdotool", "click", "1"], check=True)
    h.pump(500)

    def labelsNow():
        return sorted(segs.item(i).text().split(": ")[1].split(",")[0] for i in range(segs.count()))
    assert labelsNow() == ["E", "N", "W", "W"], labelsNow()  # S cycled to W
    for key, expected in (("s", ["E", "N", "S", "W"]), ("Delete", ["E", "N", "W", "unlabeled"]), ("s", ["E", "N", "S", "W"])):
        subprocess.run(["xdotool", "key", key], check=True)
        h.pump(400)
        assert labelsNow() == expected, (key, labelsNow())
    h.click_button(h.task_ok_button())
    h.pump(1000)
    lab = [o for o in doc.Objects if hasattr(o, "LabelsJson")]
    assert len(lab) == 1, [o.Name for o in doc.Objects]
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(lab[0])
    FreeCADGui.runCommand("HoleFill_FitLabeled")
    h.pump(300)
    label = mw.findChild(QtWidgets.QLabel, "HoleFillFitStatus")
    h.wait_for(lambda: "face " in label.text())
    status = label.text()
    assert "face valid" in status, status
    h.finish(True, segments_before=before, labels=labels)


h.run(body, 500)
