"""Task panel of "Fit labeled surface": for a BoundaryLabels object (or a mesh that has one),
the options of the labeled fit (control points, fitted/G2/G1/no extension, margin, the weights) with a
preview in the 3D view of the guiding frame (blue curves), the extended mesh (grey wireframe of
the triangles added around the region) and the trimmed surface (translucent green); the status
line carries the fit's numbers. OK creates the parametric LabeledFit object (one undo step),
which recomputes when the labels change; Cancel changes nothing."""
import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from HoleFill import labeled, optionTip, preferences
from HoleFillGui import SelectionError, scene_overlay, task_dialog

translate = FreeCAD.Qt.translate

OVERLAY = "HoleFillLabeledFit"


def labels_from_selection():
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) == 1 and hasattr(sel[0], "LabelsJson"):
        return sel[0]
    if len(sel) == 1 and hasattr(sel[0], "Mesh"):
        found = [o for o in sel[0].Document.Objects if hasattr(o, "LabelsJson") and o.Source == sel[0]]
        if found:
            return found[-1]
        raise SelectionError(translate("HoleFill", "%s has no boundary labels yet: use HoleFill → Label boundary first.") % sel[0].Label)
    raise SelectionError(translate("HoleFill", "Select the boundary labels of a mesh region (made by HoleFill → Label boundary), or the mesh itself."))


def remove_overlay():
    scene_overlay.remove(OVERLAY)


