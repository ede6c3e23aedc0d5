"""HoleFill commands. Commands are thin: they open a task panel that holds the interaction."""
import FreeCAD
import FreeCADGui

import HoleFillGui
from HoleFillGui import SelectionError

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

COMMANDS = ["HoleFill_FillHole", "HoleFill_FillMeshHoles", "HoleFill_GnurbsSurface", "HoleFill_ImportCage", "HoleFill_LabelBoundary",
            "HoleFill_FitLabeled", "HoleFill_FitPointCloud", "Separator", "HoleFill_CurvatureMap", "HoleFill_ZebraStripes", "HoleFill_ContinuityCheck"]


class FillHoleCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_Fill.svg"),
                "MenuText": QT_TRANSLATE_NOOP("HoleFill_FillHole", "Fill hole"),
                "ToolTip": QT_TRANSLATE_NOOP("HoleFill_FillHole", "Fill an N-sided hole with one trimmed B-spline face.\n"
                           "Select one edge of the hole (its whole loop is taken) or several edges, then run.")}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import task_fill
        FreeCADGui.Control.showDialog(task_fill.FillTaskPanel())


class FillMeshHolesCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_MeshFill.svg"),
                "MenuText": QT_TRANSLATE_NOOP("HoleFill_FillMeshHoles", "Fill mesh holes"),
                "ToolTip": QT_TRANSLATE_NOOP("HoleFill_FillMeshHoles", "Fill holes of a triangle mesh (scan, STL) with well-shaped triangles that follow the surface.\n"
                           "Select a mesh object, then run: its holes are listed and drawn; check the ones to fill.")}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import inspect_panels, task_meshfill
        try:
            panel = task_meshfill.MeshFillPanel(task_meshfill.mesh_from_selection())
        except SelectionError as e:
            inspect_panels._message(str(e))
            return
        except Exception as e:  # a core error on this mesh: say it, change nothing
            inspect_panels._message(translate("HoleFill", "Fill mesh holes failed: %s") % e)
            task_meshfill.remove_overlay()
            return
        FreeCADGui.Control.showDialog(panel)


class GnurbsSurfaceCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_Gnurbs.svg"),
                "MenuText": QT_TRANSLATE_NOOP("HoleFill_GnurbsSurface", "G-NURBS surface"),
                "ToolTip": QT_TRANSLATE_NOOP("HoleFill_GnurbsSurface", "A curvature-continuous (G²) surface over a quad cage with extraordinary points.\n"
                           "Select the cage (an object of quadrilateral faces), run, click edges to make them sharp,\n"
                           "set anchors at extraordinary points; the surface follows the cage when it changes.")}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import inspect_panels, task_gnurbs
        try:
            panel = task_gnurbs.GnurbsPanel(task_gnurbs.cage_from_selection())
        except SelectionError as e:
            inspect_panels._message(str(e))
            return
        except Exception as e:  # not a quad cage, or a core error: say it, change nothing
            inspect_panels._message(translate("HoleFill", "G-NURBS surface: %s") % e)
            task_gnurbs.remove_overlay()
            return
        FreeCADGui.Control.showDialog(panel)


class LabelBoundaryCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_Labels.svg"),
                "MenuText": QT_TRANSLATE_NOOP("HoleFill_LabelBoundary", "Label boundary"),
                "ToolTip": QT_TRANSLATE_NOOP("HoleFill_LabelBoundary", "Label the boundary of a mesh region North/East/South/West for a labeled fit.\n"
                           "Select a mesh region (or its labels to edit them), run, click boundary edges to cycle\n"
                           "their segment's label, click boundary vertices to split or merge segments.")}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import inspect_panels, task_labels
        try:
            mesh, existing = task_labels.mesh_from_selection()
            panel = task_labels.LabelPanel(mesh, existing=existing)
        except SelectionError as e:
            inspect_panels._message(str(e))
            return
        except Exception as e:  # a closed mesh, or a core error: say it, change nothing
            inspect_panels._message(translate("HoleFill", "Label boundary: %s") % e)
            task_labels.remove_overlay()
            return
        FreeCADGui.Control.showDialog(panel)


class FitLabeledCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_LabeledFit.svg"),
                "MenuText": QT_TRANSLATE_NOOP("HoleFill_FitLabeled", "Fit labeled surface"),
                "ToolTip": QT_TRANSLATE_NOOP("HoleFill_FitLabeled", "Fit one trimmed B-spline face to a labeled mesh region: labeled parameterization,\n"
                           "extension to the four-sided domain, tensor-product fit. Select the boundary labels\n"
                           "(or the mesh); the fit follows the labels when they change.")}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import inspect_panels, task_labeled_fit
        try:
            panel = task_labeled_fit.FitPanel(task_labeled_fit.labels_from_selection())
        except SelectionError as e:
            inspect_panels._message(str(e))
            return
        FreeCADGui.Control.showDialog(panel)


class FitPointCloudCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_PointFit.svg"),
                "MenuText": QT_TRANSLATE_NOOP("HoleFill_FitPointCloud", "Fit point cloud"),
                "ToolTip": QT_TRANSLATE_NOOP("HoleFill_FitPointCloud", "Fit a B-spline face to a Points or Mesh object: boundary (found for a bare cloud),\n"
                           "parameters (BIDGCN or classical), adaptive THB refinement with parameter correction\n"
                           "until the tolerance; shows the hierarchical mesh and the point errors.")}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import inspect_panels, task_point_fit
        try:
            panel = task_point_fit.FitPanel(task_point_fit.source_from_selection())
        except SelectionError as e:
            inspect_panels._message(str(e))
            return
        FreeCADGui.Control.showDialog(panel)


