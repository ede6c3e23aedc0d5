"""Task panels of the inspection commands: Curvature map, Zebra stripes, Continuity check.
Each applies its overlay (inspection_overlay) to the selection at once and again on every
change; OK keeps the overlay in the view, Cancel removes it. Running the command again
while its overlay is shown removes it (toggle)."""
import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtGui, QtWidgets

from HoleFill import preferences
from HoleFillGui import inspection_overlay as overlay

translate = FreeCAD.Qt.translate


def _message(text):
    FreeCAD.Console.PrintError("HoleFill: %s\n" % text)
    if FreeCAD.GuiUp and not getattr(FreeCADGui, "HoleFillQuiet", False):
        QtWidgets.QMessageBox.warning(FreeCADGui.getMainWindow(), translate("HoleFill", "HoleFill"), text)


class _Panel:
    kind = None

    def __init__(self, targets):
        self.targets = targets
        self.meshes = {}
        self.form = QtWidgets.QWidget()
        self.layout = QtWidgets.QFormLayout(self.form)
        self.status = QtWidgets.QLabel()
        self.status.setWordWrap(True)

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

    def accept(self):
        FreeCADGui.Control.closeDialog()
        return True

    def reject(self):
        overlay.remove(self.kind)
        FreeCADGui.Control.closeDialog()
        return True

    def apply(self):
        QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            lines = []
            for obj, faces in self.targets:
                lines.append(self.applyTo(obj, faces))
            self.status.setText("\n".join(lines))
        except Exception as e:
            self.status.setText(translate("HoleFill", "Failed: %s") % e)
            FreeCAD.Console.PrintError("HoleFill: %s\n" % e)
        finally:
            QtWidgets.QApplication.restoreOverrideCursor()

    def mesh(self, obj, faces, angle, maxVertices=None):
        key = (obj.Name, tuple(faces or ()), angle, obj.Shape.hashCode(), maxVertices)
        if key not in self.meshes:
            self.meshes[key] = overlay.bounded_mesh(obj, faces, angle, "%s of" % self.kind, maxVertices)
        return self.meshes[key]


class LegendWidget(QtWidgets.QWidget):
    """Colour bar with tick labels: the legend of the curvature map."""

    def __init__(self):
        super().__init__()
        self.scale = None
        self.setMinimumHeight(70)

    def setScale(self, scale, title):
        self.scale, self.title = scale, title
        self.update()

    def paintEvent(self, event):
        if not self.scale:
            return
        p = QtGui.QPainter(self)
        w, h = self.width() - 20, 22
        ramp = self.scale["ramp"]
        for i in range(w):
            r, g, b = ramp[min(len(ramp) - 1, int(i * len(ramp) / max(w, 1)))]
            p.setPen(QtGui.QColor.fromRgbF(float(r), float(g), float(b)))
            p.drawLine(10 + i, 20, 10 + i, 20 + h)
        p.setPen(QtCore.Qt.black)
        p.drawText(10, 14, self.title)
        lo, hi = self.scale["low"], self.scale["high"]
        for t, label in zip(self.scale["ticks"], self.scale["labels"]):
            x = 10 + int((t - lo) / (hi - lo) * (w - 1))
            p.drawLine(x, 20 + h, x, 26 + h)
            p.drawText(x - 20, 40 + h, label)
        p.end()


class CurvaturePanel(_Panel):
    kind = "Curvature"
    TITLES = {"mean": "Mean curvature", "gauss": "Gaussian curvature", "max": "Max principal curvature",
              "min": "Min principal curvature"}

    def __init__(self, targets):
        super().__init__(targets)
        self.form.setWindowTitle(translate("HoleFill", "Curvature map"))
        self.quantity = QtWidgets.QComboBox()
        for k, v in self.TITLES.items():
            self.quantity.addItem(v, k)
        self.clamp = QtWidgets.QComboBox()
        self.clamp.addItems(["By percentile", "By value"])
        self.low, self.high = QtWidgets.QDoubleSpinBox(), QtWidgets.QDoubleSpinBox()
        for s, v in ((self.low, 2.0), (self.high, 98.0)):
            s.setDecimals(6)
            s.setRange(-1e6, 1e6)
            s.setValue(v)
        self.legend = LegendWidget()
        self.layout.addRow(translate("HoleFill", "Quantity"), self.quantity)
        self.layout.addRow(translate("HoleFill", "Colour range"), self.clamp)
        self.layout.addRow(translate("HoleFill", "Low"), self.low)
        self.layout.addRow(translate("HoleFill", "High"), self.high)
        self.layout.addRow(self.legend)
        self.layout.addRow(self.status)
        self.quantity.currentIndexChanged.connect(self.apply)
        self.clamp.currentIndexChanged.connect(self.clampChanged)
        self.low.editingFinished.connect(self.apply)
        self.high.editingFinished.connect(self.apply)
        self.apply()

    def clampChanged(self):
        if self.clamp.currentIndex() == 0:
            self.low.setValue(2.0)
            self.high.setValue(98.0)
        elif self.legend.scale:
            self.low.setValue(self.legend.scale["low"])
            self.high.setValue(self.legend.scale["high"])
        self.apply()

    def applyTo(self, obj, faces):
        q = self.quantity.currentData()
        byValue = self.clamp.currentIndex() == 1
        cmap = overlay.show_curvature(obj, faces, quantity=q,
                                      percentiles=(2.0, 98.0) if byValue else (self.low.value(), self.high.value()),
                                      valueRange=(self.low.value(), self.high.value()) if byValue else None,
                                      mesh=self.mesh(obj, faces, 2.0))
        self.legend.setScale(cmap["scale"], self.TITLES[q])
        import numpy
        v = cmap["values"][numpy.isfinite(cmap["values"])]
        return "%s: %d vertices, %s from %.4g to %.4g (colours %.4g .. %.4g)" % (
            obj.Label, len(cmap["points"]), q, v.min(), v.max(), cmap["scale"]["low"], cmap["scale"]["high"])


