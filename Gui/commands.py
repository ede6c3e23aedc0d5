"""HoleFill commands. Commands are thin: they open a task panel that holds the interaction."""
import FreeCAD
import FreeCADGui

import HoleFillGui
from HoleFillGui import SelectionError

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

COMMANDS = ["HoleFill_FillHole", "HoleFill_FillMeshHoles", "HoleFill_GnurbsSurface", "HoleFill_ImportCage", "HoleFill_LabelBoundary",
            "HoleFill_FitLabeled", "HoleFill_FitPointCloud", "Separator", "HoleFill_CurvatureMap", "HoleFill_ZebraStripes", "HoleFill_ContinuityCheck"]


class _PanelCommand:
    """Opens its task panel, self.open(module) with HoleFillGui's `module` (task_*.py), on the
    selection. A selection the panel cannot take, or a core error while it opens, is said in a
    message and changes nothing: the module's overlay is removed (its remove_overlay()). `name` is
    the command's, and its words' translation context."""
    name = menu = tip = icon = module = None

    def GetResources(self):
        return {"Pixmap": HoleFillGui.icon(self.icon), "MenuText": self.menu, "ToolTip": self.tip}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        from HoleFillGui import inspect_panels
        try:
            panel = self.panel()
        except SelectionError as e:
            inspect_panels._message(str(e))
            return
        except Exception as e:  # a core error on this input: say it, change nothing
            inspect_panels._message(translate("HoleFill", "%s failed: %s") % (translate(self.name, self.menu), e))
            self.cleanup()
            return
        if panel is not None:  # None: the user cancelled before a panel was needed
            from HoleFillGui import task_dialog
            task_dialog.show(panel)

    def _module(self):
        import importlib
        return importlib.import_module("HoleFillGui." + self.module)

    def panel(self):
        return self.open(self._module())

    def cleanup(self):
        remove = getattr(self._module(), "remove_overlay", None)
        if remove is not None:
            remove()


class FillHoleCommand(_PanelCommand):
    name, icon, module = "HoleFill_FillHole", "HoleFill_Fill.svg", "task_fill"
    menu = QT_TRANSLATE_NOOP("HoleFill_FillHole", "Fill hole")
    tip = QT_TRANSLATE_NOOP("HoleFill_FillHole", "Fill an N-sided hole with one trimmed B-spline face.\n"
                            "Select one edge of the hole (its whole loop is taken) or several edges, then run.")

    def open(self, m):
        return m.FillTaskPanel()


class FillMeshHolesCommand(_PanelCommand):
    name, icon, module = "HoleFill_FillMeshHoles", "HoleFill_MeshFill.svg", "task_meshfill"
    menu = QT_TRANSLATE_NOOP("HoleFill_FillMeshHoles", "Fill mesh holes")
    tip = QT_TRANSLATE_NOOP("HoleFill_FillMeshHoles", "Fill holes of a triangle mesh (scan, STL) with well-shaped triangles that follow the surface.\n"
                            "Select a mesh object, then run: its holes are listed and drawn; check the ones to fill.")

    def open(self, m):
        return m.MeshFillPanel(m.mesh_from_selection())


class GnurbsSurfaceCommand(_PanelCommand):
    name, icon, module = "HoleFill_GnurbsSurface", "HoleFill_Gnurbs.svg", "task_gnurbs"
    menu = QT_TRANSLATE_NOOP("HoleFill_GnurbsSurface", "G-NURBS surface")
    tip = QT_TRANSLATE_NOOP("HoleFill_GnurbsSurface", "A curvature-continuous (G²) surface over a quad cage with extraordinary points.\n"
                            "Select the cage (an object of quadrilateral faces), run, click edges to make them sharp,\n"
                            "set anchors at extraordinary points; the surface follows the cage when it changes.")

    def open(self, m):
        return m.GnurbsPanel(m.cage_from_selection())


class LabelBoundaryCommand(_PanelCommand):
    name, icon, module = "HoleFill_LabelBoundary", "HoleFill_Labels.svg", "task_labels"
    menu = QT_TRANSLATE_NOOP("HoleFill_LabelBoundary", "Label boundary")
    tip = QT_TRANSLATE_NOOP("HoleFill_LabelBoundary", "Label the boundary of a mesh region North/East/South/West for a labeled fit.\n"
                            "Select a mesh region (or its labels to edit them), run, click boundary edges to cycle\n"
                            "their segment's label, click boundary vertices to split or merge segments.")

    def open(self, m):
        mesh, existing = m.mesh_from_selection()
        return m.LabelPanel(mesh, existing=existing)


class FitLabeledCommand(_PanelCommand):
    name, icon, module = "HoleFill_FitLabeled", "HoleFill_LabeledFit.svg", "task_labeled_fit"
    menu = QT_TRANSLATE_NOOP("HoleFill_FitLabeled", "Fit labeled surface")
    tip = QT_TRANSLATE_NOOP("HoleFill_FitLabeled", "Fit one trimmed B-spline face to a labeled mesh region: labeled parameterization,\n"
                            "extension to the four-sided domain, tensor-product fit. Select the boundary labels\n"
                            "(or the mesh); the fit follows the labels when they change.")

    def open(self, m):
        return m.FitPanel(m.labels_from_selection())


