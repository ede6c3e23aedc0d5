"""Task panel of "Label boundary": the selected mesh region's outer boundary is drawn cut into
segments (at corners turning more than the corner angle, to start with, or at four corners with
one click), each in its label's colour with its letter, and arrows along it the way S, E, N, W
must follow each other (anticlockwise seen from the region's normal). Clicking near a boundary
edge in the 3D view (within a few pixels on screen) cycles that segment's label N → E → S → W →
none, and the keys N, E, S, W (or Delete: none) set the label of the segment clicked last;
clicking on a boundary vertex splits the segment there, or merges the two segments meeting at an
existing split. OK stores the labels on a BoundaryLabels document object
(one undo step), which labeled fits follow; the mesh is never modified and Cancel changes
nothing."""
import math

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from HoleFillGui import SelectionError, scene_overlay, task_dialog

translate = FreeCAD.Qt.translate

OVERLAY = "HoleFillLabels"
CYCLE = ["N", "E", "S", "W", "-"]


def mesh_from_selection():
    """(mesh feature, existing BoundaryLabels or None) from the selection."""
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) == 1 and hasattr(sel[0], "LabelsJson") and sel[0].Source is not None:
        return sel[0].Source, sel[0]
    meshes = [o for o in sel if hasattr(o, "Mesh") and hasattr(o.Mesh, "CountFacets")]
    if len(meshes) != 1:
        raise SelectionError(translate("HoleFill", "Select one mesh region (a Mesh object with an open boundary) to label its boundary.")
                             + (translate("HoleFill", " The selection holds no mesh.") if sel and not meshes else ""))
    return meshes[0], None


def remove_overlay():
    scene_overlay.remove(OVERLAY)