class ZebraPanel(_Panel):
    kind = "Zebra"

    def __init__(self, targets):
        super().__init__(targets)
        self.form.setWindowTitle(translate("HoleFill", "Zebra stripes"))
        self.mode = QtWidgets.QComboBox()
        self.mode.addItems(["Reflection lines (follow the view)", "Isophotes (fixed)"])
        self.count = QtWidgets.QSpinBox()
        self.count.setRange(2, 200)
        self.count.setValue(16)
        self.width = QtWidgets.QDoubleSpinBox()
        self.width.setRange(0.05, 0.95)
        self.width.setSingleStep(0.05)
        self.width.setValue(0.5)
        self.angle = QtWidgets.QDoubleSpinBox()
        self.angle.setRange(-180, 180)
        self.angle.setSuffix(translate("HoleFill", " deg"))
        self.layout.addRow(translate("HoleFill", "Stripes"), self.mode)
        self.layout.addRow(translate("HoleFill", "Count"), self.count)
        self.layout.addRow(translate("HoleFill", "Black share"), self.width)
        self.layout.addRow(translate("HoleFill", "Direction"), self.angle)
        self.layout.addRow(self.status)
        for w in (self.mode,):
            w.currentIndexChanged.connect(self.apply)
        for w in (self.count, self.width, self.angle):
            # Typed values apply when complete (Enter, or leaving the box): each keystroke of
            # "120" redrew the stripes for 1 and 12 first. Arrows and the wheel apply at once.
            w.setKeyboardTracking(False)
            w.valueChanged.connect(self.apply)
        self.apply()

    def applyTo(self, obj, faces):
        import math
        a = math.radians(self.angle.value())
        renderer = preferences.get("ZebraRenderer")
        mesh = overlay.show_zebra(obj, faces, count=self.count.value(), width=self.width.value(),
                                  angleDeg=self.angle.value(), isophote=self.mode.currentIndex() == 1,
                                  isoDirection=(math.cos(a), 0.0, math.sin(a)) if self.mode.currentIndex() == 1 else (0, 0, 1),
                                  mesh=self.mesh(obj, faces, 2.0, overlay.zebra_vertex_budget(renderer)),
                                  renderer=renderer)
        return "%s: %d vertices, neighbouring normals within %.2f deg" % (
            obj.Label, len(mesh["points"]), math.degrees(max(mesh["maxInteriorNormalAngle"], mesh["maxBoundaryNormalAngle"])))


def continuity_target():
    """(object, report) for the selection: two adjacent faces of one object, or a Fill object."""
    import HoleFill
    sel = FreeCADGui.Selection.getSelectionEx()
    if not sel:
        raise overlay.SelectionError(translate("HoleFill", "Select two adjacent faces, or a Fill object."))
    if len(sel) == 1 and hasattr(sel[0].Object, "Proxy") and sel[0].Object.TypeId == "Part::FeaturePython" \
            and hasattr(sel[0].Object, "Source") and not sel[0].SubElementNames:
        fill = sel[0].Object
        src, subs = fill.Source if fill.Source else (None, [])
        if src is None or fill.Shape.isNull():
            raise overlay.SelectionError(translate("HoleFill", "%s has no result to check: recompute it first.") % fill.Label)
        edges = [int(s[4:]) for s in subs if s.startswith("Edge")]
        face = fill.Shape.Faces[0] if fill.Output == "Face" else patch_of(fill.Shape, src.Shape)
        report = HoleFill.continuityAlong(face, src.Shape, edges or HoleFill.findHoles(src.Shape)[0]["edge_indices"])
        # The numbers are the Fill's own, as its panel, its properties and its report give them:
        # measured again here at other samples, one edge showed two different G0s in two panels.
        # The check's samples still colour the boundary.
        import json
        stored = json.loads(fill.Report) if getattr(fill, "Report", "") else {}
        for key in ("g0", "g0_relative", "g1", "g2", "per_edge", "str", "scale", "samples"):
            if key in stored:
                report[key] = stored[key]
        return fill, report
    faces = [(s.Object, n) for s in sel for n in s.SubElementNames if n.startswith("Face")]
    if any(s.Object.isDerivedFrom("Mesh::Feature") for s in sel):
        raise overlay.SelectionError(translate("HoleFill", "A mesh is selected: the continuity check works on B-rep faces."))
    if len(faces) != 2:
        raise overlay.SelectionError(translate("HoleFill", "Select exactly two adjacent faces (Ctrl+click), or one Fill object; "
                                     "%d face(s) are selected.") % len(faces))
    if faces[0][0] != faces[1][0]:
        raise overlay.SelectionError(translate("HoleFill", "The two faces belong to different objects: select two faces of one shape."))
    obj = faces[0][0]
    return obj, HoleFill.faceContinuity(obj.Shape, faces[0][1], faces[1][1])


