"""Task panel of "Fit point cloud": for a Points or Mesh object, the parameterization method
(shape-preserving by default: its convex combinations cannot cross, BIDGCN's predictions can), the tolerance in model units, the degree and adaptive (THB) or
uniform refinement, with a preview in the 3D view of the fitted surface (translucent), its
hierarchical mesh (the THB leaf cells drawn on the surface, one colour per level) and the points
coloured by their distance to the surface (blue: none, red: the tolerance or more). The status
line carries the per-iteration numbers. OK creates the parametric PointCloudFit object (one undo
step); Cancel changes nothing."""
import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from HoleFill import optionTip, preferences
from HoleFill.pointcloud import POINT_FIT_OPTIONS
from HoleFillGui import SelectionError, scene_overlay, task_dialog

translate = FreeCAD.Qt.translate

OVERLAY = "HoleFillPointFit"
LEVEL_COLOURS = [(0.1, 0.1, 0.1), (0.1, 0.3, 0.9), (0.0, 0.6, 0.3), (0.85, 0.5, 0.0), (0.8, 0.1, 0.6), (0.6, 0.0, 0.0)]


def source_from_selection():
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) == 1 and ((hasattr(sel[0], "Points") and hasattr(sel[0].Points, "Points")) or hasattr(sel[0], "Mesh")):
        return sel[0]
    raise SelectionError(translate("HoleFill", "Select one Points or Mesh object to fit a surface to."))


def remove_overlay():
    scene_overlay.remove(OVERLAY)


def error_colour(t):
    """Blue (0) through green and yellow to red (1 and above)."""
    t = max(0.0, min(1.0, t))
    return (min(1.0, 2 * t), min(1.0, 2 - 2 * t) if t > 0.5 else 2 * t, max(0.0, 1 - 2 * t))


