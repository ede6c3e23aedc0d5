"""GUI test of "Fit point cloud" in the real FreeCAD: a scanned-like Points cloud of a 40 mm bumpy
sheet (no boundary marked) is selected with a real click; the panel previews with
shape-preserving parameters: the boundary is found, the fit meets the 0.04 mm tolerance without
folds, and the hierarchical mesh (one colour per level) and the point errors are drawn in the 3D
view. BIDGCN parameters preview too; unchecking adaptive refinement previews one uniform level
that does not meet the tolerance. OK makes a PointCloudFit object (valid face within the
tolerance of the points) that recomputes when its options change; undo removes it and the cloud is untouched. A bad selection answers
with a message and changes nothing. Screenshots are saved."""
import json
import math
import random

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

import guiharness as h

S = 40.0


def height(x, y):
    u, v = x / S, y / S
    return S * (0.15 * math.sin(2.5 * u) * math.cos(1.8 * v) + 0.06 * math.exp(-40 * ((u - .6) ** 2 + (v - .4) ** 2)))


def body():
    import Points
    from PySide2.QtTest import QTest
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc = FreeCAD.newDocument("GuiPointFit")
    doc.UndoMode = 1
    random.seed(11)
    pts = []
    for _ in range(2500):
        x, y = random.uniform(0, S), random.uniform(0, S)
        pts.append(FreeCAD.Vector(x, y, height(x, y)))
    cloud = doc.addObject("Points::Feature", "Scan")
    cloud.Points = Points.Points(pts)
    box = doc.addObject("Part::Box", "Box")
    box.Placement.Base = FreeCAD.Vector(100, 0, 0)
    doc.recompute()
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewTop()
    view.fitAll()
    h.pump(500)
    before = [tuple(p) for p in cloud.Points.Points]

    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(box)
    msg = h.run_expecting_message("HoleFill_FitPointCloud")
    assert "Select one Points or Mesh object" in msg, msg
    count = len(doc.Objects)

    # A real click on a point of the cloud selects it.
    FreeCADGui.Selection.clearSelection()
    cloud.ViewObject.PointSize = 6
    h.pump(200)
    near = min(pts, key=lambda p: (p.x - S / 2) ** 2 + (p.y - S / 2) ** 2)
    h.click_at(view, near)
    assert [o.Name for o in FreeCADGui.Selection.getSelection()] == ["Scan"], FreeCADGui.Selection.getSelection()
    FreeCADGui.runCommand("HoleFill_FitPointCloud")
    h.pump(2000)
    h.assert_panel_fits()
    mw = FreeCADGui.getMainWindow()
    status = mw.findChild(QtWidgets.QLabel, "HoleFillPointFitStatus")
    method = mw.findChild(QtWidgets.QComboBox, "HoleFillPointFitMethod")
    tol = mw.findChild(QtWidgets.QDoubleSpinBox, "HoleFillPointFitTolerance")
    assert status is not None and method.currentText() == "shape", status
    assert abs(tol.value() - 0.001 * cloud.Points.BoundBox.DiagonalLength) < 0.01 * tol.value(), tol.value()
    tol.setValue(0.04)
    QTest.mouseClick(mw.findChild(QtWidgets.QPushButton, "HoleFillPointFitPreview"), QtCore.Qt.LeftButton)
    h.pump(2000)
    text = status.text()
    assert "shape parameters" in text and ", found" in text and "tolerance met" in text and "folds" not in text, text
    box.ViewObject.Visibility = False
    cloud.ViewObject.Visibility = False  # the overlay draws the points in their error colours
    sg = view.getSceneGraph()
    names = set()
    for i in range(sg.getNumChildren()):
        names.add(sg.getChild(i).getName().getString())
    assert "HoleFillPointFit" in names, names
    view.viewIsometric()
    view.fitAll()
    h.pump(300)
    view.saveImage(h.shot("gui_point_fit_1_shape.png"), 1024, 768, "White")

    method.setCurrentText("bidgcn")
    QTest.mouseClick(mw.findChild(QtWidgets.QPushButton, "HoleFillPointFitPreview"), QtCore.Qt.LeftButton)
    h.pump(2000)
    assert "bidgcn parameters" in status.text(), status.text()
    view.saveImage(h.shot("gui_point_fit_2_bidgcn.png"), 1024, 768, "White")

    # One uniform level: previewed, tolerance not met.
    method.setCurrentText("shape")
    mw.findChild(QtWidgets.QCheckBox, "HoleFillPointFitAdaptive").setChecked(False)
    QTest.mouseClick(mw.findChild(QtWidgets.QPushButton, "HoleFillPointFitPreview"), QtCore.Qt.LeftButton)
    h.pump(1500)
    assert "shape parameters" in status.text() and "tolerance NOT met" in status.text(), status.text()
    view.saveImage(h.shot("gui_point_fit_3_uniform.png"), 1024, 768, "White")
    mw.findChild(QtWidgets.QCheckBox, "HoleFillPointFitAdaptive").setChecked(True)

    QTest.mouseClick(h.task_ok_button(), QtCore.Qt.LeftButton)
    h.pump(2000)
    fits = [o for o in doc.Objects if hasattr(o, "Report") and hasattr(o, "Adaptive")]
    assert len(fits) == 1, [o.Name for o in doc.Objects]
    fit = fits[0]
    rep = json.loads(fit.Report)
    assert fit.Shape.isValid() and len(fit.Shape.Faces) == 1
    assert rep["met_tolerance"] and rep["parameterization"]["method"] == "shape" and rep["folds"] == 0, rep
    import Part
    worst = max(fit.Shape.distToShape(Part.Vertex(p))[0] for p in pts[::250])
    assert worst <= 0.04 + 1e-6, worst
    view.saveImage(h.shot("gui_point_fit_4_object.png"), 1024, 768, "White")

    # Parametric: a looser tolerance recomputes with fewer functions.
    dof = rep["iterations"][-1]["dof"]
    doc.openTransaction("Looser")
    fit.Tolerance = 0.4
    doc.commitTransaction()
    doc.recompute()
    looser = json.loads(fit.Report)
    assert looser["iterations"][-1]["dof"] < dof and looser["met_tolerance"], (dof, looser["iterations"])
    doc.undo()
    doc.recompute()
    doc.undo()
    h.pump(300)
    assert len(doc.Objects) == count, [o.Name for o in doc.Objects]
    assert [tuple(p) for p in cloud.Points.Points] == before, "the cloud was modified"
    h.finish(True, dof=dof, max_error=rep["iterations"][-1]["max_error"] * rep["diagonal"], levels=rep["levels"])


h.run(body, 500)