class FitPanel(task_dialog.Panel):
    overlay = OVERLAY

    def __init__(self, labelsObj):
        self.labels = labelsObj
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("HoleFill", "Fit labeled surface"))
        layout = QtWidgets.QFormLayout(self.form)
        # Defaults, ranges and tooltips: the core's option schema (HoleFill.labeled.FIT_OPTIONS).
        opts = labeled.FIT_OPTIONS

        def integer(name, objectName):
            w = QtWidgets.QSpinBox()
            w.setObjectName(objectName)
            w.setRange(int(opts[name]["minimum"]), int(opts[name]["maximum"]))
            w.setValue(opts[name]["default"])
            w.setToolTip(optionTip(opts[name]))
            return w

        self.ctrlU, self.ctrlV = integer("controlU", "HoleFillFitCtrlU"), integer("controlV", "HoleFillFitCtrlV")
        layout.addRow(translate("HoleFill", "Control points u:"), self.ctrlU)
        layout.addRow(translate("HoleFill", "Control points v:"), self.ctrlV)
        self.extension = QtWidgets.QComboBox()
        self.extension.setObjectName("HoleFillFitExtension")
        self.extension.addItems(opts["extension"]["choices"])
        self.extension.setCurrentText(opts["extension"]["default"])
        self.extension.setToolTip(optionTip(opts["extension"]))
        layout.addRow(translate("HoleFill", "Extension:"), self.extension)
        self.margin = integer("margin", "HoleFillFitMargin")
        layout.addRow(translate("HoleFill", "Margin layers:"), self.margin)
        self.reach = QtWidgets.QDoubleSpinBox()
        self.reach.setObjectName("HoleFillFitReach")
        self.reach.setRange(opts["reach"]["minimum"], opts["reach"]["maximum"])
        self.reach.setDecimals(3)
        self.reach.setSingleStep(0.05)
        self.reach.setValue(opts["reach"]["default"])
        self.reach.setToolTip(optionTip(opts["reach"]))
        layout.addRow(translate("HoleFill", "Reach past the domain:"), self.reach)
        self.weights = {}
        for key, label in (("fairness", translate("HoleFill", "Isocurve fairness:")), ("smoothing", translate("HoleFill", "Thin-plate smoothing:")),
                           ("framePlacement", translate("HoleFill", "Frame placement:")), ("meshFairness", translate("HoleFill", "Mesh fairness (E_Mesh):"))):
            w = QtWidgets.QDoubleSpinBox()
            w.setObjectName("HoleFillFit_" + key)
            w.setDecimals(8)
            w.setRange(0, 1e6)
            w.setValue(opts[key]["default"])
            w.setToolTip(optionTip(opts[key]))
            layout.addRow(label, w)
            self.weights[key] = w
        self.relax = QtWidgets.QCheckBox(translate("HoleFill", "Relax the labels where they cannot be fitted"))
        self.relax.setObjectName("HoleFillFitRelaxLabels")
        self.relax.setToolTip(optionTip(opts["relaxLabels"]))
        self.relax.setChecked(opts["relaxLabels"]["default"])
        layout.addRow(self.relax)
        self.show = task_dialog.show_toggles(layout, "HoleFillFitShow_", (
            ("frame", translate("HoleFill", "Show the guiding frame")), ("extended", translate("HoleFill", "Show the extended mesh")),
            ("surface", translate("HoleFill", "Show the surface"))), self.draw)
        layout.addRow(task_dialog.button(translate("HoleFill", "Preview"), "HoleFillFitPreview", self.preview))
        self.status = task_dialog.status_line("HoleFillFitStatus")
        layout.addRow(self.status)
        self.result = None
        self.preview()

    def options(self):
        return dict(controlPoints=(self.ctrlU.value(), self.ctrlV.value()), extension=self.extension.currentText(),
                    margin=self.margin.value(), reach=self.reach.value(), relaxLabels=self.relax.isChecked(),
                    relativeTolerance=preferences.get("FitTolerance"), **{k: w.value() for k, w in self.weights.items()})

    def preview(self):
        import HoleFill
        QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            # In a process of its own, with progress and Cancel: a crash in the fit cannot take
            # FreeCAD and the unsaved document down, and it fails the Preview instead.
            with task_dialog.progress_dialog(translate("HoleFill", "Fitting the labeled surface..."), self.form) as progress:
                self.result = HoleFill.fitLabeled(self.labels.Source.Mesh, self.labels.LabelsJson, isolated=True, progress=progress,
                                                  **self.options())
        except Exception as e:
            self.result = None
            self.status.setText(task_dialog.failed(translate("HoleFill", "Fit"), e))
            remove_overlay()
            return
        finally:
            QtWidgets.QApplication.restoreOverrideCursor()
        r = self.result[2]
        self.status.setText(translate("HoleFill", "Data max %.2e, RMS %.2e (of the region's diagonal; scan noise %.2e); %d weak control points; "
                            "log10 condition %.1f; %d extension vertices; face %s; %.2f s%s") % (
                                r["data_max"], r["data_rms"], r["noise_estimate"], r["weak_control_points"], r["log10_condition"],
                                r["extended_vertices"],
                                "valid" if r["face_valid"] else translate("HoleFill", "INVALID (FreeCAD's check refuses its trimming: move corner labels, "
                                                                          "or let the labels relax)"), r["seconds"],
                                "".join("\nwarning: " + w for w in r["warnings"])))
        self.draw()

    def draw(self):
        from pivy import coin
        remove_overlay()
        if self.result is None:
            return
        face, _, rep = self.result
        root = scene_overlay.placed_root("%s_%s" % (OVERLAY, self.labels.Name), self.labels.Source.Placement)
        if self.show["surface"].isChecked():
            sep = scene_overlay.face_node(face, OVERLAY + "_surface", (0.45, 0.75, 0.35), 0.35)
            root.addChild(sep)
        ev, et = rep["extended"]
        regionFacets = self.labels.Source.Mesh.CountFacets
        if self.show["extended"].isChecked() and len(et) > regionFacets:
            sep = coin.SoSeparator()
            sep.setName(OVERLAY + "_extended")
            col = coin.SoBaseColor()
            col.rgb.setValue(0.35, 0.35, 0.35)
            coords = coin.SoCoordinate3()
            coords.point.setValues(0, len(ev), ev.tolist())
            lines = coin.SoIndexedLineSet()
            idx = []
            for t in et[regionFacets:].tolist():
                idx += [t[0], t[1], t[2], t[0], -1]
            lines.coordIndex.setValues(0, len(idx), idx)
            for nd in (col, coords, lines):
                sep.addChild(nd)
            root.addChild(sep)
        if self.show["frame"].isChecked():
            sep = coin.SoSeparator()
            sep.setName(OVERLAY + "_frame")
            col = coin.SoBaseColor()
            col.rgb.setValue(0.1, 0.2, 0.95)
            style = coin.SoDrawStyle()
            style.lineWidth = 3
            sep.addChild(col)
            sep.addChild(style)
            for _, curve in rep["frame"]:
                coords = coin.SoCoordinate3()
                coords.point.setValues(0, len(curve), curve.tolist())
                line = coin.SoLineSet()
                line.numVertices.setValue(len(curve))
                sub = coin.SoSeparator()
                sub.addChild(coords)
                sub.addChild(line)
                sep.addChild(sub)
            root.addChild(sep)
        scene_overlay.show(root)

    # -- dialog (task_dialog.Panel) --------------------------------------------------------------
    def make(self):
        import HoleFill
        return HoleFill.makeLabeledFit(self.labels, **self.options())

    def made(self, obj):
        import json
        r = json.loads(obj.Report)
        return "HoleFill: labeled fit %s of %s: data max %.2e, %d weak control points, log10 condition %.1f" % (
            obj.Label, self.labels.Source.Label, r["data_max"], r["weak_control_points"], r["log10_condition"])
