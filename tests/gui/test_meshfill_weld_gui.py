"""GUI test of "Fill mesh holes" on a mesh with a seam of duplicated vertices (as an exporter
writes a texture seam, CGAL's elephant-with-holes): a sphere with one hole whose two halves share
no vertex. Selected by a real click; the panel lists the one real hole (the seam's two sides are
paired, no hole) and offers "Merge coincident vertices first" with the count of copies; Preview
as it is says the result stays open by index along the seam and that the merge closes it; a real
click on the merge and Preview again: closed; OK makes a closed, manifold mesh with the copies
merged; the source mesh is untouched. Screenshots are saved."""
import math

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import guiharness as h


def seamed_sphere():
    """A sphere of radius 5 with its top cap removed, the facets with y > 0 on copies of their vertices."""
    import Mesh
    m = Mesh.createSphere(5.0, 50)
    pts, fac = m.Topology
    m.removeFacets([i for i, f in enumerate(fac) if sum(pts[k].z for k in f) / 3 > 5 * math.cos(0.5)])
    pts, fac = m.Topology
    lower = {k for f in fac if sum(pts[i].y for i in f) / 3 <= 0 for k in f}
    points, copy, facets = list(pts), {}, []
    for f in fac:
        if sum(pts[k].y for k in f) / 3 > 0:
            for k in f:
                if k in lower and k not in copy:  # a vertex both halves use: the upper half gets a copy
                    copy[k] = len(points)
                    points.append(pts[k])
            f = tuple(copy.get(k, k) for k in f)
        facets.append(tuple(f))
    return Mesh.Mesh((points, facets)), len(copy)


def body():
    import HoleFill
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc = FreeCAD.newDocument("GuiMeshWeld")
    src = doc.addObject("Mesh::Feature", "Scan")
    mesh, copies = seamed_sphere()
    src.Mesh = mesh
    doc.recompute()
    assert src.Mesh.CountPoints == mesh.CountPoints, "FreeCAD merged the seam's copies itself"
    before = (src.Mesh.CountPoints, src.Mesh.CountFacets, str(src.Mesh.BoundBox))
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewFront()
    view.fitAll()
    h.pump(500)
    FreeCADGui.Selection.clearSelection()
    h.click_at(view, FreeCAD.Vector(0, -5, 0))
    assert [o.Name for o in FreeCADGui.Selection.getSelection()] == ["Scan"]
    count = len(doc.Objects)

    FreeCADGui.runCommand("HoleFill_FillMeshHoles")
    h.pump(800)
    h.assert_panel_fits()
    mw = FreeCADGui.getMainWindow()
    table = mw.findChild(QtWidgets.QTableWidget, "HoleFillMeshHoleTable")
    weld = mw.findChild(QtWidgets.QCheckBox, "HoleFillMeshWeld")
    assert weld is not None and weld.isEnabled() and not weld.isChecked(), "the merge is not offered"
    assert "(%d)" % copies in weld.text(), (weld.text(), copies)
    rows_before = table.rowCount()
    assert rows_before == 1, "the seam is no hole: %d rows" % rows_before
    view.viewIsometric()
    view.fitAll()
    h.pump(300)
    view.saveImage(h.shot("gui_meshweld_1_seam_holes.png"), 1024, 768, "White")
    label = mw.findChild(QtWidgets.QLabel, "HoleFillMeshStatus")
    h.click_button(mw.findChild(QtWidgets.QPushButton, "HoleFillMeshPreview"))
    h.wait_for(lambda: label.text().startswith("Preview"))
    assert "still open" in label.text() and "check 'Merge coincident vertices first'" in label.text(), label.text()

    h.click_button(weld)
    h.pump(500)
    assert weld.isChecked()
    assert table.rowCount() == 1, table.rowCount()
    assert len(HoleFill.meshHoles(src.Mesh, weld=HoleFill.SEAM_WELD)) == 1
    assert not label.text().startswith("Preview"), label.text()  # the holes were listed again: the last Preview is gone
    h.click_button(mw.findChild(QtWidgets.QPushButton, "HoleFillMeshPreview"))
    h.wait_for(lambda: label.text().startswith("Preview") and "still open" not in label.text())
    assert "1 of 1 checked holes filled" in label.text() and "The result is closed." in label.text(), label.text()
    assert len(doc.Objects) == count, "a Preview added to the document"
    view.saveImage(h.shot("gui_meshweld_2_preview.png"), 1024, 768, "White")

    h.click_button(h.task_ok_button())
    h.pump(1000)
    new = [o for o in doc.Objects if o.Name != "Scan"]
    assert len(new) == 1 and new[0].isDerivedFrom("Mesh::Feature"), [o.Name for o in doc.Objects]
    import json
    rep = json.loads(new[0].HoleFillReport)
    assert rep["closed"] and rep["welded_vertices"] == copies, rep
    filled = new[0].Mesh
    assert filled.isSolid() and not filled.hasNonManifolds(), "the filled, merged mesh is not closed and manifold"
    assert filled.CountPoints == src.Mesh.CountPoints - copies + rep["hole_fills"][0]["new_vertices"]
    assert (src.Mesh.CountPoints, src.Mesh.CountFacets, str(src.Mesh.BoundBox)) == before, "the source mesh changed"
    FreeCADGui.ActiveDocument.getObject(new[0].Name).Visibility = True
    view.fitAll()
    h.pump(300)
    view.saveImage(h.shot("gui_meshweld_3_filled.png"), 1024, 768, "White")
    h.finish(True, seam_holes=rows_before, copies=copies, new_triangles=rep["hole_fills"][0]["new_triangles"])


h.run(body, 300)