def patch_of(sewn, source):
    """The face of a sewn Fill result that the source does not have (the patch)."""
    areas = [f.Area for f in source.Faces]
    new = [f for f in sewn.Faces if not any(abs(f.Area - a) <= 1e-9 * max(1.0, a) for a in areas)]
    if len(new) != 1:
        raise overlay.SelectionError(translate("HoleFill", "cannot tell the patch among the sewn faces: set the Fill's Output to Face"))
    return new[0]


class ContinuityPanel(_Panel):
    kind = "Continuity"

    def __init__(self, obj, report):
        super().__init__([])
        self.form.setWindowTitle(translate("HoleFill", "Continuity check"))
        self.report = report
        self.table = QtWidgets.QTableWidget(0, 4)
        self.table.setHorizontalHeaderLabels([translate("HoleFill", "Edge"), "G0", translate("HoleFill", "G1 (rad)"), "G2"])
        rows = [("all", report["g0"], report["g1"], report["g2"])] + \
               [("Edge%d" % e["edge"], e["g0"], e["g1"], e["g2"]) for e in report["per_edge"]]
        self.table.setRowCount(len(rows))
        for i, r in enumerate(rows):
            for j, v in enumerate(r):
                self.table.setItem(i, j, QtWidgets.QTableWidgetItem(v if j == 0 else "%.3g" % v))
        s = report["str"]
        summary = (translate("HoleFill", "Scale %.4g, %d samples. G0 %.3g (%.2g of scale): %s. G1 %.3g rad: %s. G2 %.3g: %s.\n"
                   "Boundary colours: blue G2 (<= 0.1), cyan G1 (<= 1e-3 rad), orange G0 only, red gap.") % (
                       report["scale"], report["samples"], report["g0"], report["g0_relative"],
                       translate("HoleFill", "strict") if s["g0_strict"] else (translate("HoleFill", "loose") if s["g0_loose"] else translate("HoleFill", "open")), report["g1"],
                       translate("HoleFill", "strict") if s["g1_strict"] else (translate("HoleFill", "loose") if s["g1_loose"] else translate("HoleFill", "broken")), report["g2"],
                       translate("HoleFill", "ok") if s["g2"] else translate("HoleFill", "above 0.1")))
        self.status.setText(summary)
        self.layout.addRow(self.table)
        self.layout.addRow(self.status)
        # CurvesWB's curvature combs along the boundary: the normal curvature across it of the
        # face checked and of its neighbour; where the check says G2 the two coincide.
        self.obj = obj
        self.combs = QtWidgets.QCheckBox(translate("HoleFill", "Curvature combs"))
        self.combs.setObjectName("HoleFillCombs")
        self.combs.setToolTip(translate("HoleFill", "Along the boundary, the normal curvature across it as comb teeth: the face checked\n"
                                        "in blue, its neighbour in magenta. Where they coincide the join is G2."))
        self.combs.toggled.connect(self.showCombs)
        self.combLegend = QtWidgets.QLabel()
        self.combLegend.setObjectName("HoleFillCombsLegend")
        self.combLegend.setWordWrap(True)
        self.layout.addRow(self.combs)
        self.layout.addRow(self.combLegend)
        overlay.show_continuity(obj, report)

    def showCombs(self, on):
        overlay.remove("Combs", self.obj)
        self.combLegend.setText("")
        if on:
            s = overlay.show_combs(self.obj, self.report)
            self.combLegend.setText(translate("HoleFill", "Combs: blue this face, magenta its neighbour; a tooth of one unit of length "
                                              "is a curvature of %.3g.") % (1.0 / s) if s > 0 else
                                    translate("HoleFill", "Combs: both sides are flat across the boundary (curvature 0)."))

    def reject(self):
        overlay.remove("Combs")
        return _Panel.reject(self)

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Close)

    def accept(self):
        return self.reject()
