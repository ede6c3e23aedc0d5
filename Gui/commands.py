"""HoleFill commands. Commands are thin: they open a task panel that holds the interaction."""
import FreeCAD
import FreeCADGui

import HoleFillGui

COMMANDS = ["HoleFill_FillHole"]


class FillHoleCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_Fill.svg"),
                "MenuText": "Fill hole",
                "ToolTip": "Fill an N-sided hole with one trimmed B-spline face.\n"
                           "Select one edge of the hole (its whole loop is taken) or several edges, then run."}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import task_fill
        FreeCADGui.Control.showDialog(task_fill.FillTaskPanel())


def register():
    FreeCADGui.addCommand("HoleFill_FillHole", FillHoleCommand())
