"""View-only overlays of the task panels: one named SoSeparator per overlay in the active
view's scene graph, placed like the object it annotates and unpickable (clicks reach the
object's own faces and edges underneath), removed by its name prefix."""
import FreeCAD
import FreeCADGui


# Continuity tiers in colour, for every overlay that shows them (boundary checks, the Fill's loop,
# mesh quality): none of them FreeCAD's preselection yellow or selection green, which a line drawn
# in them is taken for.
TIER_COLORS = {"none": (0.9, 0.1, 0.1), "G0": (1.0, 0.55, 0.0), "G1": (0.0, 0.78, 0.85), "G2": (0.15, 0.45, 0.95)}


def remove(prefix):
    if not FreeCAD.GuiUp or FreeCADGui.ActiveDocument is None:
        return
    from pivy import coin  # noqa: F401 (FreeCAD 1.0 wraps the scene graph only once pivy is loaded)
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    for i in reversed(range(root.getNumChildren())):
        if root.getChild(i).getName().getString().startswith(prefix):
            root.removeChild(i)


def shape_placement(obj):
    """The placement of overlays drawn from obj.Shape's own coordinates: its Placement is already
    in them (FreeCAD bakes it into the shape), so only what its containers (an App::Part) add,
    its global placement less its own. Mesh points are not placed: those overlays take obj.Placement."""
    if not hasattr(obj, "getGlobalPlacement"):
        return FreeCAD.Placement()
    return obj.getGlobalPlacement().multiply(obj.Placement.inverse())


def placed_root(name, placement):
    """A new overlay separator named `name` under `placement` (add children, then show())."""
    from pivy import coin
    root = coin.SoSeparator()
    root.setName(name)
    m = placement.toMatrix()
    xf = coin.SoMatrixTransform()
    xf.matrix.setValue(coin.SbMatrix(*[m.A[4 * c + r] for r in range(4) for c in range(4)]))
    root.addChild(xf)
    pick = coin.SoPickStyle()
    pick.style = coin.SoPickStyle.UNPICKABLE
    root.addChild(pick)
    # Drawn in front of faces it lies on (a Preview of a Fill being edited covers the Fill's own
    # face exactly, and the two fought pixel by pixel): negative factor and units pull it towards
    # the viewer, as the inspection overlays do.
    offset = coin.SoPolygonOffset()
    offset.factor = -1.0
    offset.units = -1.0
    root.addChild(offset)
    return root


def show(root):
    FreeCADGui.ActiveDocument.ActiveView.getSceneGraph().addChild(root)


def face_node(face, name, rgb, transparency, tolerance=None):
    """A separator named `name` drawing `face` (a Part.Face) tessellated (chord tolerance: 0.2%
    of its diagonal unless given), in colour `rgb` with the given transparency."""
    from pivy import coin
    pts, tris = face.tessellate(tolerance or 0.002 * max(face.BoundBox.DiagonalLength, 1e-9))
    sep = coin.SoSeparator()
    sep.setName(name)
    hints = coin.SoShapeHints()
    hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE
    hints.creaseAngle = 1.0
    mat = coin.SoMaterial()
    mat.diffuseColor.setValue(*rgb)
    mat.transparency.setValue(transparency)
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, len(pts), [[p.x, p.y, p.z] for p in pts])
    faces = coin.SoIndexedFaceSet()
    idx = []
    for t in tris:
        idx += [t[0], t[1], t[2], -1]
    faces.coordIndex.setValues(0, len(idx), idx)
    for nd in (hints, mat, coords, faces):
        sep.addChild(nd)
    return sep


def points_node(name, points, rgb, size):
    """A separator named `name` drawing each point (x, y, z) as a dot of `size` pixels in colour
    `rgb`, unlit and in front of the faces (points a fill passes through sit over a hole, or on
    a face's vertex)."""
    from pivy import coin
    sep = coin.SoSeparator()
    sep.setName(name)
    depth = coin.SoDepthBuffer()
    depth.test = False
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    col = coin.SoBaseColor()
    col.rgb.setValue(*rgb)
    style = coin.SoDrawStyle()
    style.pointSize = size
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, len(points), [list(p) for p in points])
    for nd in (depth, light, col, style, coords, coin.SoPointSet()):
        sep.addChild(nd)
    return sep


def polyline_node(name, polylines, rgb, width):
    """A separator named `name` drawing each polyline (a list of (x, y, z)) in colour `rgb`,
    `width` pixels wide, unlit and drawn over the faces it runs along (a hole's edges lie on the
    model's faces, and would flicker through them)."""
    from pivy import coin
    sep = coin.SoSeparator()
    sep.setName(name)
    depth = coin.SoDepthBuffer()
    depth.function = coin.SoDepthBuffer.LEQUAL
    light = coin.SoLightModel()
    light.model = coin.SoLightModel.BASE_COLOR
    col = coin.SoBaseColor()
    col.rgb.setValue(*rgb)
    style = coin.SoDrawStyle()
    style.lineWidth = width
    coords = coin.SoCoordinate3()
    pts = [list(p) for line in polylines for p in line]
    coords.point.setValues(0, len(pts), pts)
    lines = coin.SoLineSet()
    lines.numVertices.setValues(0, len(polylines), [len(line) for line in polylines])
    for nd in (depth, light, col, style, coords, lines):
        sep.addChild(nd)
    return sep
