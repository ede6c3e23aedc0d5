"""The Fill task panel: the hole (from the selection; one edge names its loop), method, continuity
and tolerance, points inside the hole the fill passes through (Surface Filling's vertex
constraints: selected vertices added, drawn as dots), a Preview that shows the fill as a view-only overlay with its continuity report,
OK to make the Fill object (or change the one being edited) in one undo step, Cancel to leave
the document exactly as it was. The hole is read and found once (HoleFill.PreparedHole): every
Preview reuses it, and OK hands it to the Fill object, whose first recompute neither reads the
model nor finds the hole again and, when nothing changed since the last Preview, solves nothing."""
import json

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtGui, QtWidgets

import HoleFill
from HoleFill import fill_feature, preferences
from HoleFillGui import scene_overlay, task_dialog

translate = FreeCAD.Qt.translate


def _selectedHole():
    """(object, [edge names]) from the current selection, or (None, [])."""
    for sel in FreeCADGui.Selection.getSelectionEx():
        edges = [n for n in sel.SubElementNames if n.startswith("Edge")]
        if edges and hasattr(sel.Object, "Shape"):
            return sel.Object, edges
    return None, []


def _selectedInstead():
    """What is selected that is not a hole's edge ("Panel.Face1", "Box"), to say so; "" when nothing is."""
    for sel in FreeCADGui.Selection.getSelectionEx():
        subs = [n for n in sel.SubElementNames if not n.startswith("Edge")]
        return "%s.%s" % (sel.Object.Label, subs[0]) if subs else sel.Object.Label
    return ""


def formatReport(report):
    """A short human-readable table of a fill report."""
    lines = ["Status: %s — %s" % (report["status"], report["message"]),
             "Requested %s, achieved %s (method %s)" % (report["requested"], report["achieved"], report["method"]),
             "N = %d corners, %d edges, scale %.4g" % (report["corners"], len(report["edges"]), report["scale"]),
             "G0 %.3g (%.2g of scale)   G1 %.3g rad   G2 %.3g" % (report["g0"], report["g0_relative"], report["g1"],
                                                                  report["g2"]),
             "Poles %dx%d after %d refinements; %.2f s" % (report["poles_u"], report["poles_v"], report["refinements"],
                                                          report["timings"]["total"])]
    creases = [e for e in report.get("edge_continuity", []) if e["source"] == "crease"]
    if creases:
        lines.append("Creases (asked G0): " + ", ".join("Edge%d" % e["edge"] for e in creases))
    if report.get("invalid_before"):
        lines.append("Already invalid before the fill: " + ", ".join("Face%d" % f for f in report["invalid_before"]))
    if report["faulty_edges"]:
        lines.append("Worst edges: " + ", ".join("Edge%d" % e for e in report["faulty_edges"]))
    if report.get("point_distances"):
        lines.append("Points passed through: %d, farthest %.3g" % (len(report["point_distances"]), max(report["point_distances"])))
    return "\n".join(lines)


EDGE_CHOICES = ("auto", "G0", "G1", "G2")  # auto: the panel's continuity, G0 where a crease is found
OVERLAY = "HoleFillFillPreview"
LOOP = "HoleFillFillLoop"       # the hole's loop, drawn while the panel is open
POINTS = "HoleFillFillPoints"   # the points the fill passes through, drawn while the panel is open
COLOR_POINTS = (0.1, 0.1, 0.1)
# The loop before a Preview (magenta), and after it the edges that reach what they were asked and
# those that miss it, in the tiers' colours.
COLOR_LOOP, COLOR_MET, COLOR_MISSED = (0.85, 0.15, 0.85), scene_overlay.TIER_COLORS["G2"], scene_overlay.TIER_COLORS["none"]
TIERS = ("none",) + tuple(HoleFill.CONTINUITIES)


def _missed(edge):
    """Whether an edge_continuity entry of a report reached less than it was asked."""
    return TIERS.index(edge["reached"]) < TIERS.index(edge["asked"])


class _Status:
    """The panel's report box as task_dialog.create's status line."""

    def __init__(self, box):
        self.setText = box.setPlainText


