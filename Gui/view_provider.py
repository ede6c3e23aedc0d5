"""View providers: the Fill object (its icon, the fill in a distinct colour) and the boundary
labels (segments in their labels' colours, with letters); double-click edits either in its task
panel."""
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


class FillViewProvider(_EditInPanel):
    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.ShapeColor = (0.95, 0.62, 0.20)

    def attach(self, vobj):
        self.Object = vobj.Object

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
