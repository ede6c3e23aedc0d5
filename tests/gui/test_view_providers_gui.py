"""GUI test: objects made by a macro before the HoleFill workbench is ever loaded get their view
providers — the Fill its own (orange, editable in its panel), the boundary labels theirs (coloured
segments), the others FreeCAD's — attached from the Gui side (HoleFillGui/view_attach.py), while
the App side imports nothing of the Gui."""
import sys

import FreeCAD
import FreeCADGui

import guiharness as h


def body():
    # The workbench was never activated: its commands were never loaded.
    assert "HoleFillGui.commands" not in sys.modules, "the workbench was loaded before the test"
    import HoleFill
    import Mesh
    doc, src = h.sample_document("ViewProviders", "Panel", "panel_6_sided")
    fill = HoleFill.makeFill(src)
    assert type(fill.ViewObject.Proxy).__name__ == "FillViewProvider", fill.ViewObject.Proxy
    assert tuple(round(c, 2) for c in fill.ViewObject.ShapeColor[:3]) == (0.95, 0.62, 0.2), fill.ViewObject.ShapeColor
    # A mesh region with its boundary labeled, and a labeled fit of it.
    n, pts, facets = 8, {}, []
    for i in range(n + 1):
        for j in range(n + 1):
            pts[i, j] = FreeCAD.Vector(i, j, 0.05 * i * j)
    for i in range(n):
        for j in range(n):
            facets += [[pts[i, j], pts[i + 1, j], pts[i + 1, j + 1]], [pts[i, j], pts[i + 1, j + 1], pts[i, j + 1]]]
    region = doc.addObject("Mesh::Feature", "Region")
    region.Mesh = Mesh.Mesh(facets)
    doc.recompute()
    labels = HoleFill.makeBoundaryLabels(region)
    assert type(labels.ViewObject.Proxy).__name__ == "LabelsViewProvider", labels.ViewObject.Proxy
    cloud = HoleFill.makePointCloudFit(region)
    assert cloud.ViewObject.Proxy == 0, cloud.ViewObject.Proxy  # FreeCAD's own view provider
    import re
    app_side = [m for name, m in sys.modules.items() if name.startswith("HoleFill.") or name == "HoleFill"]
    assert len(app_side) >= 5, app_side
    for m in app_side:
        src_text = open(m.__file__).read() if getattr(m, "__file__", None) else ""
        assert not re.search(r"^\s*(from|import)\s+HoleFillGui", src_text, re.M), m.__name__
    for o in (src, region, cloud):
        o.ViewObject.Visibility = False
    FreeCADGui.SendMsgToActiveView("ViewFit")
    h.pump(800)
    from PySide2 import QtWidgets
    QtWidgets.QApplication.primaryScreen().grabWindow(0).save(h.shot("gui_view_providers_before_workbench.png"))
    h.finish(True)


h.run(body, 500)
