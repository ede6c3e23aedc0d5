"""Pictures for docs/benchmarks.md: one hole of a benchmark case as filled by HoleFill, CGAL and
FreeCAD, rendered by the real FreeCAD under Xvfb (flat shading with edges; the new triangles
orange, the surrounding mesh grey), the camera on the hole. Reads the meshes bench_meshfill.py
wrote to $BENCH_OUT/meshfill; writes <case>_<method>.png next to them."""
import os
import sys

import FreeCAD
import FreeCADGui
import Mesh

OUT = os.path.join(os.environ.get("BENCH_OUT", "/tmp"), "meshfill")
CASES = [c for c in os.environ.get("PICTURE_CASES", "fandisk,holes_off,elephant-with-holes_off").split(",") if c]
METHODS = ("holefill", "holefill_c2", "cgal_liepa", "freecad_fillupholes")


def split(source, filled):
    """(kept, added) Mesh.Mesh: facets of `filled` whose corner positions are not a facet of `source`."""
    key = lambda pts: tuple(sorted((round(p.x, 5), round(p.y, 5), round(p.z, 5)) for p in pts))
    known = {key([FreeCAD.Vector(*p) for p in f.Points]) for f in source.Facets}
    kept, added = [], []
    for f in filled.Facets:
        pts = [FreeCAD.Vector(*p) for p in f.Points]
        (kept if key(pts) in known else added).append(pts)
    return Mesh.Mesh(kept), Mesh.Mesh(added)


def main():
    from pivy import coin
    from PySide2 import QtWidgets
    app = QtWidgets.QApplication.instance()
    for case in CASES:
        src = Mesh.Mesh(os.path.join(OUT, "%s_in.off" % case))
        ours = os.path.join(OUT, "%s_holefill.off" % case)
        if not os.path.exists(ours):
            continue
        _, patch = split(src, Mesh.Mesh(ours))
        if patch.CountFacets == 0:
            continue
        # Camera on the largest connected piece of our patch.
        piece = max(patch.getSeparateComponents(), key=lambda m: m.CountFacets)
        box = piece.BoundBox
        centre = box.Center
        for method in METHODS:
            path = os.path.join(OUT, "%s_%s.off" % (case, method))
            if not os.path.exists(path):
                continue
            doc = FreeCAD.newDocument("Pic")
            kept, added = split(src, Mesh.Mesh(path))
            for name, m, color in (("Kept", kept, (0.75, 0.75, 0.75)), ("Added", added, (1.0, 0.55, 0.1))):
                o = doc.addObject("Mesh::Feature", name)
                o.Mesh = m
                v = o.ViewObject
                v.ShapeColor = color
                v.DisplayMode = "Flat Lines"
                v.LineColor = (0.1, 0.1, 0.1)
            doc.recompute()
            view = FreeCADGui.ActiveDocument.ActiveView
            view.viewIsometric()
            cam = view.getCameraNode()
            n = (box.XLength + box.YLength + box.ZLength) / 3 or 1.0
            view.fitAll()
            # Zoom to the hole: look at its centre from along the patch's mean normal.
            normals = [f.Normal for f in piece.Facets]
            d = sum(normals, FreeCAD.Vector())
            d = d.normalize() if d.Length > 0 else FreeCAD.Vector(1, 1, 1).normalize()
            view.setViewDirection((-d.x, -d.y, -d.z))
            cam.position.setValue(centre.x + d.x * 6 * n, centre.y + d.y * 6 * n, centre.z + d.z * 6 * n)
            cam.pointAt(coin.SbVec3f(centre.x, centre.y, centre.z))
            if hasattr(cam, "height"):
                cam.height.setValue(2.6 * n)
            app.processEvents()
            view.saveImage(os.path.join(OUT, "%s_%s.png" % (case, method)), 480, 400, "White")
            FreeCAD.closeDocument(doc.Name)
            app.processEvents()
    sys.stdout.flush()
    os._exit(0)


from PySide2 import QtCore  # noqa: E402
QtCore.QTimer.singleShot(500, main)
