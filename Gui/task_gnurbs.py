"""Task panel of "G-NURBS surface": the selected object's quad faces are the cage. The panel lists
the cage (vertices, quads, extraordinary points), lets the user mark sharp cage edges by clicking
them in the 3D view (a click toggles; they are drawn thick orange, extraordinary points red) and
place an anchor at any extraordinary point (checkbox and x, y, z; drawn blue), and on OK creates
the parametric G-NURBS object (HoleFill.makeGnurbs, one undo step), which follows the cage when it
changes. The cage object is never modified; Cancel leaves the document as it was."""
import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from HoleFillGui import SelectionError, scene_overlay, task_dialog

translate = FreeCAD.Qt.translate

OVERLAY = "HoleFillGnurbsCage"
COLOR_SHARP, COLOR_EP, COLOR_ANCHOR = (1.0, 0.55, 0.1), (0.9, 0.0, 0.0), (0.1, 0.3, 1.0)


def cage_from_selection():
    sel = FreeCADGui.Selection.getSelection()
    shaped = [o for o in sel if hasattr(o, "Shape") and not o.Shape.isNull() and o.Shape.Faces]
    if len(shaped) != 1:
        raise SelectionError("Select one quad cage: an object whose faces are quadrilaterals (a Part shell or compound, "
                             "or a cage imported with HoleFill → Import quad cage)."
                             + (" The selection holds no object with faces." if sel and not shaped else ""))
    return shaped[0]


def remove_overlay():
    scene_overlay.remove(OVERLAY)


class _EdgeClicks:
    """Selection observer: a click on an edge of the cage object toggles it sharp."""

    def __init__(self, panel):
        self.panel = panel

    def addSelection(self, doc, obj, sub, pnt):
        if obj == self.panel.obj.Name and sub.startswith("Edge"):
            QtCore.QTimer.singleShot(0, lambda: self.panel.toggle(sub))


