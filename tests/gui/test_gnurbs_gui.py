"""GUI test of "G-NURBS surface" in the real FreeCAD: a quad cage imported from an OBJ, selected
with a real click; the panel lists its extraordinary point; real clicks (xdotool) on three cage
edges from the EP to the boundary mark them sharp (drawn orange in the overlay) and a second click
unmarks one and a third marks it again; the EP's anchor is switched on with a real checkbox click
and lifted; OK creates the parametric object: G² off the creases, the EP on its anchor. Moving
a cage vertex rebuilds the surface; undo removes the object. Bad selections answer with a
message and change nothing. Screenshots are saved."""
import os
import tempfile

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

import guiharness as h

OVERLAY = "HoleFillGnurbsCage"


def overlay_sharp_count():
    from pivy import coin
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    for i in range(root.getNumChildren()):
        node = root.getChild(i)
        if not node.getName().getString().startswith(OVERLAY):
            continue
        for k in range(node.getNumChildren()):
            sep = node.getChild(k)
            if sep.getName().getString() == OVERLAY + "_sharp":
                for j in range(sep.getNumChildren()):
                    if isinstance(sep.getChild(j), coin.SoLineSet):
                        return sep.getChild(j).numVertices.getNum()
        return 0
    return -1  # no overlay at all


