"""Task panel of "Fill mesh holes": lists the holes of the selected mesh (boundary vertices,
length, why a hole cannot be filled), draws every hole's boundary in the 3D view (holes to fill
in orange, the others in grey, the rows selected in the table in red and thicker); Preview fills
the checked holes without touching the document, draws the new triangles (orange, or coloured by
their quality on request) and says in the panel what was filled, which holes were filled again
plainer because their first patch crossed the surface (and which still cross), and whether the
result is still open, with each open hole's reason. Where the mesh has coincident vertices (the seams of an
exported scan), "Merge coincident vertices first" lists and fills the holes of the mesh with
them merged, so that a seam is no hole. OK fills the checked holes into a new mesh object
(HoleFill.makeMeshFill, one undo step). The source mesh is never modified; Cancel leaves the
document as it was."""
import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from HoleFillGui import SelectionError, scene_overlay, task_dialog

translate = FreeCAD.Qt.translate

OVERLAY = "HoleFillMeshHoles"
COLOR_FILL, COLOR_SKIP, COLOR_PICKED = (1.0, 0.55, 0.1), (0.55, 0.55, 0.55), (0.9, 0.0, 0.0)


# Shape choices of the panel: label, options for HoleFill.fillMeshHoles.
SHAPES = (("Ours (minimum angle, minimum-variation placement, quality passes)", {}),
          ("Ours, triangulated by the hole (minimum dihedral away from creases)", {"triangulation": "auto"}),
          ("The paper's pipeline exactly (Hu et al.: flat placement, no quality passes)", {"mode": "paper"}))


def mesh_from_selection():
    sel = FreeCADGui.Selection.getSelection()
    meshes = [o for o in sel if o.isDerivedFrom("Mesh::Feature")]
    if len(meshes) != 1:
        raise SelectionError(translate("HoleFill", "Select one mesh object (a Mesh feature, e.g. an imported STL/OBJ/PLY/OFF), "
                             "then run Fill mesh holes.") + (translate("HoleFill", " The selection holds no mesh.") if sel and not meshes else ""))
    return meshes[0]


def remove_overlay():
    scene_overlay.remove(OVERLAY)


def holeSize(hole):
    """The diagonal of the box around a hole's boundary points (model units)."""
    import math
    pts = hole["points"]
    return math.dist([min(p[i] for p in pts) for i in range(3)], [max(p[i] for p in pts) for i in range(3)])


def newTriangles(source, filled, report):
    """The triangles of `filled` (fillMeshHoles' result for `source`, with its `report`) that
    `source` does not have, as point triples: the core keeps the input's triangles first and in
    order (less those a weld dropped), and adds after them."""
    pts, facets = filled.Topology
    kept = source.CountFacets - report.get("dropped_triangles", 0)
    return [tuple((pts[i].x, pts[i].y, pts[i].z) for i in f) for f in facets[kept:]]


def triangleQuality(t):
    """2·r_in/R_circ of a triangle given as three points: 1 equilateral, 0 degenerate."""
    import math
    a, b, c = (math.dist(t[1], t[2]), math.dist(t[0], t[2]), math.dist(t[0], t[1]))
    s = 0.5 * (a + b + c)
    area2 = max(0.0, s * (s - a) * (s - b) * (s - c))
    if area2 <= 0 or a * b * c <= 0:
        return 0.0
    return 8.0 * area2 / (a * b * c * s)


def qualityColor(q):
    """Red at 0 through orange (0.5) and cyan (0.8) to blue at 1: the tiers' colours (scene_overlay.TIER_COLORS)."""
    tier = scene_overlay.TIER_COLORS
    stops = ((0.0, tier["none"]), (0.5, tier["G0"]), (0.8, tier["G1"]), (1.0, tier["G2"]))
    q = min(1.0, max(0.0, q))
    for (q0, c0), (q1, c1) in zip(stops, stops[1:]):
        if q <= q1:
            f = (q - q0) / (q1 - q0)
            return tuple(a + f * (b - a) for a, b in zip(c0, c1))
    return stops[-1][1]


