"""GUI test (issue 25, item 6): a band-shaped opening, a washer without its top (two free loops
bounding one annulus), is not filled with one loop. With real clicks on a top circle: the Fill
panel says at once that the opening has 2 boundary loops and draws both; Preview says why it
cannot fill; OK keeps nothing; the source is untouched. Screenshot saved."""
import subprocess

import FreeCAD
import FreeCADGui
import Part
from PySide2 import QtWidgets

import guiharness as h


def body():
    import HoleFill
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc = FreeCAD.newDocument("GuiBand")
    washer = Part.makeCylinder(10, 3).cut(Part.makeCylinder(4, 3))
    src = doc.addObject("Part::Feature", "Washer")
    src.Shape = Part.Shell([f for f in washer.Faces if not (f.Surface.__class__.__name__ == "Plane" and f.CenterOfMass.z > 1.5)])
    # Moved: its shape carries the placement, and the overlays must not apply it a second time.
    src.Placement = FreeCAD.Placement(FreeCAD.Vector(30, 5, 0), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 30))
    doc.recompute()
    before = src.Shape.exportBrepToString()
    holes = HoleFill.findHoles(src.Shape, includeOuter=True)
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    h.pump(500)
    name, x, y = h.visible_hole_edge(view, src, [e for hole in holes for e in hole.edges])
    assert name, "no top circle visible"
    FreeCADGui.Selection.clearSelection()
    subprocess.run(["xdotool", "mousemove", str(x), str(y)], check=True)
    h.pump(300)
    subprocess.run(["xdotool", "click", "1"], check=True)
    h.pump(500)
    picked = [n for s in FreeCADGui.Selection.getSelectionEx() for n in s.SubElementNames]
    assert picked == [name], picked
    FreeCADGui.runCommand("HoleFill_FillHole")
    h.pump(800)
    h.assert_panel_fits()
    mw = FreeCADGui.getMainWindow()
    labels = [w.text() for w in mw.findChildren(QtWidgets.QLabel) if w.isVisible() and "boundary loops" in w.text()]
    assert labels and "2 boundary loops" in labels[0], [w.text() for w in mw.findChildren(QtWidgets.QLabel) if w.isVisible()][:6]
    # The drawn loops lie on the washer's top circles (in the scene's coordinates), not moved twice.
    from pivy import coin
    root = view.getSceneGraph()
    loop = [root.getChild(i) for i in range(root.getNumChildren()) if root.getChild(i).getName().getString() == "HoleFillFillLoop"][0]
    found = coin.SoSearchAction()
    found.setType(coin.SoCoordinate3.getClassTypeId())
    found.setInterest(coin.SoSearchAction.ALL)
    found.apply(loop)
    pts = [tuple(c.getTail().point[k].getValue()) for c in [found.getPaths()[i] for i in range(found.getPaths().getLength())]
           for k in range(c.getTail().point.getNum())]
    xf = [loop.getChild(i) for i in range(loop.getNumChildren()) if isinstance(loop.getChild(i), coin.SoMatrixTransform)][0]
    m = xf.matrix.getValue().getValue()
    identity = all(abs(m[r][c] - (1.0 if r == c else 0.0)) < 1e-9 for r in range(4) for c in range(4))
    bb = src.Shape.BoundBox
    assert identity and abs(max(p[0] for p in pts) - bb.XMax) < 0.1 and abs(min(p[0] for p in pts) - bb.XMin) < 0.1, \
        (identity, max(p[0] for p in pts), bb)
    h.click_button([b for b in mw.findChildren(QtWidgets.QPushButton) if b.isVisible() and b.text() == "Preview"][0])
    h.pump(1500)
    reports = [w.toPlainText() for w in mw.findChildren(QtWidgets.QPlainTextEdit) if w.isVisible()]
    assert reports and "Fill failed at" in reports[0] and "2 boundary loops" in reports[0], reports[:1]
    # Pressed again, the same failure shows that this Preview ran too (its time).
    first = reports[0]
    h.pump(1100)
    h.click_button([b for b in mw.findChildren(QtWidgets.QPushButton) if b.isVisible() and b.text() == "Preview"][0])
    h.pump(1500)
    again = [w.toPlainText() for w in mw.findChildren(QtWidgets.QPlainTextEdit) if w.isVisible()][0]
    assert again != first and "2 boundary loops" in again, (first, again)
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_band_opening.png"))
    h.click_button(h.task_ok_button())
    h.pump(1500)
    assert not [o for o in doc.Objects if o.Name.startswith("Fill")], "a Fill was made of a band-shaped opening"
    assert src.Shape.exportBrepToString() == before
    h.finish(True, clicked=name, label=labels[0])


h.run(body, 500)