def body():
    import Part
    from PySide2.QtTest import QTest
    import HoleFill
    import HoleFillApp
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc = FreeCAD.newDocument("GuiGnurbs")
    doc.UndoMode = 1
    path = os.path.join(tempfile.mkdtemp(), "cage.obj")
    with open(path, "w") as f:
        f.write(HoleFillApp.sampleCageObj("cage_valence5"))
    cage_obj, imported = HoleFill.importCage(path, doc)
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewTop()
    view.fitAll()
    h.pump(500)

    # Bad selections: nothing; a cylinder (faces that are not quads).
    FreeCADGui.Selection.clearSelection()
    msg = h.run_expecting_message("HoleFill_GnurbsSurface")
    assert "Select one quad cage" in msg, msg
    cyl = doc.addObject("Part::Feature", "Cyl")
    cyl.Shape = Part.makeCylinder(1, 2, FreeCAD.Vector(30, 0, 0))
    doc.recompute()
    FreeCADGui.Selection.addSelection(cyl)
    msg = h.run_expecting_message("HoleFill_GnurbsSurface")
    assert "Face" in msg and "quads" in msg, msg
    doc.removeObject("Cyl")
    doc.recompute()
    count = len(doc.Objects)

    # Select the cage with a real click inside a face, then run the command.
    cage = HoleFill.cageFromShape(cage_obj.Shape)
    eps = HoleFill.extraordinaryPoints(cage)
    assert list(eps.values()) == [5], eps
    ep = list(eps)[0]
    FreeCADGui.Selection.clearSelection()
    face_center = cage_obj.Shape.Faces[10].CenterOfMass
    h.click_at(view, face_center)
    assert [o.Name for o in FreeCADGui.Selection.getSelection()] == [cage_obj.Name], FreeCADGui.Selection.getSelection()
    FreeCADGui.runCommand("HoleFill_GnurbsSurface")
    h.pump(800)
    h.assert_panel_fits()
    mw = FreeCADGui.getMainWindow()
    sharp_list = mw.findChild(QtWidgets.QListWidget, "HoleFillGnurbsSharp")
    anchors = mw.findChild(QtWidgets.QTableWidget, "HoleFillGnurbsAnchors")
    assert sharp_list is not None and sharp_list.isVisible() and anchors is not None
    assert anchors.rowCount() == 1 and anchors.item(0, 0).text() == str(ep)
    assert overlay_sharp_count() == 0, overlay_sharp_count()

    # The spoke line from the EP to the boundary: follow cage edges away from the EP straight on.
    by_pair = {v: k for k, v in cage["shapeEdges"].items()}
    pts = [FreeCAD.Vector(*p) for p in cage["vertices"]]
    nbr = {}
    for a, b in cage["shapeEdges"].values():
        nbr.setdefault(a, set()).add(b)
        nbr.setdefault(b, set()).add(a)
    line = [ep, sorted(nbr[ep])[0]]
    while True:
        d = pts[line[-1]] - pts[line[-2]]
        ahead = [w for w in nbr[line[-1]] if w != line[-2] and (pts[w] - pts[line[-1]]).getAngle(d) < 0.3]
        if not ahead:
            break
        line.append(ahead[0])
    edges = [(min(a, b), max(a, b)) for a, b in zip(line, line[1:])]
    assert len(edges) == 3, line
    for e in edges:
        mid = cage_obj.Shape.getElement(by_pair[e]).CenterOfMass
        h.click_at(view, mid)
    h.pump(300)
    assert sorted(sharp_list.item(i).text() for i in range(sharp_list.count())) == sorted("%d-%d" % e for e in edges), \
        [sharp_list.item(i).text() for i in range(sharp_list.count())]
    assert overlay_sharp_count() == 3
    # A second click unmarks, a third marks again.
    mid = cage_obj.Shape.getElement(by_pair[edges[1]]).CenterOfMass
    h.click_at(view, mid)
    assert sharp_list.count() == 2, sharp_list.count()
    h.click_at(view, mid)
    assert sharp_list.count() == 3 and overlay_sharp_count() == 3
    view.saveImage(h.shot("gui_gnurbs_1_sharp.png"), 1024, 768, "White")

    # Anchor at the EP: a real click on its checkbox, then lift it.
    rect = anchors.visualItemRect(anchors.item(0, 0))
    QTest.mouseClick(anchors.viewport(), QtCore.Qt.LeftButton, QtCore.Qt.NoModifier, QtCore.QPoint(rect.left() + 10, rect.center().y()))
    h.pump(300)
    assert anchors.item(0, 0).checkState() == QtCore.Qt.Checked, "the checkbox click did not switch the anchor on"
    anchors.cellWidget(0, 3).setValue(pts[ep].z + 0.5)
    h.pump(200)

    ok = h.task_ok_button()
    QTest.mouseClick(ok, QtCore.Qt.LeftButton)
    h.pump(1500)
    assert overlay_sharp_count() == -1, "overlay left after OK"
    new = [o for o in doc.Objects if o.Name != cage_obj.Name]
    assert len(new) == 1, [o.Name for o in doc.Objects]
    g = new[0]
    import json
    rep = json.loads(g.Report)
    assert g.Shape.isValid() and g.Status == "ok", g.Status
    assert rep["continuity"]["sharp_edges"] == 3 and rep["continuity"]["g2_spokes"] < 1e-6 and rep["continuity"]["g1_elsewhere"] < 1e-8, rep
    assert sorted(g.SharpEdges) == sorted("%d-%d" % e for e in edges) and len(g.Anchors) == 1, (g.SharpEdges, g.Anchors)
    tip = FreeCAD.Vector(pts[ep].x, pts[ep].y, pts[ep].z + 0.5)
    assert min((v.Point - tip).Length for v in g.Shape.Vertexes) < 1e-7, "the EP is not on its anchor"
    view.viewIsometric()
    view.fitAll()
    h.pump(300)
    view.saveImage(h.shot("gui_gnurbs_2_surface.png"), 1024, 768, "White")

    # The surface follows its cage: lift a boundary vertex.
    area = g.Shape.Area
    moved = dict(cage)
    moved["vertices"] = [list(p) for p in cage["vertices"]]
    far = max(range(len(pts)), key=lambda i: pts[i].Length)
    moved["vertices"][far][2] += 1.0
    doc.openTransaction("Move a cage vertex")
    cage_obj.Shape = HoleFill.cageShell(moved)
    doc.commitTransaction()
    doc.recompute()
    assert abs(g.Shape.Area - area) > 1e-3 * area and g.G2 < 1e-6, (g.Shape.Area, area, g.G2)
    doc.undo()  # the cage change
    doc.undo()  # the G-NURBS object
    h.pump(300)
    assert len(doc.Objects) == count, [o.Name for o in doc.Objects]
    h.finish(True, faces=rep["brep"]["faces"], g2=rep["continuity"]["g2_spokes"])


h.run(body, 500)