class MeshFillPanel(task_dialog.Panel):
    overlay = OVERLAY

    def __init__(self, obj):
        import HoleFill
        self.obj = obj
        self.holes = []
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("HoleFill", "Fill mesh holes"))
        layout = QtWidgets.QVBoxLayout(self.form)
        self.summary = QtWidgets.QLabel()
        self.summary.setWordWrap(True)
        layout.addWidget(self.summary)
        # Seams of duplicated vertices read as holes running side by side (CGAL's elephant: 171
        # loops); merged, only the holes the surface has are left. Offered, not done unasked:
        # the result's vertices are then renumbered.
        self.coincident, _ = HoleFill.weldVertices(obj.Mesh, HoleFill.SEAM_WELD, counts=True)
        self.weld = QtWidgets.QCheckBox(translate("HoleFill", "Merge coincident vertices first (%d)") % self.coincident)
        self.weld.setObjectName("HoleFillMeshWeld")
        self.weld.setEnabled(self.coincident > 0)
        self.weld.setToolTip(translate("HoleFill", "%d vertices lie on another one (within %g of the mesh's size), e.g. along the seams\n"
                                       "of an exported scan, where the surface reads as two borders side by side. Checked:\n"
                                       "the holes of the mesh with them merged are listed and filled, and the new mesh has\n"
                                       "them merged; the source mesh is not changed.") % (self.coincident, HoleFill.SEAM_WELD))
        layout.addWidget(self.weld)
        self.table = QtWidgets.QTableWidget(0, 4)
        self.table.setObjectName("HoleFillMeshHoleTable")
        self.table.setHorizontalHeaderLabels([translate("HoleFill", "Hole"), translate("HoleFill", "Vertices"), translate("HoleFill", "Length"), translate("HoleFill", "Note")])
        self.table.setSelectionBehavior(QtWidgets.QAbstractItemView.SelectRows)
        self.table.verticalHeader().setVisible(False)
        layout.addWidget(self.table)
        shape_row = QtWidgets.QHBoxLayout()
        self.shape = QtWidgets.QComboBox()
        self.shape.setObjectName("HoleFillMeshFillShape")
        for label, _ in SHAPES:
            self.shape.addItem(label)
        self.shape.setToolTip(translate("HoleFill", "Ours: minimum-angle triangulation, refinement, quality passes and a minimum-variation\n"
                              "placement (closest to the cut-away surface on the mesh-hole corpus); the same with the\n"
                              "triangulation chosen per hole; or Hu et al.'s pipeline exactly (flat placement, bilateral filter)"))
        shape_row.addWidget(QtWidgets.QLabel(translate("HoleFill", "Shape")))
        shape_row.addWidget(self.shape)
        layout.addLayout(shape_row)
        row = QtWidgets.QHBoxLayout()
        self.maxBoundary = QtWidgets.QSpinBox()
        self.maxBoundary.setObjectName("HoleFillMaxBoundary")
        self.maxBoundary.setRange(0, 10000000)
        self.maxBoundary.setSpecialValueText(translate("HoleFill", "no limit"))
        self.maxBoundary.setValue(HoleFill.defaultMaxBoundary())
        self.maxBoundary.setToolTip(translate("HoleFill", "Uncheck holes with more boundary vertices than this (e.g. the border of an open scan);\n"
                                    "a checked hole past it stays open. The fill's time grows faster than the boundary:\n"
                                    "about 2 s for 5,000 vertices, a minute for 20,000"))
        row.addWidget(QtWidgets.QLabel(translate("HoleFill", "Max boundary vertices")))
        row.addWidget(self.maxBoundary)
        layout.addLayout(row)
        # MeshLab's hole-size limit, by the hole's size in model units: a scan's small holes are
        # closed, its open border and large gaps left.
        size_row = QtWidgets.QHBoxLayout()
        self.maxSize = QtWidgets.QDoubleSpinBox()
        self.maxSize.setObjectName("HoleFillMaxHoleSize")
        self.maxSize.setDecimals(4)
        self.maxSize.setRange(0.0, 1e9)
        self.maxSize.setSpecialValueText(translate("HoleFill", "no limit"))
        self.maxSize.setToolTip(translate("HoleFill", "Uncheck holes larger than this (the diagonal of the box around the hole's boundary, "
                                          "model units)"))
        size_row.addWidget(QtWidgets.QLabel(translate("HoleFill", "Max hole size")))
        size_row.addWidget(self.maxSize)
        layout.addLayout(size_row)
        self.byQuality = QtWidgets.QCheckBox(translate("HoleFill", "Colour new triangles by quality"))
        self.byQuality.setObjectName("HoleFillMeshByQuality")
        self.byQuality.setToolTip(translate("HoleFill", "Each new triangle by its quality 2·r_in/R_circ: red at 0 (a sliver) through\n"
                                            "orange and cyan to blue at 1 (equilateral)"))
        layout.addWidget(self.byQuality)
        layout.addWidget(task_dialog.button(translate("HoleFill", "Preview"), "HoleFillMeshPreview", self.preview))
        self.status = QtWidgets.QLabel()
        self.status.setObjectName("HoleFillMeshStatus")
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        self.previewed = None  # (settings, (filled Mesh.Mesh, report), new triangles' points) of the last Preview
        self.byQuality.toggled.connect(lambda *_: self.drawPreview())
        self.listHoles()
        self.table.itemChanged.connect(lambda *_: self.redraw())
        self.table.itemSelectionChanged.connect(self.redraw)
        self.weld.toggled.connect(lambda *_: self.listHoles())
        for limit in (self.maxBoundary, self.maxSize):
            limit.setKeyboardTracking(False)  # typed values apply when complete, not per keystroke
            limit.valueChanged.connect(lambda *_: self.applyLimits())
        self.redraw()

    def weldValue(self):
        import HoleFill
        return HoleFill.SEAM_WELD if self.weld.isChecked() else 0.0

    def listHoles(self):
        """The table of the holes of the mesh as it is or, checked, with coincident vertices merged."""
        import HoleFill
        self.holes = HoleFill.meshHoles(self.obj.Mesh, weld=self.weldValue())
        fillable = [hh for hh in self.holes if hh["fillable"]]
        merged = translate("HoleFill", " (coincident vertices merged)") if self.weld.isChecked() else ""
        self.summary.setText(translate("HoleFill", "%s%s: %d holes, %d fillable. Check the holes to fill.") % (
            self.obj.Label, merged, len(self.holes), len(fillable)) if self.holes else
            translate("HoleFill", "%s%s has no holes: it is closed.") % (self.obj.Label, merged))
        blocked = self.table.blockSignals(True)
        self.table.clearContents()
        self.table.setRowCount(len(self.holes))
        for r, hole in enumerate(self.holes):
            item = QtWidgets.QTableWidgetItem(str(hole["index"]))
            item.setFlags(QtCore.Qt.ItemIsUserCheckable | QtCore.Qt.ItemIsSelectable |
                          (QtCore.Qt.ItemIsEnabled if hole["fillable"] else QtCore.Qt.NoItemFlags))
            item.setCheckState(QtCore.Qt.Checked if hole["fillable"] else QtCore.Qt.Unchecked)
            self.table.setItem(r, 0, item)
            for c, text in ((1, str(hole["boundaryVertices"])), (2, "%.6g" % hole["length"]), (3, hole["message"])):
                cell = QtWidgets.QTableWidgetItem(text)
                cell.setFlags(QtCore.Qt.ItemIsSelectable | QtCore.Qt.ItemIsEnabled)
                self.table.setItem(r, c, cell)
        self.table.resizeColumnsToContents()
        self.applyLimits()
        self.table.blockSignals(blocked)
        self.redraw()

    def checked(self):
        return [self.holes[r]["index"] for r in range(self.table.rowCount())
                if self.table.item(r, 0).checkState() == QtCore.Qt.Checked]

    def applyLimits(self):
        """Checks the fillable holes within both limits (boundary vertices, size), unchecks the rest."""
        limit, size = self.maxBoundary.value(), self.maxSize.value()
        for r, hole in enumerate(self.holes):
            if hole["fillable"]:
                over = (limit > 0 and hole["boundaryVertices"] > limit) or (size > 0 and holeSize(hole) > size)
                self.table.item(r, 0).setCheckState(QtCore.Qt.Unchecked if over else QtCore.Qt.Checked)

    def preview(self):
        """Fills the checked holes as OK would, into nothing: the new triangles drawn over the mesh
        and, in the panel, what was filled and what stays open, and why."""
        import HoleFill
        self.redraw()
        if not self.checked():
            self.status.setText(translate("HoleFill", "No hole is checked: check the holes to fill."))
            return False
        try:
            with task_dialog.progress_dialog(translate("HoleFill", "Filling mesh holes..."), self.form) as progress:
                filled, rep = HoleFill.fillMeshHoles(self.obj.Mesh, holes=self.checked(), maxBoundary=self.maxBoundary.value(),
                                                     weld=self.weldValue(), progress=progress, **SHAPES[self.shape.currentIndex()][1])
        except HoleFill.HoleFillError as e:
            self.status.setText(task_dialog.failed(translate("HoleFill", "Preview"), e))
            return False
        self.previewed = (self.settings(), (filled, rep), newTriangles(self.obj.Mesh, filled, rep))
        self.drawPreview()
        done = [f for f in rep["hole_fills"] if f["filled"]]
        text = translate("HoleFill", "Preview: %d of %d checked holes filled, %d new triangles (quality mean %.2f, worst %.2f).") % (
            len(done), len(self.checked()), len(self.previewed[2]),
            sum(f["mean_quality"] * f["new_triangles"] for f in done) / max(1, sum(f["new_triangles"] for f in done)),
            min((f["min_quality"] for f in done), default=0.0))
        refilled = ["%d (%s)" % (f["hole"], f["fallback"]) for f in done if f.get("fallback")]
        if refilled:
            text += " " + translate("HoleFill", "Filled again plainer where the first patch crossed itself or the surface: %s.") % (
                "; ".join(refilled[:3]) + ("; ..." if len(refilled) > 3 else ""))
        crossing = [str(f["hole"]) for f in done if f.get("crossings")]
        if crossing:
            text += " " + translate("HoleFill", "Still crossing the surface: holes %s (uncheck them, or repair the mesh around them).") % (
                ", ".join(crossing[:8]) + (", ..." if len(crossing) > 8 else ""))
        if rep["closed"]:
            text += " " + translate("HoleFill", "The result is closed.")
        else:
            stay = ["%d (%s)" % (f["hole"], f["message"]) if f["message"] else str(f["hole"]) for f in rep["hole_fills"] if not f["filled"]]
            text += " " + translate("HoleFill", "The result is still open; holes left open: %s.") % (
                "; ".join(stay[:5]) + ("; ..." if len(stay) > 5 else "") if stay else str(rep["open"]))
            if rep.get("closed_when_welded") and not self.weld.isChecked():
                text += " " + translate("HoleFill", "It closes when coincident vertices are merged: check 'Merge coincident vertices first'.")
        self.status.setText(text)
        return True

    def drawPreview(self):
        """The last Preview's new triangles over the mesh, orange or by quality."""
        from pivy import coin
        scene_overlay.remove("%sPreview" % OVERLAY)
        if self.previewed is None or not self.previewed[2]:
            return
        tris = self.previewed[2]
        root = scene_overlay.placed_root("%sPreview_%s" % (OVERLAY, self.obj.Name), self.obj.Placement)
        mat = coin.SoMaterial()
        bind = coin.SoMaterialBinding()
        if self.byQuality.isChecked():
            mat.diffuseColor.setValues(0, len(tris), [qualityColor(triangleQuality(t)) for t in tris])
            bind.value = coin.SoMaterialBinding.PER_FACE
        else:
            mat.diffuseColor.setValue(*COLOR_FILL)
        hints = coin.SoShapeHints()
        hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
        coords = coin.SoCoordinate3()
        coords.point.setValues(0, 3 * len(tris), [list(p) for t in tris for p in t])
        faces = coin.SoFaceSet()
        faces.numVertices.setValues(0, len(tris), [3] * len(tris))
        for n in (hints, mat, bind, coords, faces):
            root.addChild(n)
        scene_overlay.show(root)

    def redraw(self):
        """Boundary loops as line sets under one named separator, placed like the mesh object."""
        from pivy import coin
        remove_overlay()
        self.previewed = None  # the holes to fill changed: the last Preview no longer says what OK makes
        picked = {i.row() for i in self.table.selectedIndexes()}
        checked = set(self.checked())
        root = scene_overlay.placed_root("%s_%s" % (OVERLAY, self.obj.Name), self.obj.Placement)
        for r, hole in enumerate(self.holes):
            sep = coin.SoSeparator()
            sep.setName("%s_hole%d" % (OVERLAY, hole["index"]))
            mat = coin.SoBaseColor()
            color = COLOR_PICKED if r in picked else (COLOR_FILL if hole["index"] in checked else COLOR_SKIP)
            mat.rgb.setValue(*color)
            style = coin.SoDrawStyle()
            style.lineWidth = 5 if r in picked else 3
            coords = coin.SoCoordinate3()
            pts = list(hole["points"]) + [hole["points"][0]]
            coords.point.setValues(0, len(pts), [list(p) for p in pts])
            lines = coin.SoLineSet()
            lines.numVertices.setValue(len(pts))
            for n in (mat, style, coords, lines):
                sep.addChild(n)
            root.addChild(sep)
        scene_overlay.show(root)
        self.status.setText(translate("HoleFill", "%d of %d holes will be filled into a new mesh object.") % (len(checked), len(self.holes)))

    # -- dialog (task_dialog.Panel) --------------------------------------------------------------
    def accept(self):
        if not self.checked():
            self.status.setText(translate("HoleFill", "No hole is checked: check the holes to fill, or Cancel."))
            return False
        return task_dialog.Panel.accept(self)

    def settings(self):
        """What a fill of this panel depends on: the holes checked, the boundary limit, the shape, the weld."""
        return (tuple(self.checked()), self.maxBoundary.value(), self.shape.currentIndex(), self.weldValue())

    def make(self):
        import HoleFill
        # The last Preview's fill, when nothing it depends on changed since: not filled again.
        kept = self.previewed[1] if self.previewed is not None and self.previewed[0] == self.settings() else None
        return HoleFill.makeMeshFill(self.obj, holes=self.checked(), maxBoundary=self.maxBoundary.value(), filled=kept,
                                     weld=self.weldValue(), **SHAPES[self.shape.currentIndex()][1])

    def made(self, feature):
        import json
        rep = json.loads(feature.HoleFillReport)
        return "HoleFill: filled %d of %d holes of %s into %s (%s), %.3f s" % (
            rep["filled"], rep["holes"], self.obj.Label, feature.Label, "closed" if rep["closed"] else "still open", rep["seconds"])
