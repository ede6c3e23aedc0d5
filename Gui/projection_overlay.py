"""A translucent view-only overlay of UVTran's predicted projection surface (the surface the
"uvtran" method projects the hole boundary onto): shown while the Fill task panel is open, never
added to the document. One named SoSeparator in the active view's scene graph."""
from pivy import coin

import FreeCADGui

from HoleFillGui import scene_overlay

NAME = "HoleFillProjectionSurface"


def _root():
    gdoc = FreeCADGui.ActiveDocument
    if gdoc is None or not hasattr(gdoc.ActiveView, "getSceneGraph"):
        return None
    return gdoc.ActiveView.getSceneGraph()


def hide():
    root = _root()
    if root is None:
        return
    for i in reversed(range(root.getNumChildren())):
        if root.getChild(i).getName() == NAME:
            root.removeChild(i)


def show(face, tolerance=None):
    """Shows `face` (a Part.Face) translucent blue and unpickable; replaces a previous one."""
    hide()
    root = _root()
    if root is None:
        return None
    sep = scene_overlay.face_node(face, NAME, (0.25, 0.45, 0.95), 0.6, tolerance)
    pick = coin.SoPickStyle()
    pick.style = coin.SoPickStyle.UNPICKABLE
    sep.insertChild(pick, 0)
    root.addChild(sep)
    return sep
