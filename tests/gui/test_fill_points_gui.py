"""GUI test of the Fill panel's points to pass through (Surface Filling's vertex constraints), in
the real FreeCAD with real clicks: the open top of a 30 x 20 x 10 box and a vertex 2 above the
opening's middle. Click a hole edge, run Fill hole, click the vertex, press "Add selected" (the
panel lists it and draws it), Preview (the report says the point was passed through), OK: the
Fill keeps the point in its Points property and its face passes through it, where the flat top
would miss it by 2; Clear empties the list. Screenshots are saved."""
import json

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import guiharness as h


def body():
    import HoleFill
    import Part
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc, src = h.sample_document("GuiFillPoints", "Box", "box_minus_face")
    mark = doc.addObject("Part::Feature", "Mark")
    target = FreeCAD.Vector(15, 10, 12)
    mark.Shape = Part.Vertex(target)
    mark.ViewObject.PointSize = 10
    doc.recompute()
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    h.pump(500)
    hole = HoleFill.findHoles(src.Shape)[0]
    name, x, y = h.visible_hole_edge(view, src, hole.edges)
    assert name, "no hole edge visible at its midpoint"
    FreeCADGui.Selection.clearSelection()
    h.click_screen(x, y)
    assert [n for s in FreeCADGui.Selection.getSelectionEx() for n in s.SubElementNames] == [name]
    FreeCADGui.runCommand("HoleFill_FillHole")
    h.pump(800)
    h.assert_panel_fits()
    mw = FreeCADGui.getMainWindow()
    label = mw.findChild(QtWidgets.QLabel, "HoleFillFillPointsLabel")
    assert label is not None and "none" in label.text(), label.text() if label else None
    continuity = [c for c in mw.findChildren(QtWidgets.QComboBox) if c.isVisible() and c.findText("G2") >= 0 and c.count() == 3][0]
    continuity.setCurrentText("G0")  # the box's rim is sharp: G0 is what it can have

    # The vertex, by a real click on it; then "Add selected".
    FreeCADGui.Selection.clearSelection()
    h.click_at(view, target)
    picked = [(s.Object.Name, list(s.SubElementNames)) for s in FreeCADGui.Selection.getSelectionEx()]
    assert picked == [("Mark", ["Vertex1"])], picked
    h.click_button(mw.findChild(QtWidgets.QPushButton, "HoleFillFillAddPoints"))
    h.pump(300)
    assert label.text() == "1 points", label.text()
    from pivy import coin  # noqa: F401
    root = view.getSceneGraph()
    assert any(root.getChild(i).getName().getString() == "HoleFillFillPoints" for i in range(root.getNumChildren()))

    preview = [b for b in mw.findChildren(QtWidgets.QPushButton) if b.isVisible() and b.text() == "Preview"][0]
    h.click_button(preview)
    report = [w for w in mw.findChildren(QtWidgets.QPlainTextEdit) if w.isVisible()][0]
    h.wait_for(lambda: "Points passed through" in report.toPlainText())
    assert "Points passed through: 1" in report.toPlainText(), report.toPlainText()
    view.saveImage(h.shot("gui_fill_points_1_preview.png"), 1024, 768, "White")

    h.click_button(h.task_ok_button())
    h.pump(1500)
    fills = [o for o in doc.Objects if o.Name.startswith("Fill")]
    assert len(fills) == 1, [o.Name for o in doc.Objects]
    fill = fills[0]
    assert [tuple(p) for p in fill.Points] == [(15.0, 10.0, 12.0)], fill.Points
    rep = json.loads(fill.Report)
    assert rep["status"] == "ok" and rep["point_distances"][0] <= rep["g0_tolerance"], (rep["status"], rep["message"])
    gap = fill.Shape.distToShape(Part.Vertex(target))[0]
    assert gap <= rep["g0_tolerance"], gap
    assert not [n for n in (root.getChild(i).getName().getString() for i in range(root.getNumChildren())) if n == "HoleFillFillPoints"]
    view.saveImage(h.shot("gui_fill_points_2_filled.png"), 1024, 768, "White")

    # Edit it: the panel shows the point; Clear empties the list, OK refills the flat top.
    FreeCADGui.ActiveDocument.setEdit(fill.Name)
    h.pump(800)
    label = mw.findChild(QtWidgets.QLabel, "HoleFillFillPointsLabel")
    assert label.text() == "1 points", label.text()
    h.click_button(mw.findChild(QtWidgets.QPushButton, "HoleFillFillClearPoints"))
    h.pump(300)
    assert "none" in label.text(), label.text()
    h.click_button(h.task_ok_button())
    h.pump(1500)
    assert len(fill.Points) == 0
    flat = fill.Shape.distToShape(Part.Vertex(target))[0]
    assert abs(flat - 2.0) < 1e-3, flat
    h.finish(True, edge=name, gap=gap, flat=flat)


h.run(body, 500)
