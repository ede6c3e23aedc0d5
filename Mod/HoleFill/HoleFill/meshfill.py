"""Filling holes in triangle meshes (FreeCAD Mesh objects, scans, STL/OBJ/PLY/OFF files) by the
method of Hu et al.: minimum-angle triangulation, density refinement, bilateral fairing.

    import HoleFill
    holes = HoleFill.meshHoles(obj.Mesh)                      # list of MeshHole, longest first
    filled, report = HoleFill.fillMeshHoles(obj.Mesh, holes=[1, 2], maxBoundary=500)
    for h in report["hole_fills"]:
        print(h["hole"], h["new_triangles"], h["mean_quality"])
    feature = HoleFill.makeMeshFill(obj)                      # new Mesh::Feature in the document

The input mesh is never modified: the result is a new Mesh.Mesh whose first points and facets
are the input's, in their order; only new points and facets follow. Hole numbers are 0-based
(as `holefill mesh-holes` prints them). Errors raise HoleFillError.
"""
import json

import HoleFillApp
from HoleFill import optionDefaults, optionSchema, raiseOnFailure

__all__ = ["meshHoles", "fillMeshHoles", "makeMeshFill", "weldVertices", "readMesh", "writeMesh", "MeshHole", "SEAM_WELD"]

# The weld a user is offered for seams of duplicated vertices, of the bounding-box diagonal:
# copies written by an exporter are equal to FreeCAD's float precision (about 1e-7 relative).
SEAM_WELD = 1e-6


class MeshHole(dict):
    """One boundary loop: index (0-based), boundaryVertices, length (model units), fillable,
    message (why not, or what was done: split at a singular or duplicated vertex), loop
    (point indices in order) and points ((x, y, z) per loop vertex)."""

    def __repr__(self):
        return "MeshHole(%d: %d vertices, length %.6g%s)" % (self["index"], self["boundaryVertices"], self["length"],
                                                               "" if self["fillable"] else ", not fillable")


def _arrays(mesh):
    """(vertices, triangles) NumPy arrays of a Mesh.Mesh, a Mesh feature or a (points, facets) pair."""
    import numpy as np
    if hasattr(mesh, "Mesh") and not hasattr(mesh, "Topology"):
        mesh = mesh.Mesh
    if hasattr(mesh, "Topology"):
        if mesh.CountFacets == 0:
            raise HoleFillApp.HoleFillError("the mesh is empty: select a mesh with triangles")
        points, facets = mesh.Topology
    else:
        points, facets = mesh
    v = np.array([(p[0], p[1], p[2]) for p in points], dtype=float).reshape(-1, 3)
    t = np.array(facets, dtype=np.int32).reshape(-1, 3)
    return v, t


def _mesh(vertices, triangles):
    import FreeCAD
    import Mesh
    points = [FreeCAD.Vector(*p) for p in vertices.tolist()]
    return Mesh.Mesh((points, [tuple(f) for f in triangles.tolist()]))


def weldVertices(mesh, weld=SEAM_WELD, counts=False):
    """`mesh` with its coincident vertices (within weld × the bounding-box diagonal) merged, as
    fillMeshHoles(weld=) does first: (new Mesh.Mesh, merged vertices, dropped triangles).
    counts=True: only (merged vertices, dropped triangles), without building the new Mesh (a panel
    that offers the merge needs no more)."""
    v, t = _arrays(mesh)
    wv, wt, merged, dropped = HoleFillApp.weldVertices(v, t, float(weld))
    return (merged, dropped) if counts else (_mesh(wv, wt), merged, dropped)


def meshHoles(mesh, weld=0):
    """Boundary loops of a mesh (Mesh.Mesh or Mesh feature), longest first, as MeshHole dicts.
    weld > 0: of the mesh with its coincident vertices merged first (weldVertices), numbered as
    fillMeshHoles(weld=) numbers them."""
    v, t = _arrays(mesh)
    if weld:
        v, t, _, _ = HoleFillApp.weldVertices(v, t, float(weld))
    d = json.loads(HoleFillApp.meshHoles(v, t))
    out = []
    for i, h in enumerate(d["holes"]):
        hole = MeshHole(index=i, boundaryVertices=h["boundary_vertices"], length=h["length"], fillable=h["fillable"],
                        message=h["message"], loop=h["loop"], points=[tuple(v[k]) for k in h["loop"]])
        out.append(hole)
    return out


MESH_FILL_OPTIONS = optionSchema("mesh_fill")
_MF = optionDefaults(MESH_FILL_OPTIONS)


def defaultMaxBoundary():
    """Holes with more boundary vertices stay open unless maxBoundary says otherwise (the core's default)."""
    return _MF["maxBoundary"]


