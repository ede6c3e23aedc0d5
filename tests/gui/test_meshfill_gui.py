"""GUI test of "Fill mesh holes" in the real FreeCAD: click a scanned-like mesh with the real mouse
(xdotool), run the command, see its two holes listed and drawn (overlay line sets in the scene
graph, checked holes orange, the row selected in the table red), uncheck one hole with a real
click on its checkbox (QTest), press OK: a new mesh object with exactly that hole filled, the
source untouched, the overlay gone; undo removes the new object. Bad selections (nothing, a Part
shape) answer with a message and change nothing. Screenshots are saved."""
import math
import subprocess

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

import guiharness as h

OVERLAY = "HoleFillMeshHoles"


def overlay_nodes():
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    return [root.getChild(i) for i in range(root.getNumChildren())
            if root.getChild(i).getName().getString().startswith(OVERLAY)]


def line_colors(node):
    """{hole index: (r, g, b, line width)} read back from the overlay."""
    from pivy import coin
    out = {}
    for i in range(node.getNumChildren()):
        sep = node.getChild(i)
        name = sep.getName().getString()
        if "_hole" not in name:
            continue
        color = width = None
        for k in range(sep.getNumChildren()):
            n = sep.getChild(k)
            if isinstance(n, coin.SoBaseColor):
                color = tuple(round(x, 2) for x in n.rgb[0].getValue())
            if isinstance(n, coin.SoDrawStyle):
                width = n.lineWidth.getValue()
        out[int(name.split("_hole")[1])] = color + (width,)
    return out


