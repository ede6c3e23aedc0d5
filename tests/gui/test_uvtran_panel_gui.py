"""GUI test: the Fill task panel with UVTran: pick "uvtran" in the real combo box, tick "Show UVTran
projection surface" (a translucent overlay appears in the 3D view), Preview, OK; the Fill object
uses UVTran (no fallback), and the overlay is gone once the panel closes. Screenshots saved."""

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets
from PySide2.QtTest import QTest
from PySide2 import QtCore

import guiharness as h


def overlay_present():
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    return any(root.getChild(i).getName() == "HoleFillProjectionSurface" for i in range(root.getNumChildren()))


def body():
    import HoleFill
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc, src = h.sample_document("GuiUvtran", "Corner", "filleted_box_corner")
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    h.pump(300)
    hole = HoleFill.findHoles(src.Shape)[0]
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(src, hole.edges[0])
    FreeCADGui.runCommand("HoleFill_FillHole")
    h.pump(800)
    mw = FreeCADGui.getMainWindow()
    combos = [c for c in mw.findChildren(QtWidgets.QComboBox) if c.isVisible() and c.findText("uvtran") >= 0]
    assert combos, "no parameterization combo with uvtran in the task panel"
    combo = combos[0]
    # Choose it as a user does: open the popup, move to the entry with the keyboard, Enter.
    combo.setFocus()
    QTest.keyClick(combo, QtCore.Qt.Key_Home)
    for _ in range(combo.findText("uvtran")):
        QTest.keyClick(combo, QtCore.Qt.Key_Down)
    h.pump(200)
    assert combo.currentText() == "uvtran", combo.currentText()
    boxes = [b for b in mw.findChildren(QtWidgets.QCheckBox) if b.isVisible() and "projection" in " ".join(b.text().split())]
    assert boxes, "no 'Show UVTran projection surface' check box"
    QTest.mouseClick(boxes[0], QtCore.Qt.LeftButton)
    h.pump(1500)
    assert boxes[0].isChecked()
    assert overlay_present(), "the projection surface overlay did not appear"
    view.saveImage(h.shot("gui_uvtran_1_projection.png"), 1024, 768, "White")
    previews = [b for b in mw.findChildren(QtWidgets.QPushButton) if b.isVisible() and b.text() == "Preview"]
    QTest.mouseClick(previews[0], QtCore.Qt.LeftButton)
    h.pump(3000)
    oks = [b for box in mw.findChildren(QtWidgets.QDialogButtonBox) if box.isVisible()
           for b in [box.button(QtWidgets.QDialogButtonBox.Ok)] if b is not None and b.isVisible()]
    QTest.mouseClick(oks[0], QtCore.Qt.LeftButton)
    h.pump(1500)
    assert not overlay_present(), "the overlay outlived the task panel"
    fill = [o for o in doc.Objects if o.Name.startswith("Fill")][0]
    import json
    rep = json.loads(fill.Report)
    assert fill.Method == "uvtran" and rep["method"] == "uvtran", (fill.Method, rep["method"], rep["warnings"])
    assert fill.Status == "ok" and fill.G1 <= 1e-3, (fill.Status, fill.G1)
    h.pump(300)
    view.saveImage(h.shot("gui_uvtran_2_filled.png"), 1024, 768, "White")
    h.finish(True, g0=fill.G0, g1=fill.G1, method=rep["method"])


h.run(body, 500)