class ImportCageCommand:
    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon("HoleFill_Gnurbs.svg"),
                "MenuText": QT_TRANSLATE_NOOP("HoleFill_ImportCage", "Import quad cage (OBJ)"),
                "ToolTip": QT_TRANSLATE_NOOP("HoleFill_ImportCage", "Read a quad cage from an OBJ file (with '# sharp i j', '# knot i j d', '# anchor i x y z'\n"
                           "lines) as a shell of quads, and open G-NURBS surface on it with those marks.")}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from PySide2 import QtWidgets
        from HoleFillGui import inspect_panels, task_gnurbs
        import HoleFill
        path, _ = QtWidgets.QFileDialog.getOpenFileName(FreeCADGui.getMainWindow(), "Import quad cage", "", "OBJ cages (*.obj)")
        if not path:
            return
        try:
            obj, cage = HoleFill.importCage(path, FreeCAD.ActiveDocument)
            FreeCADGui.SendMsgToActiveView("ViewFit")
            panel = task_gnurbs.GnurbsPanel(obj, cage["sharpEdges"], cage["anchors"], cage["knots"])
        except Exception as e:
            inspect_panels._message(translate("HoleFill", "Import quad cage: %s") % e)
            return
        FreeCADGui.Control.showDialog(panel)


class _InspectCommand:
    """Opens the panel on the selection; when the overlay of its kind is shown, removes it (toggle)."""
    kind = menu = tip = icon = context = None  # context: the command's name, the translations' context

    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon(self.icon), "MenuText": self.menu, "ToolTip": self.tip}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import inspect_panels, inspection_overlay
        if inspection_overlay.nodes(self.kind):
            inspection_overlay.remove(self.kind)
            FreeCAD.Console.PrintMessage("HoleFill: %s overlay removed\n" % self.kind.lower())
            return
        try:
            panel = self.panel(inspect_panels, inspection_overlay)
        except SelectionError as e:
            inspect_panels._message(str(e))
            return
        except Exception as e:  # a core error on this shape: say it, change nothing
            inspect_panels._message(translate("HoleFill", "%s failed: %s") % (translate(self.context, self.menu), e))
            inspection_overlay.remove(self.kind)
            return
        FreeCADGui.Control.showDialog(panel)


class CurvatureMapCommand(_InspectCommand):
    context = "HoleFill_CurvatureMap"
    kind, menu, icon = "Curvature", QT_TRANSLATE_NOOP("HoleFill_CurvatureMap", "Curvature map"), "HoleFill_Curvature.svg"
    tip = QT_TRANSLATE_NOOP("HoleFill_CurvatureMap", ("Colour the selected faces or objects by mean, Gaussian or principal curvature, computed from the\n"
           "exact surfaces. Run again to remove the colours."))

    def panel(self, panels, overlay):
        return panels.CurvaturePanel(overlay.targets_from_selection())


class ZebraStripesCommand(_InspectCommand):
    context = "HoleFill_ZebraStripes"
    kind, menu, icon = "Zebra", QT_TRANSLATE_NOOP("HoleFill_ZebraStripes", "Zebra stripes"), "HoleFill_Zebra.svg"
    tip = QT_TRANSLATE_NOOP("HoleFill_ZebraStripes", ("Reflection lines (follow the view) or isophotes on the selected faces or objects: a stripe that\n"
           "breaks shows a G1 break, a kink a G2 break. Run again to remove them."))

    def panel(self, panels, overlay):
        return panels.ZebraPanel(overlay.targets_from_selection())


class ContinuityCheckCommand(_InspectCommand):
    context = "HoleFill_ContinuityCheck"
    kind, menu, icon = "Continuity", QT_TRANSLATE_NOOP("HoleFill_ContinuityCheck", "Continuity check"), "HoleFill_Continuity.svg"
    tip = QT_TRANSLATE_NOOP("HoleFill_ContinuityCheck", "Select two adjacent faces or a Fill object: G0/G1/G2 along the shared boundary, drawn in colour.")

    def panel(self, panels, overlay):
        return panels.ContinuityPanel(*panels.continuity_target())


def register():
    FreeCADGui.addCommand("HoleFill_FillHole", FillHoleCommand())
    FreeCADGui.addCommand("HoleFill_FillMeshHoles", FillMeshHolesCommand())
    FreeCADGui.addCommand("HoleFill_GnurbsSurface", GnurbsSurfaceCommand())
    FreeCADGui.addCommand("HoleFill_ImportCage", ImportCageCommand())
    FreeCADGui.addCommand("HoleFill_LabelBoundary", LabelBoundaryCommand())
    FreeCADGui.addCommand("HoleFill_FitLabeled", FitLabeledCommand())
    FreeCADGui.addCommand("HoleFill_FitPointCloud", FitPointCloudCommand())
    FreeCADGui.addCommand("HoleFill_CurvatureMap", CurvatureMapCommand())
    FreeCADGui.addCommand("HoleFill_ZebraStripes", ZebraStripesCommand())
    FreeCADGui.addCommand("HoleFill_ContinuityCheck", ContinuityCheckCommand())