def body():
    import Mesh
    import Part
    from PySide2.QtTest import QTest
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc = FreeCAD.newDocument("GuiMeshFill")
    src = doc.addObject("Mesh::Feature", "Scan")
    m = Mesh.createSphere(5.0, 50)
    pts, fac = m.Topology
    z = [sum(pts[k].z for k in f) / 3 for f in fac]
    m.removeFacets([i for i, f in enumerate(fac) if z[i] > 5 * math.cos(0.5) or z[i] < -5 * math.cos(0.35)])
    src.Mesh = m
    doc.recompute()
    before = (src.Mesh.CountPoints, src.Mesh.CountFacets, str(src.Mesh.BoundBox))
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewFront()
    view.fitAll()
    h.pump(500)

    # Bad selections first: a message each, nothing added.
    FreeCADGui.Selection.clearSelection()
    msg = h.run_expecting_message("HoleFill_FillMeshHoles")
    assert "Select one mesh object" in msg, msg
    part = doc.addObject("Part::Feature", "Box")
    part.Shape = Part.makeBox(1, 1, 1, FreeCAD.Vector(20, 0, 0))
    doc.recompute()
    FreeCADGui.Selection.addSelection(part)
    msg = h.run_expecting_message("HoleFill_FillMeshHoles")
    assert "holds no mesh" in msg, msg
    doc.removeObject("Box")
    doc.recompute()
    count = len(doc.Objects)

    # Select the mesh with a real click on its front.
    vp = view.graphicsView().viewport()
    sx, sy = view.getPointOnScreen(FreeCAD.Vector(0, -5, 0))
    g = vp.mapToGlobal(QtCore.QPoint(sx, vp.height() - 1 - sy))
    FreeCADGui.Selection.clearSelection()
    subprocess.run(["xdotool", "mousemove", str(g.x()), str(g.y())], check=True)
    h.pump(300)
    subprocess.run(["xdotool", "click", "1"], check=True)
    h.pump(500)
    sel = [o.Name for o in FreeCADGui.Selection.getSelection()]
    assert sel == ["Scan"], "selection after the click: %s" % sel

    FreeCADGui.runCommand("HoleFill_FillMeshHoles")
    h.pump(800)
    h.assert_panel_fits()
    table = FreeCADGui.getMainWindow().findChild(QtWidgets.QTableWidget, "HoleFillMeshHoleTable")
    assert table is not None and table.isVisible(), "no hole table in the task panel"
    assert table.rowCount() == 2, table.rowCount()
    shape = FreeCADGui.getMainWindow().findChild(QtWidgets.QComboBox, "HoleFillMeshFillShape")
    assert shape is not None and shape.count() == 3 and shape.currentIndex() == 0
    shape.setCurrentIndex(1)  # the closest-to-surface variant: the report must say which triangulation ran
    nodes = overlay_nodes()
    assert len(nodes) == 1, nodes
    colors = line_colors(nodes[0])
    assert set(colors) == {0, 1} and all(c[:3] == (1.0, 0.55, 0.1) for c in colors.values()), colors
    view.viewIsometric()
    view.fitAll()
    h.pump(300)
    view.saveImage(h.shot("gui_meshfill_1_holes.png"), 1024, 768, "White")

    # The hole-size limit (MeshLab's): between the two holes' sizes, the larger one is unchecked;
    # no limit checks both again.
    from HoleFillGui.task_meshfill import holeSize
    import HoleFill
    sizes = [holeSize(hh) for hh in HoleFill.meshHoles(src.Mesh)]
    size = FreeCADGui.getMainWindow().findChild(QtWidgets.QDoubleSpinBox, "HoleFillMaxHoleSize")
    size.setValue(0.5 * (sizes[0] + sizes[1]))
    h.pump(300)
    checked = [table.item(r, 0).checkState() == QtCore.Qt.Checked for r in range(2)]
    assert checked == [s_ < 0.5 * (sizes[0] + sizes[1]) for s_ in sizes], (checked, sizes)
    size.setValue(0)
    h.pump(300)
    assert all(table.item(r, 0).checkState() == QtCore.Qt.Checked for r in range(2))

    # Uncheck hole 1 with a real click on its checkbox; select row 0 to highlight it.
    table.scrollToItem(table.item(1, 0))
    rect = table.visualItemRect(table.item(1, 0))
    box = QtCore.QPoint(rect.left() + 10, rect.center().y())
    QTest.mouseClick(table.viewport(), QtCore.Qt.LeftButton, QtCore.Qt.NoModifier, box)
    h.pump(300)
    assert table.item(1, 0).checkState() == QtCore.Qt.Unchecked, "the checkbox click did not uncheck hole 1"
    table.selectRow(0)
    h.pump(300)
    colors = line_colors(overlay_nodes()[0])
    assert colors[0][:3] == (0.9, 0.0, 0.0) and colors[0][3] == 5, colors
    assert colors[1][:3] == (0.55, 0.55, 0.55), colors
    view.saveImage(h.shot("gui_meshfill_2_selected.png"), 1024, 768, "White")

    # Preview (a real click): the new triangles drawn, nothing added; the panel says what was
    # filled and that the result is still open (hole 1 unchecked), not only the report view.
    from pivy import coin
    h.click_button(FreeCADGui.getMainWindow().findChild(QtWidgets.QPushButton, "HoleFillMeshPreview"))
    label = FreeCADGui.getMainWindow().findChild(QtWidgets.QLabel, "HoleFillMeshStatus")
    h.wait_for(lambda: label.text().startswith("Preview"))
    status = label.text()
    assert "1 of 1 checked holes filled" in status and "still open" in status and "holes left open: 1 (not filled: not asked for)" in status, status
    assert len(doc.Objects) == count, "a Preview added to the document"
    previews = [n for n in overlay_nodes() if "Preview" in n.getName().getString()]
    assert len(previews) == 1, [n.getName().getString() for n in overlay_nodes()]
    faces = [previews[0].getChild(i) for i in range(previews[0].getNumChildren()) if isinstance(previews[0].getChild(i), coin.SoFaceSet)]
    added = faces[0].numVertices.getNum()
    assert added > 10, added
    # By quality: one colour per new triangle, from the red-to-blue scale (no grey, no green).
    byq = FreeCADGui.getMainWindow().findChild(QtWidgets.QCheckBox, "HoleFillMeshByQuality")
    h.click_button(byq)
    h.pump(500)
    assert byq.isChecked()
    previews = [n for n in overlay_nodes() if "Preview" in n.getName().getString()]
    mat = [previews[0].getChild(i) for i in range(previews[0].getNumChildren()) if isinstance(previews[0].getChild(i), coin.SoMaterial)][0]
    assert mat.diffuseColor.getNum() == added, (mat.diffuseColor.getNum(), added)
    view.saveImage(h.shot("gui_meshfill_2b_preview_quality.png"), 1024, 768, "White")

    ok = None
    for bb in FreeCADGui.getMainWindow().findChildren(QtWidgets.QDialogButtonBox):
        b = bb.button(QtWidgets.QDialogButtonBox.Ok)
        if bb.isVisible() and b is not None and b.isVisible():
            ok = b
    assert ok is not None, "no OK button"
    QTest.mouseClick(ok, QtCore.Qt.LeftButton)
    h.pump(1000)
    assert not overlay_nodes(), "overlay left after OK"
    new = [o for o in doc.Objects if o.Name not in ("Scan",)]
    assert len(new) == 1 and new[0].isDerivedFrom("Mesh::Feature"), [o.Name for o in doc.Objects]
    filled = new[0]
    import json
    rep = json.loads(filled.HoleFillReport)
    assert rep["filled"] == 1 and rep["open"] == 1, rep
    assert [f["hole"] for f in rep["hole_fills"] if f["filled"]] == [0], rep["hole_fills"]
    assert rep["hole_fills"][0]["triangulation"] == "dihedral", rep["hole_fills"][0]  # a sphere: no crease
    assert (src.Mesh.CountPoints, src.Mesh.CountFacets, str(src.Mesh.BoundBox)) == before, "the source mesh changed"
    assert filled.Mesh.CountFacets > src.Mesh.CountFacets
    FreeCADGui.ActiveDocument.getObject(filled.Name).Visibility = True
    view.fitAll()
    h.pump(300)
    view.saveImage(h.shot("gui_meshfill_3_filled.png"), 1024, 768, "White")
    doc.undo()
    h.pump(300)
    assert len(doc.Objects) == count, [o.Name for o in doc.Objects]
    h.finish(True, filled_triangles=rep["hole_fills"][0]["new_triangles"], quality=rep["hole_fills"][0]["mean_quality"])


h.run(body, 500)
