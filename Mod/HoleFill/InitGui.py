# HoleFill workbench registration. FreeCAD exec's this file inside a function:
# names defined here are not visible later, so imports happen inside methods.


class HoleFillWorkbench(Workbench):  # noqa: F821 (FreeCAD provides Workbench)
    MenuText = "HoleFill"
    ToolTip = "Fill N-sided holes with trimmed B-spline faces (G0/G1/G2) and inspect their continuity"

    def __init__(self):
        import HoleFillGui
        self.__class__.Icon = HoleFillGui.icon("HoleFill.svg")

    def Initialize(self):
        from HoleFillGui import commands
        commands.register()
        self.appendToolbar("HoleFill", commands.COMMANDS)
        self.appendMenu("HoleFill", commands.COMMANDS)

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


Gui.addWorkbench(HoleFillWorkbench())  # noqa: F821


def _addPreferencePage():
    import os
    import HoleFillGui
    from HoleFillGui.preferences_page import PreferencePage
    # The dialog shows the group with the icon named preferences-<group> on an icon path.
    Gui.addIconPath(os.path.dirname(HoleFillGui.icon("HoleFill.svg")))  # noqa: F821
    Gui.addPreferencePage(PreferencePage, "HoleFill")  # noqa: F821


_addPreferencePage()


def _attachViewProviders():
    # HoleFill's objects get their view providers from the Gui side, from the start, whether or
    # not the workbench is ever loaded (a macro's makeFill).
    from HoleFillGui import view_attach
    view_attach.install()


_attachViewProviders()
