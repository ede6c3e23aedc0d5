"""View-only overlays of the task panels: one named SoSeparator per overlay in the active
view's scene graph, placed like the object it annotates and unpickable (clicks reach the
object's own faces and edges underneath), removed by its name prefix."""
import FreeCAD
import FreeCADGui


def remove(prefix):
    if not FreeCAD.GuiUp or FreeCADGui.ActiveDocument is None:
        return
    root = FreeCADGui.ActiveDocument.ActiveView.getSceneGraph()
    for i in reversed(range(root.getNumChildren())):
        if root.getChild(i).getName().getString().startswith(prefix):
            root.removeChild(i)


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
    root.addChild(coin.SoPolygonOffset())
    return root


def show(root):
    FreeCADGui.ActiveDocument.ActiveView.getSceneGraph().addChild(root)
