"""GUI test: the inspection commands on a real fill in the real FreeCAD. Curvature map (quantity
changed in the panel, legend numbers, toggle off), zebra stripes (stripes present, they follow a
camera change, Cancel removes them), continuity check on a Fill object and on two adjacent faces,
an overlay following a recompute, and bad selections (nothing, a mesh, an edge only) answered
with a clear message. Overlay nodes are asserted in the scene graph, screenshots are saved and
checked not to be blank; the document is never modified by any of it."""
import json

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import guiharness as h

PREFIX = "HoleFillInspect"


def overlays(kind=""):
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    return [root.getChild(i) for i in range(root.getNumChildren())
            if root.getChild(i).getName().getString().startswith(PREFIX + "_" + kind)]


def pixels(path):
    """(share of non-background pixels, share dark, share light, share saturated) of a screenshot."""
    from PySide2 import QtGui
    img = QtGui.QImage(path)
    assert not img.isNull(), path
    n = cov = dark = light = sat = 0
    for y in range(0, img.height(), 3):
        for x in range(0, img.width(), 3):
            c = QtGui.QColor(img.pixel(x, y))
            r, g, b = c.red(), c.green(), c.blue()
            n += 1
            if (r, g, b) == (255, 255, 255):
                continue
            cov += 1
            dark += r + g + b < 150
            light += r + g + b > 600
            sat += max(r, g, b) - min(r, g, b) > 80
    return cov / n, dark / n, light / n, sat / n


def striped_shot(view, name):
    """Saves the view as `name` and asserts it shows stripes (dark and light pixels); returns
    (share covered, share dark, share light)."""
    view.saveImage(h.shot(name), 1024, 768, "White")
    cov, dark, light, sat = pixels(h.shot(name))
    assert dark > 0.05 and light > 0.05, (dark, light)
    return cov, dark, light


def button(which):
    for box in FreeCADGui.getMainWindow().findChildren(QtWidgets.QDialogButtonBox):
        b = box.button(which)
        if box.isVisible() and b is not None and b.isVisible():
            return b
    return None


def comb_lengths(node):
    """{"face"|"support": [tooth length, ...]} read back from the combs overlay's line sets."""
    import math
    from pivy import coin
    out = {}
    for i in range(node.getNumChildren()):
        part = node.getChild(i)
        name = part.getName().getString()
        if not name.startswith("HoleFillInspect_Combs_"):
            continue
        coords = [part.getChild(k) for k in range(part.getNumChildren()) if isinstance(part.getChild(k), coin.SoCoordinate3)][0]
        lines = [part.getChild(k) for k in range(part.getNumChildren()) if isinstance(part.getChild(k), coin.SoLineSet)][0]
        pts = [coords.point[k].getValue() for k in range(coords.point.getNum())]
        teeth, at = [], 0
        for k in range(lines.numVertices.getNum()):
            n = lines.numVertices[k]
            if n == 2:
                teeth.append(math.dist(pts[at], pts[at + 1]))
            at += n
        out[name.rsplit("_", 1)[1]] = teeth
    return out