def fillMeshHoles(mesh, holes=None, maxBoundary=_MF["maxBoundary"], refine=_MF["refine"], fairIterations=_MF["fairIterations"],
                  smoothIterations=_MF["smoothIterations"], densityFactor=_MF["densityFactor"], closenessScale=_MF["closenessScale"],
                  featureScale=_MF["featureScale"], progress=None, shapeOrder=_MF["shapeOrder"], triangulation=_MF["triangulation"],
                  shapePasses=_MF["shapePasses"], alongNormals=_MF["alongNormals"], weld=_MF["weld"], mode=_MF["mode"],
                  checkCrossings=_MF["checkCrossings"]):
    """Fill holes of `mesh`; returns (new Mesh.Mesh, report dict).

    holes: hole numbers (0-based, as meshHoles numbers them) or MeshHole dicts; None fills every
    fillable hole. Holes with more boundary vertices than maxBoundary stay open (e.g. the border
    of an open scan); 0: no limit. refine=False keeps the bare minimum-angle triangulation. fairIterations,
    smoothIterations, densityFactor (α), closenessScale and featureScale (σ_c, σ_s per local
    density), shapePasses and alongNormals: the shape and fairing steps (0 iterations: off).
    The defaults are the core's (optionSchema("mesh_fill"), as `holefill options mesh_fill` lists
    them). progress(fraction) -> False cancels.
    shapeOrder: 0 flat (the paper's placement), 1 membrane, 2 thin plate (default), 3 minimum
    variation. triangulation: "angle" (the paper's minimum-angle ear cutting, default; better
    across creases), "dihedral" (Liepa's minimum-dihedral program; better on smooth curved holes)
    or "auto" (per hole: minimum angle where a crease of the surrounding mesh reaches the hole).
    mode: "ours" (the defaults) or "paper" (Hu et al.'s pipeline exactly: flat placement, no quality
    passes, the paper's bilateral sigma_c, no crossing check; options given besides it that differ
    from the defaults still apply). checkCrossings: each hole's patch tested exactly for triangles
    crossing each other or the surface and filled again plainer where one does (the report's
    fallback and crossings per hole).
    weld > 0 (e.g. SEAM_WELD): coincident vertices merged first, so that seams of duplicated
    vertices close; the result then starts with the merged mesh, and hole numbers are meshHoles(mesh, weld)'s.
    The report has per hole: new_vertices, new_triangles, min/max/mean_quality (Field's
    2·r_in/R_circ), share_quality_0_7, seconds, message; and closed / closed_when_welded; its
    status is ok, or warned where holes stay open. When holes were asked for and none could be
    filled (or the fill was cancelled), HoleFillError is raised with each hole's reason."""
    v, t = _arrays(mesh)
    indices = [int(h["index"]) if isinstance(h, dict) else int(h) for h in (holes or [])]
    if holes is not None and not indices:
        raise HoleFillApp.HoleFillError("no hole selected: pass hole numbers, or holes=None for all")
    if maxBoundary is None:  # documents and macros of earlier versions: the default
        maxBoundary = _MF["maxBoundary"]
    given = dict(maxBoundary=int(maxBoundary), refine=bool(refine), fairIterations=int(fairIterations),
                 smoothIterations=int(smoothIterations), densityFactor=float(densityFactor), closenessScale=float(closenessScale),
                 featureScale=float(featureScale), shapeOrder=int(shapeOrder), triangulation=str(triangulation),
                 shapePasses=int(shapePasses), alongNormals=bool(alongNormals), weld=float(weld),
                 checkCrossings=bool(checkCrossings))
    # The mode first (a preset), then only what differs from the defaults, so that it stays the preset.
    options = dict(mode=str(mode), **{k: v for k, v in given.items() if v != _MF[k]})
    nv, nt, report = HoleFillApp.fillMeshHoles(v, t, indices, options, progress)
    return _mesh(nv, nt), raiseOnFailure(json.loads(report), "mesh fill")


def makeMeshFill(source, holes=None, maxBoundary=_MF["maxBoundary"], name=None, filled=None, **options):
    """Fill `source` (a Mesh feature) into a new Mesh::Feature of the same document, in one undo
    transaction; the source is left as it is. Returns the new feature; the fill's report is in
    its read-only property HoleFillReport (JSON text). filled: (mesh, report) that fillMeshHoles
    already gave for this source with these holes and options (a Preview's), kept as it is
    instead of filling again."""
    import FreeCAD
    doc = source.Document
    filled, report = filled or fillMeshHoles(source.Mesh, holes=holes, maxBoundary=maxBoundary, **options)
    if report["filled"] == 0:  # nothing failed: there was nothing to fill
        raise HoleFillApp.HoleFillError("no hole was filled: the mesh has no holes")
    doc.openTransaction("Fill mesh holes")
    try:
        feature = doc.addObject("Mesh::Feature", name or (source.Name + "_filled"))
        feature.Label = source.Label + " (filled)"
        feature.Mesh = filled
        feature.addProperty("App::PropertyString", "HoleFillReport", "HoleFill", "JSON report of the fill")
        feature.HoleFillReport = json.dumps(report)
        feature.setEditorMode("HoleFillReport", 1)
        if FreeCAD.GuiUp:
            source.ViewObject.Visibility = False
        doc.recompute()
    except Exception:
        doc.abortTransaction()
        raise
    doc.commitTransaction()
    return feature


def readMesh(path):
    """Read .obj/.off/.ply/.stl with the core's checks (NaN, bad indices, truncation) into a Mesh.Mesh."""
    v, t = HoleFillApp.readMesh(str(path))
    return _mesh(v, t)


def writeMesh(mesh, path):
    """Write a Mesh.Mesh atomically as .obj/.off/.ply/.stl (kept exactly as indexed, duplicates included)."""
    v, t = _arrays(mesh)
    HoleFillApp.writeMesh(v, t, str(path))
