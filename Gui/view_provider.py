"""View providers: the Fill object (its icon, the fill in a distinct colour) and the boundary
labels (segments in their labels' colours, with letters); double-click edits either in its task
panel."""
import FreeCAD

import HoleFillGui


class _EditInPanel:
    """Double-click (or Edit) opens the object's task panel; nothing is pickled."""

    def panel(self, obj):
        raise NotImplementedError

    def setEdit(self, vobj, mode=0):
        from HoleFillGui import task_dialog
        task_dialog.show(self.panel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        import FreeCADGui
        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        return self.setEdit(vobj)

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


def knot_isocurves(face, samples=64):
    """Polylines [[(x, y, z), ...], ...] of `face`'s B-spline surface along its interior knots
    (u = knot and v = knot), clipped to the face's trimming loops: where an isoline crosses a
    loop (the loops' points taken back to (u, v) by the surface), even-odd, so that holes in
    the face stay empty. Each inside stretch is sampled at about `samples` points per domain width."""
    surf = face.Surface
    u0, u1, v0, v1 = surf.bounds()
    loops = []
    for wire in face.Wires:
        pts = wire.discretize(Number=max(64, 32 * len(wire.Edges)))
        loops.append([surf.parameter(p) for p in pts])
    out = []
    for along_u, knots, lo, hi in ((True, surf.getUKnots()[1:-1], v0, v1), (False, surf.getVKnots()[1:-1], u0, u1)):
        for k in knots:
            crossings = []
            for loop in loops:
                for a, b in zip(loop, loop[1:] + loop[:1]):
                    ka, kb = (a[0], b[0]) if along_u else (a[1], b[1])
                    if (ka - k) * (kb - k) < 0:
                        f = (k - ka) / (kb - ka)
                        crossings.append((a[1] + f * (b[1] - a[1])) if along_u else (a[0] + f * (b[0] - a[0])))
            crossings.sort()
            for start, end in zip(crossings[0::2], crossings[1::2]):
                n = max(2, int(samples * (end - start) / max(hi - lo, 1e-300)) + 1)
                ts = [start + (end - start) * i / (n - 1) for i in range(n)]
                out.append([tuple(surf.value(k, t) if along_u else surf.value(t, k)) for t in ts])
    return out


class FillViewProvider(_EditInPanel):
    """The Fill in its colour, its tree icon (a warning sign when it reaches no tier), and on
    request its B-spline surface's poles and control net (ShowControlPoints), as Surface Filling
    users inspect a patch, and its knot lines on the face (ShowIsocurves), where the fill's
    control is dense and where it is coarse."""

    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.ShapeColor = (0.95, 0.62, 0.20)

    def attach(self, vobj):
        from pivy import coin
        self.Object = vobj.Object
        # Added here, not in __init__: a saved document's view provider is restored without it.
        if not hasattr(vobj, "ShowControlPoints"):
            vobj.addProperty("App::PropertyBool", "ShowControlPoints", "HoleFill",
                             "Draw the fill's B-spline poles and control net over it")
        if not hasattr(vobj, "ShowIsocurves"):
            vobj.addProperty("App::PropertyBool", "ShowIsocurves", "HoleFill",
                             "Draw the fill's knot lines (isocurves at its B-spline knots) on its face")
        self.poles = coin.SoSeparator()
        self.poles.setName("HoleFillPoles")
        vobj.RootNode.addChild(self.poles)
        self.isocurves = coin.SoSeparator()
        self.isocurves.setName("HoleFillIsocurves")
        vobj.RootNode.addChild(self.isocurves)

    def onChanged(self, vobj, prop):
        if prop == "ShowControlPoints":
            self.drawPoles(vobj)
        if prop == "ShowIsocurves":
            self.drawIsocurves(vobj)

    def patch(self, vobj, wanted):
        """The fill's B-spline face when the view property `wanted` is on, else None: the Face
        output, or the patch among a Sewn output's faces (None when it cannot be told)."""
        obj = vobj.Object
        if not getattr(vobj, wanted, False) or obj.Shape.isNull():
            return None
        face = obj.Shape.Faces[0]
        if obj.Output != "Face":
            from HoleFillGui.inspect_panels import patch_of
            try:
                face = patch_of(obj.Shape, obj.Source[0].Shape)
            except Exception:  # the patch cannot be told among the sewn faces: nothing drawn
                return None
        return face if face.Surface.__class__.__name__ == "BSplineSurface" else None

    def drawIsocurves(self, vobj):
        """The knot lines of the fill's surface on its face (knot_isocurves), dark blue, over it."""
        from pivy import coin
        node = getattr(self, "isocurves", None)
        if node is None:
            return
        node.removeAllChildren()
        face = self.patch(vobj, "ShowIsocurves")
        if face is None:
            return
        inverse = vobj.Object.Placement.inverse()
        lines = [[inverse.multVec(FreeCAD.Vector(*p)) for p in line] for line in knot_isocurves(face)]
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        offset = coin.SoPolygonOffset()
        col = coin.SoBaseColor()
        col.rgb.setValue(0.05, 0.1, 0.45)
        coords = coin.SoCoordinate3()
        coords.point.setValues(0, sum(len(ln) for ln in lines), [[p.x, p.y, p.z] for ln in lines for p in ln])
        lineset = coin.SoLineSet()
        lineset.numVertices.setValues(0, len(lines), [len(ln) for ln in lines])
        for nd in (pick, offset, col, coords, lineset):
            node.addChild(nd)

    def drawPoles(self, vobj):
        """The poles (black points) and the control net (grey lines) of the fill's surface."""
        from pivy import coin
        poles = getattr(self, "poles", None)
        if poles is None:
            return
        poles.removeAllChildren()
        obj = vobj.Object
        face = self.patch(vobj, "ShowControlPoints")
        if face is None:
            return
        inverse = obj.Placement.inverse()
        grid = [[inverse.multVec(p) for p in row] for row in face.Surface.getPoles()]
        nu, nv = len(grid), len(grid[0])
        coords = coin.SoCoordinate3()
        coords.point.setValues(0, nu * nv, [[p.x, p.y, p.z] for row in grid for p in row])
        net = coin.SoSeparator()
        col = coin.SoBaseColor()
        col.rgb.setValue(0.35, 0.35, 0.35)
        lines = coin.SoIndexedLineSet()
        idx = []
        for i in range(nu):
            idx += [i * nv + j for j in range(nv)] + [-1]
        for j in range(nv):
            idx += [i * nv + j for i in range(nu)] + [-1]
        lines.coordIndex.setValues(0, len(idx), idx)
        for nd in (col, lines):
            net.addChild(nd)
        points = coin.SoSeparator()
        pcol = coin.SoBaseColor()
        pcol.rgb.setValue(0.0, 0.0, 0.0)
        style = coin.SoDrawStyle()
        style.pointSize = 5
        for nd in (pcol, style, coin.SoPointSet()):
            points.addChild(nd)
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        for nd in (pick, coords, net, points):
            poles.addChild(nd)

    def getIcon(self):
        # A fill that reaches no continuity tier (kept by the user anyway: the Fill panel asks)
        # carries a warning sign in the tree, so that it is not taken for a good one later.
        obj = getattr(self, "Object", None)
        if obj is not None and getattr(obj, "Achieved", "") == "none":
            return HoleFillGui.icon("HoleFill_FillWarning.svg")
        return HoleFillGui.icon("HoleFill_Fill.svg")

    def updateData(self, obj, prop):
        if prop == "Achieved" and obj.ViewObject is not None and hasattr(obj.ViewObject, "signalChangeIcon"):
            obj.ViewObject.signalChangeIcon()
        if prop == "Shape" and obj.ViewObject is not None:
            self.drawPoles(obj.ViewObject)
            self.drawIsocurves(obj.ViewObject)

    def claimChildren(self):
        return []

    def panel(self, obj):
        from HoleFillGui import task_fill
        return task_fill.FillTaskPanel(existing=obj)


class LabelsViewProvider(_EditInPanel):
    """View provider of BoundaryLabels: each segment's polyline in its label's colour (N red, E
    green, S blue, W amber, unlabeled magenta), thick, with its letter at the segment's middle."""

    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.LineWidth = 5
        vobj.PointSize = 1

    def attach(self, vobj):
        from pivy import coin
        self.Object = vobj.Object
        self.letters = coin.SoSeparator()
        self.letters.setName("HoleFillLabelLetters")
        vobj.RootNode.addChild(self.letters)

    def updateData(self, obj, prop):
        if prop in ("Shape", "Labels"):
            self._paint(obj)

    def _paint(self, obj):
        from pivy import coin
        from HoleFill.labeled import LABEL_COLORS
        vobj = obj.ViewObject
        if vobj is None or obj.Shape.isNull():
            return
        colors = []
        for wire, label in zip(obj.Shape.Wires, obj.Labels):
            colors += [LABEL_COLORS.get(label, LABEL_COLORS["-"])] * len(wire.Edges)
        if len(colors) == len(obj.Shape.Edges):
            vobj.LineColorArray = colors
        letters = getattr(self, "letters", None)
        if letters is None:
            return
        letters.removeAllChildren()
        depth = coin.SoDepthBuffer()
        depth.test = False
        letters.addChild(depth)
        for wire, label in zip(obj.Shape.Wires, obj.Labels):
            if label == "-":
                continue
            edges = wire.Edges
            mid = edges[len(edges) // 2].valueAt(edges[len(edges) // 2].FirstParameter)
            sep = coin.SoSeparator()
            col = coin.SoBaseColor()
            col.rgb.setValue(*LABEL_COLORS[label])
            tr = coin.SoTranslation()
            tr.translation.setValue(mid.x, mid.y, mid.z)
            font = coin.SoFont()
            font.size = 22
            text = coin.SoText2()
            text.string = label
            for n in (col, tr, font, text):
                sep.addChild(n)
            letters.addChild(sep)

    def getIcon(self):
        return HoleFillGui.icon("HoleFill_Labels.svg")

    def panel(self, obj):
        from HoleFillGui import task_labels
        return task_labels.LabelPanel(obj.Source, existing=obj)
