"""View provider of the Fill object: an icon, the fill drawn in a distinct colour,
and double-click to edit it in the Fill task panel."""
import HoleFillGui


class FillViewProvider:
    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.ShapeColor = (0.95, 0.62, 0.20)

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return HoleFillGui.icon("HoleFill_Fill.svg")

    def claimChildren(self):
        return []

    def setEdit(self, vobj, mode=0):
        import FreeCADGui
        from HoleFillGui import task_fill
        FreeCADGui.Control.showDialog(task_fill.FillTaskPanel(existing=vobj.Object))
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
