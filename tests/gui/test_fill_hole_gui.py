"""GUI test: activate HoleFill, click one edge of a hole with the real mouse (xdotool),
run "Fill hole", Preview (an overlay; nothing added to the document), Preview again with
another continuity, press OK in the task panel, and check the Fill object: the hole was read
and found once for both Previews and OK, and OK's fill was the last Preview's, not solved again;
screenshots saved."""
import json
import subprocess

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import guiharness as h


def overlay_present(name):
    from pivy import coin  # noqa: F401 (FreeCAD 1.0 wraps the scene graph only once pivy is loaded)
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    return any(root.getChild(i).getName().getString() == name for i in range(root.getNumChildren()))


def body():
    import HoleFill
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    assert FreeCADGui.activeWorkbench().name() == "HoleFillWorkbench"
    doc, src = h.sample_document("GuiFill", "Panel", "panel_6_sided")
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewTop()
    view.fitAll()
    h.pump(500)
    hole = HoleFill.findHoles(src.Shape)[0]
    name, x, y = h.visible_hole_edge(view, src, hole.edges)
    assert name, "no hole edge visible at its midpoint"
    h.log("clicking %s at %d,%d" % (name, x, y))
    FreeCADGui.Selection.clearSelection()
    subprocess.run(["xdotool", "mousemove", str(x), str(y)], check=True)
    h.pump(300)
    subprocess.run(["xdotool", "click", "1"], check=True)
    h.pump(500)
    sel = FreeCADGui.Selection.getSelectionEx()
    picked = [n for s in sel for n in s.SubElementNames]
    assert picked == [name], "selection after the click: %s" % picked
    view.saveImage(h.shot("gui_fill_1_selected.png"), 1024, 768, "White")

    # Count what crosses into the core: holes read and found, and fills solved.
    calls = {"prepare": 0, "solve": 0}
    real_prepare = HoleFill.prepareHole

    def counting_prepare(shape, hole=1):
        calls["prepare"] += 1
        p = real_prepare(shape, hole)
        inner = p._prepared

        class Counting:
            def fill(self, *args):
                calls["solve"] += 1
                return inner.fill(*args)

            def computed(self):
                return inner.computed()

        p._prepared = Counting()
        return p

    HoleFill.prepareHole = counting_prepare
    FreeCADGui.runCommand("HoleFill_FillHole")
    h.pump(800)
    h.assert_panel_fits()
    # Press the task panel's OK button, as a user would.
    mw = FreeCADGui.getMainWindow()
    oks = [b for box in mw.findChildren(QtWidgets.QDialogButtonBox) if box.isVisible()
           for b in [box.button(QtWidgets.QDialogButtonBox.Ok)] if b is not None and b.isVisible()]
    assert oks, "the Fill hole task panel did not open"
    labels = [w.text() for w in mw.findChildren(QtWidgets.QLabel) if w.isVisible() and "hole" in w.text()]
    h.log("task panel: %s" % labels)
    assert any("6-sided hole" in t for t in labels), labels
    # The edge list: one row per loop edge, each with its Ask column; ask G0 of the clicked edge.
    tables = [t for t in mw.findChildren(QtWidgets.QTableWidget) if t.isVisible() and t.columnCount() == 3]
    assert tables and tables[0].rowCount() == 6, [t.rowCount() for t in tables]
    table = tables[0]
    rows = {table.item(r, 0).text(): r for r in range(table.rowCount())}
    assert set(rows) == set(hole.edges), rows
    table.cellWidget(rows[name], 1).setCurrentText("G0")
    h.pump(200)
    # Preview, change the continuity, Preview again: a view-only overlay, nothing in the document;
    # the second Preview reuses the hole the first one read (issue 20: the precompute/solve split).
    previews = [b for b in mw.findChildren(QtWidgets.QPushButton) if b.isVisible() and b.text() == "Preview"]
    assert len(previews) == 1, [b.text() for b in mw.findChildren(QtWidgets.QPushButton) if b.isVisible()]
    h.click_button(previews[0])
    h.pump(1500)
    assert not [o for o in doc.Objects if o.Name.startswith("Fill")], "a Preview added to the document"
    assert overlay_present("HoleFillFillPreview"), "no preview overlay"
    combos = [c for c in mw.findChildren(QtWidgets.QComboBox)
              if c.isVisible() and not table.isAncestorOf(c) and c.findText("G2") >= 0]
    assert len(combos) == 1, len(combos)
    combos[0].setCurrentText("G2")
    h.pump(200)
    h.click_button(previews[0])
    h.pump(3000)
    reports = [w.toPlainText() for w in mw.findChildren(QtWidgets.QPlainTextEdit) if w.isVisible()]
    assert any("Requested G2" in t for t in reports), reports
    assert calls == {"prepare": 1, "solve": 2}, calls
    h.log("two Previews, one prepared hole: %s" % (calls,))
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_fill_1c_preview.png"))
    combos[0].setCurrentText("G1")
    h.pump(200)
    mw.grab().save(h.shot("gui_fill_1b_panel.png"))
    oks[0].click()
    h.pump(3000)
    fills = [o for o in doc.Objects if o.Name.startswith("Fill")]
    assert len(fills) == 1, [o.Name for o in doc.Objects]
    fill = fills[0]
    HoleFill.prepareHole = real_prepare
    # OK: settings changed since the last Preview (G1 again), so one more solve, seen as a Preview;
    # the Fill object took that prepared hole and that fill as they were.
    assert calls == {"prepare": 1, "solve": 3}, calls
    assert not overlay_present("HoleFillFillPreview"), "the preview overlay outlived the panel"
    assert fill.isValid() and fill.Shape.isValid(), fill.getStatusString()
    assert fill.Status == "ok" and fill.G1 <= 1e-3, (fill.Status, fill.G1)
    assert sorted(fill.Source[1]) == [name]
    assert list(fill.EdgeContinuity) == ["%s=G0" % name], fill.EdgeContinuity
    per = {"Edge%d" % e["edge"]: e for e in json.loads(fill.Report)["edge_continuity"]}
    assert per[name]["asked"] == "G0" and per[name]["source"] == "override", per[name]
    assert all(e["asked"] == "G1" for n, e in per.items() if n != name), per
    assert src.Shape.isValid() and len(src.Shape.Faces) == 1  # the source is untouched
    # Undo removes the fill in one step (it was one transaction).
    view.viewIsometric()
    view.fitAll()
    h.pump(500)
    view.saveImage(h.shot("gui_fill_2_filled.png"), 1024, 768, "White")
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_fill_3_screen.png"))
    # The fill's poles and control net on request (the view property ShowControlPoints), as many
    # points as the surface has poles; off again, none.
    from pivy import coin
    surf = fill.Shape.Faces[0].Surface
    fill.ViewObject.ShowControlPoints = True
    h.pump(300)
    search = coin.SoSearchAction()
    search.setName("HoleFillPoles")
    search.apply(fill.ViewObject.RootNode)
    node = search.getPath().getTail()
    coords = [node.getChild(i) for i in range(node.getNumChildren()) if isinstance(node.getChild(i), coin.SoCoordinate3)]
    assert coords and coords[0].point.getNum() == surf.NbUPoles * surf.NbVPoles, (coords, surf.NbUPoles, surf.NbVPoles)
    view.saveImage(h.shot("gui_fill_4_poles.png"), 1024, 768, "White")
    fill.ViewObject.ShowControlPoints = False
    h.pump(200)
    assert node.getNumChildren() == 0
    # Its knot lines on the face (ShowIsocurves): one or more stretches per interior knot that
    # crosses the trimmed face, every drawn point on the face.
    import Part
    fill.ViewObject.ShowIsocurves = True
    h.pump(300)
    search = coin.SoSearchAction()
    search.setName("HoleFillIsocurves")
    search.apply(fill.ViewObject.RootNode)
    iso = search.getPath().getTail()
    coords = [iso.getChild(i) for i in range(iso.getNumChildren()) if isinstance(iso.getChild(i), coin.SoCoordinate3)][0]
    lines = [iso.getChild(i) for i in range(iso.getNumChildren()) if isinstance(iso.getChild(i), coin.SoLineSet)][0]
    knots = len(surf.getUKnots()) + len(surf.getVKnots()) - 4
    assert knots > 0 and lines.numVertices.getNum() >= 1, (knots, lines.numVertices.getNum())
    face = fill.Shape.Faces[0]
    pts = [FreeCAD.Vector(*coords.point[i].getValue()) for i in range(0, coords.point.getNum(), 7)]
    worst = max(face.distToShape(Part.Vertex(fill.Placement.multVec(p)))[0] for p in pts)
    assert worst < 1e-3 * face.BoundBox.DiagonalLength, worst
    view.saveImage(h.shot("gui_fill_4b_isocurves.png"), 1024, 768, "White")
    fill.ViewObject.ShowIsocurves = False
    h.pump(200)
    assert iso.getNumChildren() == 0
    doc.undo()
    h.pump(300)
    assert not [o for o in doc.Objects if o.Name.startswith("Fill")], "undo did not remove the fill"
    h.finish(True, clicked=name, g0=fill.G0, g1=fill.G1)


h.run(body, 500)