class FitPointCloudCommand(_PanelCommand):
    name, icon, module = "HoleFill_FitPointCloud", "HoleFill_PointFit.svg", "task_point_fit"
    menu = QT_TRANSLATE_NOOP("HoleFill_FitPointCloud", "Fit point cloud")
    tip = QT_TRANSLATE_NOOP("HoleFill_FitPointCloud", "Fit a B-spline face to a Points or Mesh object: boundary (found for a bare cloud),\n"
                            "parameters (BIDGCN or classical), adaptive THB refinement with parameter correction\n"
                            "until the tolerance; shows the hierarchical mesh and the point errors.")

    def open(self, m):
        return m.FitPanel(m.source_from_selection())


class ImportCageCommand(_PanelCommand):
    name, icon, module = "HoleFill_ImportCage", "HoleFill_Gnurbs.svg", "task_gnurbs"
    menu = QT_TRANSLATE_NOOP("HoleFill_ImportCage", "Import quad cage (OBJ)")
    tip = QT_TRANSLATE_NOOP("HoleFill_ImportCage", "Read a quad cage from an OBJ file (with '# sharp i j', '# knot i j d', '# anchor i x y z'\n"
                            "lines) as a shell of quads, and open G-NURBS surface on it with those marks.")

    def open(self, m):
        from PySide2 import QtWidgets
        import HoleFill
        path, _ = QtWidgets.QFileDialog.getOpenFileName(FreeCADGui.getMainWindow(), "Import quad cage", "", "OBJ cages (*.obj)")
        if not path:
            return None
        obj, cage = HoleFill.importCage(path, FreeCAD.ActiveDocument)
        FreeCADGui.SendMsgToActiveView("ViewFit")
        return m.GnurbsPanel(obj, cage["sharpEdges"], cage["anchors"], cage["knots"])


class _InspectCommand(_PanelCommand):
    """Opens the panel on the selection; when the overlay of its kind is shown, removes it (toggle)."""
    kind = None

    def Activated(self):
        from HoleFillGui import inspection_overlay
        if inspection_overlay.nodes(self.kind):
            inspection_overlay.remove(self.kind)
            FreeCAD.Console.PrintMessage("HoleFill: %s overlay removed\n" % self.kind.lower())
            return
        _PanelCommand.Activated(self)

    module = "inspect_panels"

    def open(self, m):
        from HoleFillGui import inspection_overlay
        return self.inspectPanel(m, inspection_overlay)

    def cleanup(self):
        from HoleFillGui import inspection_overlay
        inspection_overlay.remove(self.kind)


class CurvatureMapCommand(_InspectCommand):
    name = "HoleFill_CurvatureMap"
    kind, menu, icon = "Curvature", QT_TRANSLATE_NOOP("HoleFill_CurvatureMap", "Curvature map"), "HoleFill_Curvature.svg"
    tip = QT_TRANSLATE_NOOP("HoleFill_CurvatureMap", ("Colour the selected faces or objects by mean, Gaussian or principal curvature, computed from the\n"
           "exact surfaces. Run again to remove the colours."))

    def inspectPanel(self, panels, overlay):
        return panels.CurvaturePanel(overlay.targets_from_selection())


class ZebraStripesCommand(_InspectCommand):
    name = "HoleFill_ZebraStripes"
    kind, menu, icon = "Zebra", QT_TRANSLATE_NOOP("HoleFill_ZebraStripes", "Zebra stripes"), "HoleFill_Zebra.svg"
    tip = QT_TRANSLATE_NOOP("HoleFill_ZebraStripes", ("Reflection lines (follow the view) or isophotes on the selected faces or objects,\n"
           "or with nothing selected on every visible object: a stripe that breaks shows a G1 break,\n"
           "a kink a G2 break. Run again to remove them."))

    def inspectPanel(self, panels, overlay):
        return panels.ZebraPanel(overlay.targets_from_selection(whole_scene=True))


class ContinuityCheckCommand(_InspectCommand):
    name = "HoleFill_ContinuityCheck"
    kind, menu, icon = "Continuity", QT_TRANSLATE_NOOP("HoleFill_ContinuityCheck", "Continuity check"), "HoleFill_Continuity.svg"
    tip = QT_TRANSLATE_NOOP("HoleFill_ContinuityCheck", "Select two adjacent faces or a Fill object: G0/G1/G2 along the shared boundary, drawn in colour.")

    def inspectPanel(self, panels, overlay):
        return panels.ContinuityPanel(*panels.continuity_target())


def register():
    for command in (FillHoleCommand, FillMeshHolesCommand, GnurbsSurfaceCommand, ImportCageCommand, LabelBoundaryCommand,
                    FitLabeledCommand, FitPointCloudCommand, CurvatureMapCommand, ZebraStripesCommand, ContinuityCheckCommand):
        FreeCADGui.addCommand(command.name, command())