class LabelPanel(task_dialog.Panel):
    overlay = OVERLAY

    def __init__(self, meshObj, existing=None, cornerAngle=35.0):
        from HoleFill.labeled import boundaryLoop, cornerSplits
        self.obj = meshObj
        self.existing = existing
        self.loop, self.points = boundaryLoop(meshObj.Mesh)  # raises for a closed or empty mesh
        n = len(self.loop)
        self.edgeLength = sum(self._dist(self.points[k], self.points[(k + 1) % n]) for k in range(n)) / n
        if existing is not None and list(existing.Loop) == self.loop:
            self.splits = set(existing.Splits)
            starts = sorted(self.splits)
            self.labelAt = {s: l for s, l in zip(starts, existing.Labels)} if starts else {0: existing.Labels[0]}
        else:
            self.splits = set(cornerSplits(self.points, cornerAngle))
            self.labelAt = {}
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("HoleFill", "Label boundary"))
        layout = QtWidgets.QVBoxLayout(self.form)
        self.summary = QtWidgets.QLabel(translate("HoleFill", "%s: boundary of %d vertices.") % (meshObj.Label, n))
        self.summary.setWordWrap(True)
        layout.addWidget(self.summary)
        help = QtWidgets.QLabel(translate("HoleFill", "Click near a boundary edge to cycle its segment's label N → E → S → W → none. "
                                "Click on a boundary vertex to split a segment there, or on a split to merge. "
                                "Going anticlockwise around the region the labels must run S, E, N, W."))
        help.setWordWrap(True)
        layout.addWidget(help)
        self.segmentList = QtWidgets.QListWidget()
        self.segmentList.setObjectName("HoleFillLabelSegments")
        layout.addWidget(self.segmentList)
        row = QtWidgets.QHBoxLayout()
        row.addWidget(QtWidgets.QLabel(translate("HoleFill", "Corner angle (°):")))
        self.angle = QtWidgets.QDoubleSpinBox()
        self.angle.setObjectName("HoleFillLabelCornerAngle")
        self.angle.setRange(5, 175)
        self.angle.setValue(cornerAngle)
        row.addWidget(self.angle)
        layout.addLayout(row)
        layout.addWidget(task_dialog.button(translate("HoleFill", "Split at corners"), "HoleFillLabelResplit", self.splitAtCorners))
        four = task_dialog.button(translate("HoleFill", "Four corners (S, E, N, W)"), "HoleFillLabelFourCorners", self.setFourCorners)
        four.setToolTip(translate("HoleFill", "Split the boundary at the vertices nearest the corners of its smallest bounding rectangle "
                                  "and label the sides S, E, N, W anticlockwise: one click for a jagged scan boundary"))
        layout.addWidget(four)
        layout.addWidget(task_dialog.button(translate("HoleFill", "Clear labels"), "HoleFillLabelClear", self.clearLabels))
        self.status = task_dialog.status_line("HoleFillLabelStatus")
        layout.addWidget(self.status)
        from pivy import coin
        self.view = FreeCADGui.ActiveDocument.ActiveView
        self.callback = self.view.addEventCallbackPivy(coin.SoMouseButtonEvent.getClassTypeId(), self.onMouse)
        self.keys = self.view.addEventCallbackPivy(coin.SoKeyboardEvent.getClassTypeId(), self.onKey)
        self.current = None  # the start of the segment clicked last: the keys N, E, S, W label it
        self.normal = self._meanNormal()
        self.redraw()

    # -- geometry ----------------------------------------------------------------------------
    def _meanNormal(self):
        n = [0.0, 0.0, 0.0]
        for f in self.obj.Mesh.Facets:
            for i in range(3):
                n[i] += f.Normal[i] * f.Area
        return n

    def _anticlockwise(self):
        """Whether the loop runs anticlockwise seen from the region's normal (the way S, E, N, W go)."""
        c = [sum(p[i] for p in self.points) / len(self.points) for i in range(3)]
        total = 0.0
        for k in range(len(self.points)):
            a = [self.points[k][i] - c[i] for i in range(3)]
            b = [self.points[(k + 1) % len(self.points)][i] - c[i] for i in range(3)]
            cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
            total += sum(x * y for x, y in zip(cross, self.normal))
        return total > 0
    @staticmethod
    def _dist(a, b):
        return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))

    def _segmentDistance(self, p, a, b):
        d = [y - x for x, y in zip(a, b)]
        dd = sum(x * x for x in d)
        t = 0.0 if dd == 0 else max(0.0, min(1.0, sum((pp - x) * y for pp, x, y in zip(p, a, d)) / dd))
        return self._dist(p, [x + t * y for x, y in zip(a, d)])

    def segments(self):
        """[(start position, [loop positions])], in loop order."""
        from HoleFill.labeled import segmentsOf
        segs = segmentsOf(len(self.loop), self.splits)
        starts = sorted(self.splits) or [0]
        return list(zip(starts, segs))

    def labels(self):
        return [self.labelAt.get(s, "-") for s, _ in self.segments()]

    # -- clicks ------------------------------------------------------------------------------
    def onMouse(self, cb):
        from pivy import coin
        ev = cb.getEvent()
        if ev.getButton() != coin.SoMouseButtonEvent.BUTTON1 or ev.getState() != coin.SoButtonEvent.DOWN:
            return
        pos = tuple(ev.getPosition().getValue())
        QtCore.QTimer.singleShot(0, lambda: self.clickOnScreen(pos))

    def onKey(self, cb):
        from pivy import coin
        ev = cb.getEvent()
        if ev.getState() != coin.SoButtonEvent.DOWN or self.current is None:
            return
        keys = {coin.SoKeyboardEvent.N: "N", coin.SoKeyboardEvent.E: "E", coin.SoKeyboardEvent.S: "S", coin.SoKeyboardEvent.W: "W",
                coin.SoKeyboardEvent.DELETE: "-", coin.SoKeyboardEvent.BACKSPACE: "-"}
        label = keys.get(ev.getKey())
        if label is None:
            return
        cb.setHandled()  # the view's own shortcuts do not also take the key
        self.labelAt[self.current] = label
        self.redraw()

    # Pick tolerances on screen, as the user sees the boundary: a vertex within 5 pixels, an edge
    # within 12 (in model units, two edge lengths missed clicks 5-8 px inside a silhouette and a
    # fifth of an edge made splitting fiddly).
    VERTEX_PIXELS, EDGE_PIXELS = 5.0, 12.0

    def clickOnScreen(self, pos):
        """A click at screen position `pos`: on a boundary vertex it splits or merges there, near a
        boundary edge it cycles that segment's label; elsewhere it is said to miss."""
        screen = [self.view.getPointOnScreen(self.obj.Placement.multVec(FreeCAD.Vector(*q))) for q in self.points]
        n = len(screen)
        # Zoomed out, edges a few pixels long would be all vertex: a vertex then takes a third of
        # the typical edge on screen, so that the middle of an edge still reads as the edge.
        lengths = sorted(math.hypot(screen[i][0] - screen[(i + 1) % n][0], screen[i][1] - screen[(i + 1) % n][1]) for i in range(n))
        vertexPixels = min(self.VERTEX_PIXELS, lengths[n // 2] / 3)
        k = min(range(n), key=lambda i: math.hypot(screen[i][0] - pos[0], screen[i][1] - pos[1]))
        if math.hypot(screen[k][0] - pos[0], screen[k][1] - pos[1]) <= vertexPixels:
            self.toggleSplit(k)
            return
        e = min(range(n), key=lambda i: self._segmentDistance(pos, screen[i], screen[(i + 1) % n]))
        if self._segmentDistance(pos, screen[e], screen[(e + 1) % n]) > self.EDGE_PIXELS:
            self.status.setText(translate("HoleFill", "That click was not near the boundary (%d pixels from it at least).") % self.EDGE_PIXELS)
            return
        self.cycleEdge(e)

    def clickAt(self, p):
        """A click at model point p, as the click on screen where the view draws it."""
        self.clickOnScreen(self.view.getPointOnScreen(self.obj.Placement.multVec(FreeCAD.Vector(*p))))

    def segmentOfEdge(self, e):
        for start, seg in self.segments():
            if e in seg[:-1]:
                return start
        return None

    def cycleEdge(self, e):
        start = self.segmentOfEdge(e)
        self.current = start
        current = self.labelAt.get(start, "-")
        self.labelAt[start] = CYCLE[(CYCLE.index(current) + 1) % len(CYCLE)]
        self.redraw()

    def toggleSplit(self, k):
        if k in self.splits:
            self.splits.discard(k)
            self.labelAt.pop(k, None)
        else:
            inherited = self.labelAt.get(self.segmentOfEdge(k), "-")
            self.splits.add(k)
            self.labelAt[k] = inherited
        self.redraw()

    def splitAtCorners(self):
        from HoleFill.labeled import cornerSplits
        self.splits = set(cornerSplits(self.points, self.angle.value()))
        self.labelAt = {}
        self.redraw()

    def setFourCorners(self):
        import HoleFill
        from HoleFill.labeled import fourCorners
        try:
            corners = fourCorners(self.points, self.normal)
        except HoleFill.HoleFillError as e:
            self.status.setText(str(e))
            return
        self.splits = set(corners)
        self.labelAt = dict(corners)
        self.redraw()
        self.status.setText(translate("HoleFill", "Four corners set where the boundary meets the corners of its smallest bounding "
                                      "rectangle; S, E, N, W run anticlockwise. Click a boundary vertex to move a split."))

    def clearLabels(self):
        self.labelAt = {}
        self.redraw()

    # -- drawing -----------------------------------------------------------------------------
    def redraw(self):
        from pivy import coin
        from HoleFill.labeled import LABEL_COLORS
        remove_overlay()
        root = scene_overlay.placed_root("%s_%s" % (OVERLAY, self.obj.Name), self.obj.Placement)
        depth = coin.SoDepthBuffer()
        depth.test = False  # boundary, letters and splits stay visible over the mesh
        root.addChild(depth)
        self.segmentList.clear()
        for i, ((start, seg), label) in enumerate(zip(self.segments(), self.labels())):
            self.segmentList.addItem("%d: %s, %d edges from boundary vertex %d" % (
                i + 1, {"-": "unlabeled"}.get(label, label), len(seg) - 1, self.loop[start]))
            sep = coin.SoSeparator()
            sep.setName("%s_segment" % OVERLAY)
            col = coin.SoBaseColor()
            col.rgb.setValue(*LABEL_COLORS.get(label, LABEL_COLORS["-"]))
            style = coin.SoDrawStyle()
            style.lineWidth = 6 if label != "-" else 3
            coords = coin.SoCoordinate3()
            coords.point.setValues(0, len(seg), [list(self.points[k]) for k in seg])
            line = coin.SoLineSet()
            line.numVertices.setValue(len(seg))
            for nd in (col, style, coords, line):
                sep.addChild(nd)
            if label != "-":
                mid = self.points[seg[len(seg) // 2]]
                tr = coin.SoTranslation()
                tr.translation.setValue(*mid)
                font = coin.SoFont()
                font.size = 24
                text = coin.SoText2()
                text.string = label
                for nd in (tr, font, text):
                    sep.addChild(nd)
            root.addChild(sep)
        root.addChild(self.arrows())
        if self.splits:
            sep = coin.SoSeparator()
            col = coin.SoBaseColor()
            col.rgb.setValue(0, 0, 0)
            style = coin.SoDrawStyle()
            style.pointSize = 9
            coords = coin.SoCoordinate3()
            coords.point.setValues(0, len(self.splits), [list(self.points[k]) for k in sorted(self.splits)])
            for nd in (col, style, coords, coin.SoPointSet()):
                sep.addChild(nd)
            root.addChild(sep)
        scene_overlay.show(root)
        labeled = sum(1 for l in self.labels() if l != "-")
        self.status.setText(translate("HoleFill", "%d segments, %d labeled. OK stores the labels; then use Fit labeled surface.") % (len(self.segments()), labeled))

    def arrows(self):
        """An arrowhead at the middle of each segment, pointing the way S, E, N, W follow each
        other (anticlockwise seen from the region's normal), black so it shows on any label."""
        from pivy import coin
        sep = coin.SoSeparator()
        sep.setName("%s_arrows" % OVERLAY)
        col = coin.SoBaseColor()
        col.rgb.setValue(0, 0, 0)
        style = coin.SoDrawStyle()
        style.lineWidth = 3
        forward = 1 if self._anticlockwise() else -1
        size = 1.5 * self.edgeLength
        nn = math.sqrt(sum(x * x for x in self.normal)) or 1.0
        normal = [x / nn for x in self.normal]
        pts = []
        for _, seg in self.segments():
            m = seg[len(seg) // 2]
            a, b = self.points[seg[max(0, len(seg) // 2 - 1)]], self.points[seg[min(len(seg) - 1, len(seg) // 2 + 1)]]
            d = [forward * (y - x) for x, y in zip(a, b)]
            dl = math.sqrt(sum(x * x for x in d))
            if dl == 0:
                continue
            d = [x / dl for x in d]
            side = (normal[1] * d[2] - normal[2] * d[1], normal[2] * d[0] - normal[0] * d[2], normal[0] * d[1] - normal[1] * d[0])
            tip = self.points[m]
            for sgn in (1, -1):
                pts += [[t - size * x + sgn * 0.6 * size * y for t, x, y in zip(tip, d, side)], list(tip)]
        coords = coin.SoCoordinate3()
        coords.point.setValues(0, len(pts), pts)
        lines = coin.SoLineSet()
        lines.numVertices.setValues(0, len(pts) // 2, [2] * (len(pts) // 2))
        for nd in (col, style, coords, lines):
            sep.addChild(nd)
        return sep

    # -- dialog (task_dialog.Panel; OK stores or edits the labels in one transaction) ---------------
    def release(self):
        from pivy import coin
        self.view.removeEventCallbackPivy(coin.SoMouseButtonEvent.getClassTypeId(), self.callback)
        self.view.removeEventCallbackPivy(coin.SoKeyboardEvent.getClassTypeId(), self.keys)
        task_dialog.Panel.release(self)

    def accept(self):
        import HoleFill
        labels = self.labels()
        if sum(1 for l in labels if l != "-") < 2:
            self.status.setText(translate("HoleFill", "Label at least two segments (a fit needs two sides of its four-sided domain)."))
            return False
        try:
            if self.existing is not None:
                doc = self.existing.Document
                doc.openTransaction("Label boundary")
                self.existing.Loop = self.loop
                self.existing.Splits = sorted(self.splits)
                self.existing.Labels = labels
                doc.recompute()
                doc.commitTransaction()
                obj = self.existing
            else:
                obj = HoleFill.makeBoundaryLabels(self.obj, splits=sorted(self.splits), labels=labels)
        except Exception as e:
            self.status.setText(translate("HoleFill", "Failed: %s") % e)
            FreeCAD.Console.PrintError("HoleFill: %s\n" % e)
            return False
        FreeCAD.Console.PrintMessage("HoleFill: %s labels %s: %s\n" % (obj.Label, self.obj.Label, " ".join(l for l in labels)))
        self.close()
        return True
