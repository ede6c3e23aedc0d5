"""Task panel of "Fill mesh holes": lists the holes of the selected mesh (boundary vertices,
length, why a hole cannot be filled), draws every hole's boundary in the 3D view (holes to fill
in orange, the others in grey, the rows selected in the table in red and thicker), and on OK
fills the checked holes into a new mesh object (HoleFill.makeMeshFill, one undo step). The
source mesh is never modified; Cancel leaves the document as it was."""
import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from HoleFillGui import SelectionError, scene_overlay, task_dialog

translate = FreeCAD.Qt.translate

OVERLAY = "HoleFillMeshHoles"
COLOR_FILL, COLOR_SKIP, COLOR_PICKED = (1.0, 0.55, 0.1), (0.55, 0.55, 0.55), (0.9, 0.0, 0.0)


# Shape choices of the panel: label, options for HoleFill.fillMeshHoles.
SHAPES = (("Paper (minimum angle, thin plate, bilateral filter)", {}),
          ("Closest to the surface (auto triangulation, C2, no bilateral)",
           {"shapeOrder": 3, "fairIterations": 0, "triangulation": "auto"}))


def mesh_from_selection():
    sel = FreeCADGui.Selection.getSelection()
    meshes = [o for o in sel if o.isDerivedFrom("Mesh::Feature")]
    if len(meshes) != 1:
        raise SelectionError(translate("HoleFill", "Select one mesh object (a Mesh feature, e.g. an imported STL/OBJ/PLY/OFF), "
                             "then run Fill mesh holes.") + (translate("HoleFill", " The selection holds no mesh.") if sel and not meshes else ""))
    return meshes[0]


def remove_overlay():
    scene_overlay.remove(OVERLAY)


class MeshFillPanel(task_dialog.Panel):
    overlay = OVERLAY

    def __init__(self, obj):
        import HoleFill
        self.obj = obj
        self.holes = HoleFill.meshHoles(obj.Mesh)
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("HoleFill", "Fill mesh holes"))
        layout = QtWidgets.QVBoxLayout(self.form)
        fillable = [hh for hh in self.holes if hh["fillable"]]
        self.summary = QtWidgets.QLabel("%s: %d holes, %d fillable. Check the holes to fill." % (
            obj.Label, len(self.holes), len(fillable)) if self.holes else "%s has no holes: it is closed." % obj.Label)
        self.summary.setWordWrap(True)
        layout.addWidget(self.summary)
        self.table = QtWidgets.QTableWidget(len(self.holes), 4)
        self.table.setObjectName("HoleFillMeshHoleTable")
        self.table.setHorizontalHeaderLabels([translate("HoleFill", "Hole"), translate("HoleFill", "Vertices"), translate("HoleFill", "Length"), translate("HoleFill", "Note")])
        self.table.setSelectionBehavior(QtWidgets.QAbstractItemView.SelectRows)
        self.table.verticalHeader().setVisible(False)
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
        layout.addWidget(self.table)
        shape_row = QtWidgets.QHBoxLayout()
        self.shape = QtWidgets.QComboBox()
        self.shape.setObjectName("HoleFillMeshFillShape")
        for label, _ in SHAPES:
            self.shape.addItem(label)
        self.shape.setToolTip(translate("HoleFill", "Hu et al.'s pipeline (minimum-angle triangulation, thin-plate placement, 3 bilateral\n"
                              "iterations), or the variant that measured closest to the cut-away surface in the\n"
                              "benchmark (triangulation chosen per hole, smoother placement, no bilateral filter)"))
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
        self.status = QtWidgets.QLabel()
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        self.table.itemChanged.connect(lambda *_: self.redraw())
        self.table.itemSelectionChanged.connect(self.redraw)
        self.maxBoundary.setKeyboardTracking(False)  # typed values apply when complete, not per keystroke
        self.maxBoundary.valueChanged.connect(self.applyMaxBoundary)
        self.applyMaxBoundary(self.maxBoundary.value())
        self.redraw()

    def checked(self):
        return [self.holes[r]["index"] for r in range(self.table.rowCount())
                if self.table.item(r, 0).checkState() == QtCore.Qt.Checked]

    def applyMaxBoundary(self, limit):
        for r, hole in enumerate(self.holes):
            if hole["fillable"]:
                over = limit > 0 and hole["boundaryVertices"] > limit
                self.table.item(r, 0).setCheckState(QtCore.Qt.Unchecked if over else QtCore.Qt.Checked)

    def redraw(self):
        """Boundary loops as line sets under one named separator, placed like the mesh object."""
        from pivy import coin
        remove_overlay()
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

    def make(self):
        import HoleFill
        return HoleFill.makeMeshFill(self.obj, holes=self.checked(), maxBoundary=self.maxBoundary.value(), **SHAPES[self.shape.currentIndex()][1])

    def made(self, feature):
        import json
        rep = json.loads(feature.HoleFillReport)
        return "HoleFill: filled %d of %d holes of %s into %s (%s), %.3f s" % (
            rep["filled"], rep["holes"], self.obj.Label, feature.Label, "closed" if rep["closed"] else "still open", rep["seconds"])