class GnurbsPanel(task_dialog.Panel):
    overlay = OVERLAY

    def __init__(self, obj, sharpEdges=(), anchors=None, knots=()):
        import HoleFill
        self.obj = obj
        self.cage = HoleFill.cageFromShape(obj.Shape)  # raises with the face named when not all quads
        self.eps = HoleFill.extraordinaryPoints(self.cage)
        self.knots = list(knots)
        self.sharp = {(min(a, b), max(a, b)) for a, b in sharpEdges}
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("HoleFill", "G-NURBS surface"))
        layout = QtWidgets.QVBoxLayout(self.form)
        valences = ", ".join("%d (valence %d)" % (v, n) for v, n in sorted(self.eps.items())) or "none"
        self.summary = QtWidgets.QLabel(translate("HoleFill", "%s: %d vertices, %d quads. Extraordinary points: %s.") % (
            obj.Label, len(self.cage["vertices"]), len(self.cage["quads"]), valences))
        self.summary.setWordWrap(True)
        layout.addWidget(self.summary)
        layout.addWidget(QtWidgets.QLabel(translate("HoleFill", "Sharp edges: click cage edges in the 3D view to mark or unmark them.")))
        self.sharpList = QtWidgets.QListWidget()
        self.sharpList.setObjectName("HoleFillGnurbsSharp")
        layout.addWidget(self.sharpList)
        clear = QtWidgets.QPushButton(translate("HoleFill", "Clear sharp edges"))
        clear.setObjectName("HoleFillGnurbsClearSharp")
        clear.clicked.connect(self.clearSharp)
        layout.addWidget(clear)
        layout.addWidget(QtWidgets.QLabel(translate("HoleFill", "Anchors (V_EP = A_EP) at extraordinary points:")))
        self.anchors = QtWidgets.QTableWidget(len(self.eps), 4)
        self.anchors.setObjectName("HoleFillGnurbsAnchors")
        self.anchors.setHorizontalHeaderLabels([translate("HoleFill", "EP"), "x", "y", "z"])
        self.anchors.verticalHeader().setVisible(False)
        self.spins = {}
        anchors = anchors or {}
        for r, v in enumerate(sorted(self.eps)):
            item = QtWidgets.QTableWidgetItem(str(v))
            item.setFlags(QtCore.Qt.ItemIsUserCheckable | QtCore.Qt.ItemIsEnabled)
            item.setCheckState(QtCore.Qt.Checked if v in anchors else QtCore.Qt.Unchecked)
            self.anchors.setItem(r, 0, item)
            at = anchors.get(v, self.cage["vertices"][v])
            spins = []
            for c in range(3):
                spin = QtWidgets.QDoubleSpinBox()
                spin.setRange(-1e9, 1e9)
                spin.setDecimals(6)
                spin.setValue(float(at[c]))
                spin.setKeyboardTracking(False)  # typed values redraw when complete, not per keystroke
                spin.valueChanged.connect(lambda *_: self.redraw())
                self.anchors.setCellWidget(r, 1 + c, spin)
                spins.append(spin)
            self.spins[v] = spins
        self.anchors.itemChanged.connect(lambda *_: self.redraw())
        layout.addWidget(self.anchors)
        self.refine = QtWidgets.QCheckBox(translate("HoleFill", "Refine the cage once when its extraordinary points are too close"))
        self.refine.setObjectName("HoleFillGnurbsRefine")
        self.refine.setChecked(True)
        layout.addWidget(self.refine)
        self.status = QtWidgets.QLabel()
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        self.observer = _EdgeClicks(self)
        FreeCADGui.Selection.addObserver(self.observer)
        FreeCADGui.Selection.clearSelection()
        self.redraw()

    # -- state -------------------------------------------------------------------------------
    def toggle(self, edgeName):
        e = self.cage["shapeEdges"].get(edgeName)
        FreeCADGui.Selection.clearSelection()  # the next click on the same edge toggles it back
        if e is None:
            return
        self.sharp.symmetric_difference_update({e})
        self.redraw()

    def clearSharp(self):
        self.sharp.clear()
        self.redraw()

    def anchorValues(self):
        out = {}
        for r, v in enumerate(sorted(self.eps)):
            if self.anchors.item(r, 0).checkState() == QtCore.Qt.Checked:
                out[v] = tuple(s.value() for s in self.spins[v])
        return out

    # -- drawing -----------------------------------------------------------------------------
    def redraw(self):
        from pivy import coin
        remove_overlay()
        self.sharpList.clear()
        for a, b in sorted(self.sharp):
            self.sharpList.addItem("%d-%d" % (a, b))
        pts = self.cage["vertices"]
        # The cage's vertices come from its shape, which holds its Placement already.
        root = scene_overlay.placed_root("%s_%s" % (OVERLAY, self.obj.Name), scene_overlay.shape_placement(self.obj))
        if self.sharp:
            sep = coin.SoSeparator()
            sep.setName(OVERLAY + "_sharp")
            col = coin.SoBaseColor()
            col.rgb.setValue(*COLOR_SHARP)
            style = coin.SoDrawStyle()
            style.lineWidth = 5
            coords = coin.SoCoordinate3()
            flat = [list(pts[i]) for e in sorted(self.sharp) for i in e]
            coords.point.setValues(0, len(flat), flat)
            lines = coin.SoLineSet()
            lines.numVertices.setValues(0, len(self.sharp), [2] * len(self.sharp))
            for n in (col, style, coords, lines):
                sep.addChild(n)
            root.addChild(sep)
        anchors = self.anchorValues()
        for name, color, where in (("eps", COLOR_EP, [pts[v] for v in sorted(self.eps)]),
                                   ("anchors", COLOR_ANCHOR, list(anchors.values()))):
            if not where:
                continue
            sep = coin.SoSeparator()
            sep.setName("%s_%s" % (OVERLAY, name))
            col = coin.SoBaseColor()
            col.rgb.setValue(*color)
            style = coin.SoDrawStyle()
            style.pointSize = 10
            coords = coin.SoCoordinate3()
            coords.point.setValues(0, len(where), [list(p) for p in where])
            for n in (col, style, coords, coin.SoPointSet()):
                sep.addChild(n)
            root.addChild(sep)
        scene_overlay.show(root)
        self.status.setText(translate("HoleFill", "%d sharp edges, %d anchors. OK builds the G² surface as a new object.") % (len(self.sharp), len(anchors)))

    # -- dialog (task_dialog.Panel) --------------------------------------------------------------
    def release(self):
        FreeCADGui.Selection.removeObserver(self.observer)
        task_dialog.Panel.release(self)

    def make(self):
        import HoleFill
        return HoleFill.makeGnurbs(self.obj, sharpEdges=sorted(self.sharp), anchors=self.anchorValues(), refine=self.refine.isChecked(),
                                   knots=self.knots)

    def made(self, obj):
        import json
        rep = json.loads(obj.Report)
        self.obj.ViewObject.Visibility = False
        return ("HoleFill: G-NURBS surface %s over %s: %d B-rep faces, %d extraordinary points, spokes G1 %.1e rad G2 %.1e, %.3f s%s" % (
            obj.Label, self.obj.Label, rep["brep"]["faces"], len(rep["extraordinary_points"]), rep["continuity"]["g1_spokes"],
            rep["continuity"]["g2_spokes"], rep["seconds"], "".join("\n  warning: " + w for w in rep["warnings"])))