def body():
    import HoleFill
    import Mesh
    FreeCADGui.activateWorkbench("HoleFillWorkbench")
    h.pump(300)
    doc, src = h.sample_document("GuiInspect", "Corner", "filleted_box_corner")
    fill = HoleFill.makeFill(src, None, method="auto", continuity="G1")
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    h.pump(500)
    def shapes():  # geometry, not identity: the recompute test below moves the source and back
        return {o.Name: (round(o.Shape.Area, 6), str(o.Shape.BoundBox), len(o.Shape.Faces))
                for o in doc.Objects if hasattr(o, "Shape")}
    shapes_before = shapes()
    info = {}

    # 1. Curvature map on the source and the fill (whole objects), then Gaussian, then toggle off.
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(src)
    FreeCADGui.Selection.addSelection(fill)
    FreeCADGui.runCommand("HoleFill_CurvatureMap")
    h.pump(1500)
    h.assert_panel_fits()
    assert len(overlays("Curvature")) == 2, [n.getName().getString() for n in overlays()]
    mw = FreeCADGui.getMainWindow()
    combo = [c for c in mw.findChildren(QtWidgets.QComboBox) if c.isVisible() and c.findText("Gaussian curvature") >= 0][0]
    combo.setCurrentIndex(combo.findText("Gaussian curvature"))
    h.pump(1500)
    labels = " ".join(w.text() for w in mw.findChildren(QtWidgets.QLabel) if w.isVisible())
    assert "gauss from" in labels, labels
    view.saveImage(h.shot("gui_inspect_1_curvature.png"), 1024, 768, "White")
    cov, dark, light, sat = pixels(h.shot("gui_inspect_1_curvature.png"))
    info["curvature_pixels"] = (cov, sat)
    assert cov > 0.1 and sat > 0.005, (cov, sat)  # coloured (red corner spheres on neutral grey), not blank
    button(QtWidgets.QDialogButtonBox.Ok).click()
    h.pump(500)
    assert len(overlays("Curvature")) == 2, "OK must keep the map in the view"
    # The overlay follows a recompute: move the source, its map moves with it.
    first = overlays("Curvature_Corner")[0]
    before = [c for c in (first.getChild(i) for i in range(first.getNumChildren())) if c.isOfType(
        __import__("pivy").coin.SoCoordinate3.getClassTypeId())][0].point[0][0]
    src.Placement.Base = FreeCAD.Vector(5, 0, 0)
    doc.recompute()
    h.pump(1500)
    node = overlays("Curvature_Corner")[0]
    after = [c for c in (node.getChild(i) for i in range(node.getNumChildren())) if c.isOfType(
        __import__("pivy").coin.SoCoordinate3.getClassTypeId())][0].point[0][0]
    info["recompute_shift"] = after - before
    assert abs(after - before - 5.0) < 1e-3, (before, after)
    src.Placement.Base = FreeCAD.Vector(0, 0, 0)
    doc.recompute()
    h.pump(1000)
    FreeCADGui.runCommand("HoleFill_CurvatureMap")  # toggle off
    h.pump(300)
    assert not overlays("Curvature"), "the curvature map survived its toggle"

    # 2. Zebra on the source and the fill: stripes, following the camera; Cancel removes them.
    FreeCADGui.runCommand("HoleFill_ZebraStripes")
    h.pump(1500)
    assert len(overlays("Zebra")) == 2
    info["zebra_pixels"] = striped_shot(view, "gui_inspect_2_zebra_iso.png")
    view.viewTop()
    h.pump(500)
    view.saveImage(h.shot("gui_inspect_3_zebra_top.png"), 1024, 768, "White")
    from PySide2 import QtGui
    a, b = QtGui.QImage(h.shot("gui_inspect_2_zebra_iso.png")), QtGui.QImage(h.shot("gui_inspect_3_zebra_top.png"))
    assert a != b, "the stripes did not change with the view"
    view.viewIsometric()
    # A count typed with real keys redraws once, when complete (Tab to the next field; Enter is
    # the panel's OK), not per keystroke.
    import subprocess
    from HoleFillGui import inspection_overlay as zebra_overlay
    drawn, real_show = [], zebra_overlay.show_zebra

    def counting_show(*args, **kwargs):
        drawn.append(kwargs.get("count"))
        return real_show(*args, **kwargs)

    zebra_overlay.show_zebra = counting_show
    try:
        spin = [w for w in FreeCADGui.getMainWindow().findChildren(QtWidgets.QSpinBox) if w.isVisible() and w.maximum() == 200][0]
        g = spin.mapToGlobal(spin.rect().center())
        subprocess.run(["xdotool", "mousemove", str(g.x()), str(g.y())], check=True)
        h.pump(200)
        subprocess.run(["xdotool", "click", "1"], check=True)
        h.pump(200)
        subprocess.run(["xdotool", "key", "ctrl+a"], check=True)
        subprocess.run(["xdotool", "type", "--delay", "80", "120"], check=True)
        h.pump(600)
        assert drawn == [], "the stripes were redrawn while typing: %s" % drawn
        subprocess.run(["xdotool", "key", "Tab"], check=True)
        h.pump(1500)
        assert spin.value() == 120 and drawn and set(drawn) == {120} and len(drawn) == 2, (spin.value(), drawn)
    finally:
        zebra_overlay.show_zebra = real_show
    button(QtWidgets.QDialogButtonBox.Cancel).click()
    h.pump(500)
    assert not overlays("Zebra"), "Cancel left the zebra overlay"

    # 2b. The same with Preferences → Zebra stripes drawn by: vertex (OpenGL without shaders): no
    # shader in the overlay, per-vertex greys that change when the camera turns; Cancel removes them.
    from pivy import coin
    from HoleFill import preferences
    from HoleFillGui import inspection_overlay
    preferences.put("ZebraRenderer", "vertex")
    try:
        FreeCADGui.runCommand("HoleFill_ZebraStripes")
        h.pump(1500)
        assert len(overlays("Zebra")) == 2
        node = overlays("Zebra_Fill")[0]
        kids = [node.getChild(i) for i in range(node.getNumChildren())]
        assert not [k for k in kids if k.isOfType(coin.SoShaderProgram.getClassTypeId())], "vertex zebra has a shader"
        mat = [k for k in kids if k.isOfType(coin.SoMaterial.getClassTypeId())][0]
        coords = [k for k in kids if k.isOfType(coin.SoCoordinate3.getClassTypeId())][0]
        assert mat.diffuseColor.getNum() == coords.point.getNum() > 100, (mat.diffuseColor.getNum(), coords.point.getNum())
        greys = [mat.diffuseColor[i][0] for i in range(mat.diffuseColor.getNum())]
        info["vertex_zebra_light_share"] = sum(g > 0.5 for g in greys) / len(greys)
        assert 0.05 < info["vertex_zebra_light_share"] < 0.95, info["vertex_zebra_light_share"]
        info["vertex_zebra_pixels"] = striped_shot(view, "gui_inspect_2b_zebra_vertex_iso.png")
        view.viewTop()
        h.pump(500)
        turned = [mat.diffuseColor[i][0] for i in range(mat.diffuseColor.getNum())]
        changed = sum(abs(a - b) > 0.3 for a, b in zip(greys, turned)) / len(greys)
        info["vertex_zebra_changed_with_view"] = changed
        assert changed > 0.05, "the per-vertex stripes did not follow the camera"
        view.saveImage(h.shot("gui_inspect_2b_zebra_vertex_top.png"), 1024, 768, "White")
        view.viewIsometric()
        button(QtWidgets.QDialogButtonBox.Cancel).click()
        h.pump(500)
        assert not overlays("Zebra"), "Cancel left the vertex zebra overlay"
        assert not inspection_overlay._VERTEX_ZEBRAS, "a removed vertex zebra still watches the camera"
    finally:
        preferences.reset()

    # 2c. Zebra with nothing selected: stripes on every visible object (the source and the fill),
    # to judge the fill with its neighbours without selecting them.
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand("HoleFill_ZebraStripes")
    h.pump(1500)
    assert len(overlays("Zebra")) == 2, [n.getName().getString() for n in overlays()]
    button(QtWidgets.QDialogButtonBox.Cancel).click()
    h.pump(500)
    assert not overlays("Zebra")

    # 3. Continuity check on the Fill object: a panel with numbers and a coloured boundary.
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(fill)
    FreeCADGui.runCommand("HoleFill_ContinuityCheck")
    h.pump(1500)
    h.assert_panel_fits()
    assert len(overlays("Continuity")) == 1
    table = [t for t in mw.findChildren(QtWidgets.QTableWidget) if t.isVisible()][0]
    info["fill_g1"] = table.item(0, 2).text()
    assert float(table.item(0, 2).text()) <= 1e-3, table.item(0, 2).text()  # the G1 fill is G1
    # One G0 per edge in every panel: the check shows the Fill's own numbers.
    own = {"Edge%d" % e["edge"]: "%.3g" % e["g0"] for e in json.loads(fill.Report)["per_edge"]}
    shown = {table.item(r, 0).text(): table.item(r, 1).text() for r in range(1, table.rowCount())}
    assert shown == own, (shown, own)
    view.saveImage(h.shot("gui_inspect_4_continuity_fill.png"), 1024, 768, "White")
    assert pixels(h.shot("gui_inspect_4_continuity_fill.png"))[3] > 0.001
    # The boundary's colours are none that FreeCAD uses for preselection or selection (a G1
    # boundary in yellow was taken for a preselected edge).
    from pivy import coin as _coin
    mats = _coin.SoSearchAction()
    mats.setType(_coin.SoMaterial.getClassTypeId())
    mats.setInterest(_coin.SoSearchAction.ALL)
    mats.apply(overlays("Continuity")[0])
    drawn = {tuple(round(c, 2) for c in m.getTail().diffuseColor[k].getValue())
             for m in [mats.getPaths()[i] for i in range(mats.getPaths().getLength())] for k in range(m.getTail().diffuseColor.getNum())}
    params = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/View")
    for name, default in (("HighlightColor", 3789624575), ("SelectionColor", 481107199)):
        packed = params.GetUnsigned(name, default)
        theirs = tuple(round(((packed >> shift) & 255) / 255.0, 2) for shift in (24, 16, 8))
        assert all(sum(abs(a - b) for a, b in zip(c, theirs)) > 0.3 for c in drawn), (name, theirs, drawn)
    info["continuity_colours"] = sorted(drawn)
    # Curvature combs along the boundary (a real click): the fill's and its neighbours'.
    combs = mw.findChild(QtWidgets.QCheckBox, "HoleFillCombs")
    h.click_button(combs)
    h.pump(500)
    assert combs.isChecked() and len(overlays("Combs")) == 1
    lengths = comb_lengths(overlays("Combs")[0])
    # The corner's neighbours are flat across its edges (planes, fillets across their axis): their
    # teeth have no length, the fill's bend away from its rim.
    assert set(lengths) == {"face", "support"} and max(lengths["face"]) > 0 and max(lengths["support"]) < 1e-9, \
        {k: max(v) for k, v in lengths.items()}
    info["fill_comb_teeth"] = len(lengths["face"])
    FreeCADGui.SendMsgToActiveView("ViewSelection")  # the fill is selected: its combs close up
    h.pump(500)
    view.saveImage(h.shot("gui_inspect_4b_combs_fill.png"), 1024, 768, "White")
    view.fitAll()
    button(QtWidgets.QDialogButtonBox.Close).click()
    h.pump(500)
    assert not overlays("Continuity") and not overlays("Combs")
    # ... and on two adjacent faces of the source: a plane against a fillet is G1, not G2.
    import Part
    shape = src.Shape
    pair = None
    for i, f in enumerate(shape.Faces):
        for j, g in enumerate(shape.Faces):
            if i < j and f.Surface.TypeId != g.Surface.TypeId and any(e.isSame(k) for e in f.Edges for k in g.Edges):
                pair = ("Face%d" % (i + 1), "Face%d" % (j + 1))
                break
        if pair:
            break
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(src, list(pair))
    FreeCADGui.runCommand("HoleFill_ContinuityCheck")
    h.pump(1000)
    table = [t for t in mw.findChildren(QtWidgets.QTableWidget) if t.isVisible()][0]
    info["pair"] = pair
    info["pair_g1_g2"] = (table.item(0, 2).text(), table.item(0, 3).text())
    assert float(table.item(0, 2).text()) < 1e-6 and float(table.item(0, 3).text()) > 0.1, info["pair_g1_g2"]
    # Its combs: one side's teeth are all of one length (the fillet's constant curvature across),
    # the other's zero (the plane): what "G1, not G2" looks like.
    h.click_button(mw.findChild(QtWidgets.QCheckBox, "HoleFillCombs"))
    h.pump(500)
    lengths = comb_lengths(overlays("Combs")[0])
    longest = {k: max(v) for k, v in lengths.items()}
    flat, round_ = sorted(longest, key=longest.get)
    assert longest[flat] < 1e-9 * longest[round_], longest
    assert max(lengths[round_]) - min(lengths[round_]) < 1e-6 * longest[round_], lengths[round_][:5]
    legend = mw.findChild(QtWidgets.QLabel, "HoleFillCombsLegend")
    assert "curvature of" in legend.text(), legend.text()
    info["pair_combs"] = longest
    view.saveImage(h.shot("gui_inspect_4c_combs_pair.png"), 1024, 768, "White")
    button(QtWidgets.QDialogButtonBox.Close).click()
    h.pump(300)

    # 4. Bad selections: a clear message, no overlay, no panel.
    FreeCADGui.Selection.clearSelection()
    info["msg_none"] = h.run_expecting_message("HoleFill_CurvatureMap")
    assert "Select faces" in info["msg_none"], info["msg_none"]
    mesh = doc.addObject("Mesh::Feature", "Scan")
    mesh.Mesh = Mesh.Mesh(Part.makeBox(1, 1, 1).tessellate(0.1))
    doc.recompute()
    FreeCADGui.Selection.addSelection(mesh)
    info["msg_mesh"] = h.run_expecting_message("HoleFill_ZebraStripes")
    assert "is a mesh" in info["msg_mesh"], info["msg_mesh"]
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(src, "Edge1")
    info["msg_edge"] = h.run_expecting_message("HoleFill_CurvatureMap")
    assert "Only edges" in info["msg_edge"], info["msg_edge"]
    info["msg_cont"] = h.run_expecting_message("HoleFill_ContinuityCheck")
    assert "two adjacent faces" in info["msg_cont"], info["msg_cont"]
    assert not overlays(), [n.getName().getString() for n in overlays()]
    doc.removeObject("Scan")
    doc.recompute()
    assert shapes() == shapes_before, (shapes(), shapes_before)
    h.finish(True, **info)


h.run(body, 500)
