"""A translucent view-only overlay of UVTran's predicted projection surface (the surface the
"uvtran" method projects the hole boundary onto): shown while the Fill task panel is open, never
added to the document. One named SoSeparator in the active view's scene graph."""
from pivy import coin

import FreeCADGui

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
    pts, tris = face.tessellate(tolerance or face.BoundBox.DiagonalLength * 2e-3)
    sep = coin.SoSeparator()
    sep.setName(NAME)
    pick = coin.SoPickStyle()
    pick.style = coin.SoPickStyle.UNPICKABLE
    hints = coin.SoShapeHints()
    hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
    hints.creaseAngle = 1.0
    mat = coin.SoMaterial()
    mat.diffuseColor = (0.25, 0.45, 0.95)
    mat.transparency = 0.6
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, len(pts), [(p.x, p.y, p.z) for p in pts])
    faces = coin.SoIndexedFaceSet()
    idx = []
    for t in tris:
        idx.extend([t[0], t[1], t[2], -1])
    faces.coordIndex.setValues(0, len(idx), idx)
    for n in (pick, hints, mat, coords, faces):
        sep.addChild(n)
    root.addChild(sep)
    return sep