class FillTaskPanel(task_dialog.Panel):
    overlay = OVERLAY

    def __init__(self, existing=None):
        self.doc = FreeCAD.ActiveDocument
        self.obj = existing
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("HoleFill", "Fill hole"))
        lay = QtWidgets.QFormLayout(self.form)
        self.holeLabel = QtWidgets.QLabel()
        self.holeLabel.setWordWrap(True)
        lay.addRow(translate("HoleFill", "Hole:"), self.holeLabel)
        self.useSel = QtWidgets.QPushButton(translate("HoleFill", "Use selected edges"))
        lay.addRow(self.useSel)
        self.method = QtWidgets.QComboBox()
        self.method.addItems(list(HoleFill.METHODS))
        tips = {name: HoleFill.optionTip(f) for name, f in HoleFill.FILL_OPTIONS.items()}
        self.method.setToolTip(tips["method"])
        lay.addRow(translate("HoleFill", "Parameterization:"), self.method)
        self.showProjection = QtWidgets.QCheckBox(translate("HoleFill", "Show UVTran projection surface"))
        self.showProjection.setToolTip(translate("HoleFill", "Overlay the surface UVTran predicts for this hole (view only)"))
        lay.addRow(self.showProjection)
        self.continuity = QtWidgets.QComboBox()
        self.continuity.addItems(list(HoleFill.CONTINUITIES))
        self.continuity.setCurrentText(HoleFill.FILL_OPTIONS["continuity"]["default"])
        self.continuity.setToolTip(tips["continuity"])
        lay.addRow(translate("HoleFill", "Continuity:"), self.continuity)
        # One row per loop edge: what to ask of it (auto = the continuity above, G0 on creases found
        # at the hole's corners) and, after a preview, what was asked and reached there.
        self.edgeTable = QtWidgets.QTableWidget(0, 3)
        self.edgeTable.setHorizontalHeaderLabels([translate("HoleFill", "Edge"), translate("HoleFill", "Ask"), translate("HoleFill", "Reached")])
        # Compact, so that all three columns show in the Combo View's 264 px.
        for column in (0, 1):
            self.edgeTable.horizontalHeader().setSectionResizeMode(column, QtWidgets.QHeaderView.ResizeToContents)
        self.edgeTable.horizontalHeader().setStretchLastSection(True)
        self.edgeTable.verticalHeader().setVisible(False)
        self.edgeTable.setMinimumHeight(110)
        lay.addRow(self.edgeTable)
        self.tolerance = QtWidgets.QDoubleSpinBox()
        self.tolerance.setDecimals(7)
        self.tolerance.setRange(0.0, 1e3)
        self.tolerance.setSpecialValueText(translate("HoleFill", "auto (1e-6 of hole size)"))
        self.tolerance.setToolTip(tips["tolerance"])
        lay.addRow(translate("HoleFill", "G0 tolerance:"), self.tolerance)
        # Surface Filling's vertex constraints: points inside the hole the face passes through.
        self.points = []
        self.pointsLabel = QtWidgets.QLabel()
        self.pointsLabel.setObjectName("HoleFillFillPointsLabel")
        self.pointsLabel.setWordWrap(True)
        lay.addRow(translate("HoleFill", "Pass through:"), self.pointsLabel)
        pointRow = QtWidgets.QHBoxLayout()
        self.addPoints = QtWidgets.QPushButton(translate("HoleFill", "Add selected"))
        self.addPoints.setObjectName("HoleFillFillAddPoints")
        self.addPoints.setToolTip(translate("HoleFill", "Add the selected vertices (of any object, e.g. a Draft point or a sketch)\n"
                                            "as points inside the hole that the fill passes through"))
        self.clearPoints = QtWidgets.QPushButton(translate("HoleFill", "Clear"))
        self.clearPoints.setObjectName("HoleFillFillClearPoints")
        pointRow.addWidget(self.addPoints)
        pointRow.addWidget(self.clearPoints)
        lay.addRow(pointRow)
        self.output = QtWidgets.QComboBox()
        self.output.addItems(list(fill_feature.OUTPUTS))
        lay.addRow(translate("HoleFill", "Output:"), self.output)
        self.preview = QtWidgets.QPushButton(translate("HoleFill", "Preview"))
        lay.addRow(self.preview)
        # What a Preview that reaches no tier means, in words, with what else reaches one.
        self.verdict = QtWidgets.QLabel()
        self.verdict.setWordWrap(True)
        self.verdict.setObjectName("HoleFillFillVerdict")
        self.verdict.hide()
        lay.addRow(self.verdict)
        self.alternativesBox = QtWidgets.QWidget()
        self.alternativesBox.setLayout(QtWidgets.QVBoxLayout())
        self.alternativesBox.layout().setContentsMargins(0, 0, 0, 0)
        lay.addRow(self.alternativesBox)
        self.keepAnyway = QtWidgets.QCheckBox(translate("HoleFill", "Keep a fill that reaches no tier"))
        self.keepAnyway.setToolTip(translate("HoleFill", "OK keeps a fill that meets none of G0, G1, G2 only when this is ticked; "
                                             "it is marked with a warning sign in the tree"))
        self.keepAnyway.hide()
        lay.addRow(self.keepAnyway)
        self.report = QtWidgets.QPlainTextEdit()
        self.report.setReadOnly(True)
        self.report.setMinimumHeight(140)
        lay.addRow(self.report)
        self.useSel.clicked.connect(self.takeSelection)
        self.addPoints.clicked.connect(self.takePoints)
        self.clearPoints.clicked.connect(lambda: self.setPoints([]))
        self.preview.clicked.connect(self.runPreview)
        self.showProjection.toggled.connect(self.updateProjection)

        self.source, self.edges = None, []
        self.hole = None      # HoleFill.PreparedHole of (source, edges), made at the first Preview
        self.previewed = None  # (options, face, report) of the last Preview
        if existing is not None:
            self.source, self.edges = existing.Source[0], list(existing.Source[1])
            self.method.setCurrentText(existing.Method)
            self.continuity.setCurrentText(existing.Continuity)
            self.tolerance.setValue(float(existing.Tolerance))
            self.output.setCurrentText(existing.Output)
            self.setPoints([(p.x, p.y, p.z) for p in getattr(existing, "Points", [])])
        else:
            # A new fill starts from the user's preferences (Edit → Preferences → HoleFill).
            self.method.setCurrentText(preferences.get("FillMethod"))
            self.continuity.setCurrentText(preferences.get("FillContinuity"))
            self.tolerance.setValue(preferences.get("FillTolerance"))
            self.output.setCurrentText(preferences.get("FillOutput"))
            self.takeSelection()
            self.setPoints([])
        self.showHole()
        if existing is not None:
            asked = fill_feature.edgeContinuityDict(getattr(existing, "EdgeContinuity", []))
            for row in range(self.edgeTable.rowCount()):
                name = self.edgeTable.item(row, 0).text()
                if name in asked:
                    self.edgeTable.cellWidget(row, 1).setCurrentText(asked[name])
            if existing.Report:
                self.showReport(json.loads(existing.Report))
                # Kept on purpose once (it reaches no tier): an edit that changes nothing keeps it.
                self.keepAnyway.setChecked(existing.Achieved == "none")

    def setPoints(self, points):
        """The points to pass through, listed in the panel and drawn as dots."""
        self.points = [tuple(p) for p in points]
        self.pointsLabel.setText(translate("HoleFill", "%d points") % len(self.points) if self.points else
                                 translate("HoleFill", "none (select vertices, then Add selected)"))
        scene_overlay.remove(POINTS)
        if self.points and FreeCAD.GuiUp and FreeCADGui.ActiveDocument is not None:
            root = scene_overlay.placed_root(POINTS, FreeCAD.Placement())  # global coordinates
            root.addChild(scene_overlay.points_node(POINTS + "_dots", self.points, COLOR_POINTS, 9))
            scene_overlay.show(root)

    def takePoints(self):
        """Adds the selected vertices (global coordinates; a vertex-only object's vertices when the
        object itself is selected, as a Draft point) to the points to pass through."""
        found = []
        for sel in FreeCADGui.Selection.getSelectionEx():
            vertices = [v for v in sel.SubObjects if v.ShapeType == "Vertex"]
            shape = getattr(sel.Object, "Shape", None)
            if not sel.SubObjects and shape is not None and not shape.isNull() and not shape.Edges:
                vertices = shape.Vertexes
            found += [(v.Point.x, v.Point.y, v.Point.z) for v in vertices]
        if not found:
            self.report.setPlainText(translate("HoleFill", "No vertex is selected: select vertices (or Draft points) inside the hole, "
                                               "then press Add selected."))
            return
        self.setPoints(self.points + [p for p in found if p not in self.points])

    def takeSelection(self):
        src, edges = _selectedHole()
        if src is not None:
            self.source, self.edges = src, edges
        self.showHole()
        if hasattr(self, "showProjection") and self.showProjection.isChecked():
            self.updateProjection()

    def showHole(self):
        if self.source is None:
            instead = _selectedInstead()
            if instead:
                # A face or a whole object picked: the hole is where a face is missing, so its
                # boundary edges are what to pick.
                self.holeLabel.setText(translate("HoleFill", "%s is selected, not an edge: a hole is where a face is missing; select "
                                                 "one edge of its boundary in the 3D view, then press 'Use selected edges'.") % instead)
            else:
                self.holeLabel.setText(translate("HoleFill", "Select one edge of a hole in the 3D view, then press 'Use selected edges'."))
            return
        try:
            holes = HoleFill.findHoles(self.source.Shape, includeOuter=True)
            idx = {int(e[4:]) for e in self.edges}
            hole = next((h for h in holes if idx <= set(h["edge_indices"])), None)
        except HoleFill.HoleFillError as e:
            hole = None
            self.report.setPlainText(str(e))
        if hole is None:
            self.holeLabel.setText(translate("HoleFill", "%s: %s is not on one hole loop") % (self.source.Label, ", ".join(self.edges)))
            self.edgeTable.setRowCount(0)
            scene_overlay.remove(LOOP)
        elif hole.get("opening_loops"):
            # A band-shaped opening: the fill refuses it, so say so before any Preview.
            self.holeLabel.setText(translate("HoleFill", "%s: this opening has %d boundary loops (%s and %s): a face with one loop "
                                             "would cap one over the other; build a face bounded by all of them instead") % (
                self.source.Label, 1 + len(hole["opening_loops"]), ", ".join(hole["edges"]),
                " and ".join(", ".join(loop) for loop in hole["opening_loops"])))
            self.edgeTable.setRowCount(0)
            self.drawLoop(hole["edges"] + [e for loop in hole["opening_loops"] for e in loop])
        else:
            self.drawLoop(hole["edges"])
            self.holeLabel.setText(translate("HoleFill", "%s: %d-sided hole, %d edges (%s)") % (
                self.source.Label, hole["corners"], len(hole["edges"]), ", ".join(hole["edges"])))
            if [self.edgeTable.item(r, 0).text() for r in range(self.edgeTable.rowCount())] != hole["edges"]:
                self.edgeTable.setRowCount(len(hole["edges"]))
                for row, name in enumerate(hole["edges"]):
                    item = QtWidgets.QTableWidgetItem(name)
                    item.setFlags(item.flags() & ~QtCore.Qt.ItemIsEditable)
                    self.edgeTable.setItem(row, 0, item)
                    ask = QtWidgets.QComboBox()
                    ask.addItems(list(EDGE_CHOICES))
                    self.edgeTable.setCellWidget(row, 1, ask)
                    self.edgeTable.setItem(row, 2, QtWidgets.QTableWidgetItem(""))

    def drawLoop(self, edges, report=None):
        """The hole's loop over the model: in one colour before a Preview; after it, the edges that
        reach what they were asked in another and those that miss it in red (report given)."""
        scene_overlay.remove(LOOP)
        if not FreeCAD.GuiUp or FreeCADGui.ActiveDocument is None or self.source is None:
            return
        missed = {"Edge%d" % e["edge"] for e in (report or {}).get("edge_continuity", []) if _missed(e)}
        groups = {}
        for name in edges:
            edge = self.source.Shape.getElement(name)
            color = COLOR_LOOP if report is None else (COLOR_MISSED if name in missed else COLOR_MET)
            deflection = 0.002 * max(edge.BoundBox.DiagonalLength, 1e-9)
            groups.setdefault(color, []).append([(p.x, p.y, p.z) for p in edge.discretize(Deflection=deflection)])
        root = scene_overlay.placed_root(LOOP, self.placement())
        for k, (color, lines) in enumerate(sorted(groups.items())):
            root.addChild(scene_overlay.polyline_node("%s_%d" % (LOOP, k), lines, color, 5 if color == COLOR_MISSED else 4))
        scene_overlay.show(root)

    def placement(self):
        return scene_overlay.shape_placement(self.source)

    def edgeRequests(self):
        """The Ask column as EdgeContinuity entries (["Edge5=G0", ...]; auto rows are left out)."""
        out = []
        for row in range(self.edgeTable.rowCount()):
            ask = self.edgeTable.cellWidget(row, 1).currentText()
            if ask != "auto":
                out.append("%s=%s" % (self.edgeTable.item(row, 0).text(), ask))
        return out

    def showReport(self, report):
        self.report.setPlainText(formatReport(report))
        self.showVerdict(report)
        if report.get("edges"):
            self.drawLoop(["Edge%d" % e for e in report["edges"]], report)
        per = {"Edge%d" % e["edge"]: e for e in report.get("edge_continuity", [])}
        for row in range(self.edgeTable.rowCount()):
            e = per.get(self.edgeTable.item(row, 0).text())
            item = QtWidgets.QTableWidgetItem("" if e is None else "%s→%s" % (e["asked"], e["reached"]))
            if e is not None:
                item.setToolTip(translate("HoleFill", "asked %s (%s), reached %s") % (e["asked"], e["source"], e["reached"]))
                if _missed(e):
                    item.setForeground(QtGui.QBrush(QtGui.QColor(176, 0, 0)))
            self.edgeTable.setItem(row, 2, item)

    def showVerdict(self, report, alternatives=None):
        """Above the report: a fill that reaches no tier said in words (how far its patch spans past
        the hole, the edges that miss, in red in the 3D view), what else reached one (a button
        each, which previews it), and that OK keeps it only when 'Keep' is ticked."""
        for child in self.alternativesBox.findChildren(QtWidgets.QPushButton):
            child.setParent(None)
        none = report["achieved"] == "none"
        self.keepAnyway.setVisible(none)
        if not none:
            self.keepAnyway.setChecked(False)
            short = TIERS.index(report["achieved"]) < TIERS.index(report["requested"])
            self.verdict.setVisible(short)
            self.verdict.setStyleSheet("")
            self.verdict.setText(translate("HoleFill", "Reached %s of the %s asked; the edges in red miss it.") % (
                report["achieved"], report["requested"]) if short else "")
            return
        missed = ["Edge%d" % e["edge"] for e in report.get("edge_continuity", []) if _missed(e)]
        text = translate("HoleFill", "No continuity tier reached (%s asked); the edges in red miss (%s).") % (
            report["requested"], ", ".join(missed) or "-")
        # Which tier and by how much: a gap along the loop over the strict G0 tolerance (1e-6 of the
        # hole by default) leaves no tier even where the tangents meet.
        worst = max(report.get("per_edge", []), key=lambda e: e["g0"], default=None)
        tolerance = report.get("g0_tolerance", 0)
        if worst is not None and tolerance > 0 and worst["g0"] > tolerance:
            text += " " + translate("HoleFill", "The gap along Edge%d is %.2g, %.0f times the G0 tolerance %.2g") % (
                worst["edge"], worst["g0"], worst["g0"] / tolerance, tolerance)
            bent = max((e["g1"] for e in report.get("per_edge", []) if "Edge%d" % e["edge"] in missed), default=0.0)
            text += translate("HoleFill", "; the normals there meet within %.1e rad.") % bent
        if report.get("str", {}).get("g0_loose"):
            text += " " + translate("HoleFill", "It still sews within the model's edge tolerances.")
        if alternatives:
            text += " " + translate("HoleFill", "These reach a tier:")
            for a in alternatives[:3]:
                b = QtWidgets.QPushButton(translate("HoleFill", "Use %s at %s: %s, gap %.1g") % (
                    a["method"], a["continuity"], a["achieved"], a["g0"]))
                b.setToolTip(translate("HoleFill", "Preview the %s parameterization at %s: it reaches %s, with a largest gap of %.3g "
                                       "along the loop and normals within %.2g rad") % (a["method"], a["continuity"], a["achieved"], a["g0"], a["g1"]))
                b.setObjectName("HoleFillFillAlternative")
                b.clicked.connect(lambda checked=False, a=a: self.useAlternative(a))
                self.alternativesBox.layout().addWidget(b)
        elif alternatives is not None:
            text += " " + translate("HoleFill", "No other method or lower continuity reaches one either: check the hole's edges.")
        text += " " + translate("HoleFill", "OK keeps it only with 'Keep a fill that reaches no tier' ticked.")
        self.verdict.setText(text)
        self.verdict.setStyleSheet("QLabel { color: #b00000; font-weight: bold; }")
        self.verdict.show()

    def useAlternative(self, alternative):
        self.method.setCurrentText(alternative["method"])
        self.continuity.setCurrentText(alternative["continuity"])
        self.runPreview()

    def updateProjection(self, *args):
        from HoleFillGui import projection_overlay
        projection_overlay.hide()
        if not self.showProjection.isChecked() or self.source is None:
            return
        try:
            face = HoleFill.projectionSurface(self.source.Shape, self.edges,
                                              self.obj.Weights if self.obj is not None else preferences.get("UvtranWeights"))
        except HoleFill.HoleFillError as e:
            self.report.setPlainText(translate("HoleFill", "No projection surface: %s") % e)
            return
        projection_overlay.show(face)

    def options(self):
        """The panel's settings as fillHole's keywords (weights: the edited Fill's, or the preferences')."""
        return dict(method=self.method.currentText(), continuity=self.continuity.currentText(), tolerance=self.tolerance.value(),
                    angularTolerance=self.obj.AngularTolerance if self.obj is not None else preferences.get("FillAngularTolerance"),
                    edgeContinuity=fill_feature.edgeContinuityDict(self.edgeRequests()),
                    weights=self.obj.Weights if self.obj is not None else preferences.get("UvtranWeights"),
                    points=list(self.points))

    def prepared(self):
        """The hole of the current source and edges, read and found once."""
        if self.hole is None or not self.hole.isFor(self.source.Shape, self.edges):
            self.hole = HoleFill.prepareHole(self.source.Shape, self.edges)
        return self.hole

    def runPreview(self):
        """Fills the hole with the panel's settings and shows the face over the model (nothing is
        added to the document); False, with the reason in the report, when it cannot."""
        scene_overlay.remove(OVERLAY)
        if self.source is None:
            self.report.setPlainText(translate("HoleFill", "No hole selected: click an edge of the hole first."))
            return False
        options, output = self.options(), self.output.currentText()
        try:
            # Sewn as the Fill will be, so that OK's recompute finds this very fill kept.
            with task_dialog.progress_dialog(translate("HoleFill", "Filling hole..."), self.form) as progress:
                face, _, report = self.prepared().fill(progress=progress, sewn=output == "Sewn", **options)
        except HoleFill.HoleFillError as e:
            self.previewed = None
            self.report.setPlainText(task_dialog.failed(translate("HoleFill", "Fill"), e))
            return False
        self.previewed = ((options, output), face, report)
        self.showReport(report)
        if report["achieved"] == "none":
            # What reaches a tier instead, measured on the same prepared hole (the other methods,
            # then lower continuities), with progress and Cancel.
            others = {k: v for k, v in options.items() if k not in ("method", "continuity")}
            with task_dialog.progress_dialog(translate("HoleFill", "Trying other methods..."), self.form) as progress:
                found = self.prepared().alternatives(options["method"], options["continuity"], progress=progress, **others)
            self.showVerdict(report, found)
        root = scene_overlay.placed_root(OVERLAY, self.placement())
        root.addChild(scene_overlay.face_node(face, OVERLAY + "Face", (0.95, 0.62, 0.20), 0.15))
        scene_overlay.show(root)
        return True

    def accept(self):
        if self.previewed is None or self.previewed[0] != (self.options(), self.output.currentText()):
            if not self.runPreview():
                return False  # keep the panel open: the report says what went wrong
        if self.previewed[2]["achieved"] == "none" and not self.keepAnyway.isChecked():
            # A plain OK never keeps a fill that reaches no tier (its patch may bulge far past
            # the hole): the panel stays open with what else works.
            self.verdict.setText(self.verdict.text() + "\n" + translate("HoleFill", "Not kept: choose one of the fills above, or tick 'Keep a fill that reaches no tier'."))
            return False
        options, output = self.previewed[0]
        if self.obj is None:
            obj = task_dialog.create(_Status(self.report), lambda: fill_feature.makeFill(
                self.source, self.edges, output=output, prepared=self.prepared(), **options))
        else:
            obj = task_dialog.create(_Status(self.report), lambda: fill_feature.changeFill(
                self.obj, self.source, self.edges, output=output, prepared=self.prepared(), **options))
        if obj is None:
            return False
        if output == "Sewn" and self.source.ViewObject is not None:
            self.source.ViewObject.Visibility = False
        self.close()
        return True

    def release(self):
        from HoleFillGui import projection_overlay
        projection_overlay.hide()
        scene_overlay.remove(LOOP)
        scene_overlay.remove(POINTS)
        task_dialog.Panel.release(self)