class FitPanel(task_dialog.Panel):
    overlay = OVERLAY

    def __init__(self, source):
        import HoleFill
        self.source = source
        self.points = HoleFill.pointcloud._sourcePoints(source)
        pts = self.points.Points if hasattr(self.points, "Topology") else self.points
        self.xyz = [(p.x, p.y, p.z) for p in (q.Vector if hasattr(q, "Vector") else q for q in pts)]
        lo = [min(p[k] for p in self.xyz) for k in range(3)]
        hi = [max(p[k] for p in self.xyz) for k in range(3)]
        self.diagonal = sum((a - b) ** 2 for a, b in zip(hi, lo)) ** 0.5
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("HoleFill", "Fit point cloud"))
        layout = QtWidgets.QFormLayout(self.form)
        self.method = QtWidgets.QComboBox()
        self.method.setObjectName("HoleFillPointFitMethod")
        self.method.addItems(POINT_FIT_OPTIONS["method"]["choices"])
        self.method.setCurrentText(POINT_FIT_OPTIONS["method"]["default"])
        self.method.setToolTip(optionTip(POINT_FIT_OPTIONS["method"]))
        layout.addRow(translate("HoleFill", "Parameterization:"), self.method)
        self.tolerance = QtWidgets.QDoubleSpinBox()
        self.tolerance.setObjectName("HoleFillPointFitTolerance")
        self.tolerance.setDecimals(6)
        self.tolerance.setRange(1e-6, 1e6)
        self.tolerance.setValue(float("%.3g" % (preferences.get("FitTolerance") * self.diagonal)))
        self.tolerance.setSuffix(translate("HoleFill", " mm"))
        self.tolerance.setToolTip(optionTip(POINT_FIT_OPTIONS["tolerance"]))
        layout.addRow(translate("HoleFill", "Tolerance:"), self.tolerance)
        self.degree = QtWidgets.QSpinBox()
        self.degree.setObjectName("HoleFillPointFitDegree")
        f = POINT_FIT_OPTIONS["degree"]
        self.degree.setRange(int(f["minimum"]), int(f["maximum"]))
        self.degree.setValue(int(f["default"]))
        self.degree.setToolTip(optionTip(f))
        layout.addRow(translate("HoleFill", "Degree:"), self.degree)
        self.adaptive = QtWidgets.QCheckBox(translate("HoleFill", "Adaptive refinement (THB-splines)"))
        self.adaptive.setObjectName("HoleFillPointFitAdaptive")
        self.adaptive.setChecked(bool(POINT_FIT_OPTIONS["adaptive"]["default"]))
        self.adaptive.setToolTip(optionTip(POINT_FIT_OPTIONS["adaptive"]))
        layout.addRow(self.adaptive)
        self.show = task_dialog.show_toggles(layout, "HoleFillPointFitShow_", (
            ("surface", translate("HoleFill", "Show the surface")), ("cells", translate("HoleFill", "Show the hierarchical mesh")),
            ("errors", translate("HoleFill", "Show the point errors"))), self.draw)
        layout.addRow(task_dialog.button(translate("HoleFill", "Preview"), "HoleFillPointFitPreview", self.preview))
        self.status = task_dialog.status_line("HoleFillPointFitStatus")
        layout.addRow(self.status)
        self.result = None
        self.preview()

    def options(self):
        return dict(method=self.method.currentText(), tolerance=self.tolerance.value(), degree=self.degree.value(),
                    adaptive=self.adaptive.isChecked(), weights=preferences.get("BidgcnWeights"))

    def preview(self):
        import HoleFill
        QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            self.result = HoleFill.fitPoints(self.points, **self.options())
        except Exception as e:
            self.result = None
            self.status.setText(task_dialog.failed(translate("HoleFill", "Fit"), e))
            remove_overlay()
            return
        finally:
            QtWidgets.QApplication.restoreOverrideCursor()
        r = self.result[1]
        lines = ["%d functions: max error %.3g mm, RMS %.3g mm" % (it["dof"], it["max_error"] * r["diagonal"],
                                                                  (it["mse"] ** 0.5) * r["diagonal"]) for it in r["iterations"]]
        self.status.setText("%s parameters for %d points (%d on the boundary%s), %s after %d iterations, %d levels:\n%s" % (
            r["parameterization"]["method"], r["parameterization"]["points"], len(r["boundary"]),
            ", found" if r["boundary_found"] >= 0 else "", "tolerance met" if r["met_tolerance"] else "tolerance NOT met",
            len(r["iterations"]), r["levels"], "\n".join(lines[-4:])) + (
            "\nwarning: the surface folds at %d of 4225 domain samples" % r["folds"] if r["folds"] else ""))
        self.draw()

    def draw(self):
        from pivy import coin
        remove_overlay()
        if self.result is None:
            return
        face, rep = self.result
        root = scene_overlay.placed_root(OVERLAY, FreeCAD.Placement())
        if self.show["surface"].isChecked():
            sep = scene_overlay.face_node(face, OVERLAY + "_surface", (0.45, 0.75, 0.35), 0.4)
            root.addChild(sep)
        if self.show["cells"].isChecked():
            surf = face.Surface
            sep = coin.SoSeparator()
            sep.setName(OVERLAY + "_cells")
            style = coin.SoDrawStyle()
            style.lineWidth = 1.5
            sep.addChild(style)
            for level in sorted(set(int(c[0]) for c in rep["cells"])):
                col = coin.SoBaseColor()
                col.rgb.setValue(*LEVEL_COLOURS[min(level, len(LEVEL_COLOURS) - 1)])
                sub = coin.SoSeparator()
                sub.addChild(col)
                pts, counts = [], []
                for c in rep["cells"]:
                    if int(c[0]) != level:
                        continue
                    u0, v0, u1, v1 = c[1:]
                    ring = [(u0, v0), (u1, v0), (u1, v1), (u0, v1), (u0, v0)]
                    for (a, b), (p, q) in zip(ring, ring[1:]):
                        seg = [surf.value(a + (p - a) * s / 6.0, b + (q - b) * s / 6.0) for s in range(7)]
                        pts += [[x.x, x.y, x.z] for x in seg]
                        counts.append(len(seg))
                coords = coin.SoCoordinate3()
                coords.point.setValues(0, len(pts), pts)
                lines = coin.SoLineSet()
                lines.numVertices.setValues(0, len(counts), counts)
                sub.addChild(coords)
                sub.addChild(lines)
                sep.addChild(sub)
            root.addChild(sep)
        if self.show["errors"].isChecked():
            tol = max(rep["tolerance"], 1e-300)
            sep = coin.SoSeparator()
            sep.setName(OVERLAY + "_errors")
            style = coin.SoDrawStyle()
            style.pointSize = 4
            mat = coin.SoMaterial()
            mat.diffuseColor.setValues(0, len(self.xyz), [error_colour(e / tol) for e in rep["errors"]])
            binding = coin.SoMaterialBinding()
            binding.value = coin.SoMaterialBinding.PER_VERTEX
            coords = coin.SoCoordinate3()
            coords.point.setValues(0, len(self.xyz), [list(p) for p in self.xyz])
            cloud = coin.SoPointSet()
            cloud.numPoints.setValue(len(self.xyz))
            for nd in (style, mat, binding, coords, cloud):
                sep.addChild(nd)
            root.addChild(sep)
        scene_overlay.show(root)

    # -- dialog (task_dialog.Panel) --------------------------------------------------------------
    def make(self):
        import HoleFill
        return HoleFill.makePointCloudFit(self.source, **self.options())

    def made(self, obj):
        import json
        r = json.loads(obj.Report)
        return "HoleFill: point-cloud fit %s of %s: %d functions, max error %.3g mm, tolerance %s" % (
            obj.Label, self.source.Label, r["iterations"][-1]["dof"], r["iterations"][-1]["max_error"] * r["diagonal"],
            "met" if r["met_tolerance"] else "NOT met")
