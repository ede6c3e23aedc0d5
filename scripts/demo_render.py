"""Renders each demo document to a PNG with the real FreeCAD GUI (run under Xvfb by demo.sh):
the model in grey, the Fill in orange with its edges, isometric view; a filled mesh with
its triangle edges."""
import glob
import os
import sys
import traceback

import FreeCAD
import FreeCADGui
from PySide2 import QtCore

OUT = os.environ["HOLEFILL_DEMO_OUT"]


def render():
    code = 1
    try:
        for path in sorted(glob.glob(os.path.join(OUT, "*.FCStd"))):
            doc = FreeCAD.openDocument(path)
            FreeCADGui.activateWorkbench("HoleFillWorkbench")
            filled_mesh = any(o.Name.endswith("_filled") for o in doc.Objects)
            for o in doc.Objects:
                vo = o.ViewObject
                vo.Visibility = True
                if o.isDerivedFrom("Mesh::Feature"):
                    # Mesh demo: the filled copy with its triangle edges; the source is hidden.
                    vo.Visibility = o.Name.endswith("_filled") or not filled_mesh
                    vo.DisplayMode = "Flat Lines"
                    vo.ShapeColor = (0.72, 0.76, 0.82)
                elif o.Name.startswith("Fill"):
                    vo.ShapeColor = (0.95, 0.55, 0.15)
                    vo.LineWidth = 2.0
                else:
                    vo.ShapeColor = (0.72, 0.76, 0.82)
            view = FreeCADGui.ActiveDocument.ActiveView
            view.viewIsometric()
            view.fitAll()
            FreeCADGui.updateGui()
            view.saveImage(path[:-6] + ".png", 1024, 768, "White")
            FreeCAD.closeDocument(doc.Name)
        code = 0
    except Exception:
        # Said, not swallowed: demo.sh shows this log when a picture is missing.
        traceback.print_exc()
        sys.stderr.flush()
    finally:
        os._exit(code)


QtCore.QTimer.singleShot(0, render)
