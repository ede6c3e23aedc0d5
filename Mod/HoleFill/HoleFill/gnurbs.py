"""G² G-NURBS surfaces over quad cages (g2-gnurbs paper): a curvature-continuous spline surface
whose faces follow a quad control mesh with extraordinary points, as a B-rep shell.

    import HoleFill
    shell, report = HoleFill.gnurbsSurface(vertices, quads, sharpEdges=[(3, 4)])
    print(report["continuity"]["g2_spokes"], report["faces"][0])   # Face1 -> control face, sub-patch
    cage = HoleFill.cageFromShape(obj.Shape)                        # a Part shell of quads as a cage
    feature = HoleFill.makeGnurbs(obj)                              # parametric, follows the cage

Indices are 0-based here (NumPy rows); OBJ cage files are 1-based, as OBJ is. Knot intervals
are (i, j, d) triples, sharp edges (i, j) pairs, anchors {vertex: (x, y, z)} at extraordinary
points. The cage is never modified. Errors raise HoleFillError naming the vertex or quad.
"""
import json
from functools import partial

import HoleFillApp
from HoleFill import optionDefaults, optionSchema, optionTip
from HoleFill.transaction import ParametricFeature, ensureProperty

__all__ = ["gnurbsSurface", "cageFromShape", "readCage", "sampleCage", "makeGnurbs", "GnurbsFeature", "cageShell", "importCage",
           "extraordinaryPoints"]


def _shape(brep):
    import Part
    s = Part.Shape()
    s.importBrepFromString(brep.decode() if isinstance(brep, bytes) else brep)
    return s


GNURBS_OPTIONS = optionSchema("gnurbs")
_GN = optionDefaults(GNURBS_OPTIONS)


def gnurbsSurface(vertices, quads, knots=None, sharpEdges=(), anchors=None, refine=_GN["refine"], mergeRegular=_GN["mergeRegular"],
                  target=None, fitRounds=_GN["fitRounds"], maxValence=_GN["maxValence"], solve=_GN["solve"]):
    """The G² surface over the cage: (Part.Shape shell, report dict). The report holds the
    construction's diagnostics (extraordinary_points, refinements and why, constraint_residual,
    warnings), the continuity reached (g1/g2 on spoke edges and elsewhere), the B-rep checks, and
    "faces": for Face1, Face2, ... the control face and sub-patch (-1: the face's bicubic patch).
    refine=False refuses cages that need a Catmull-Clark step instead of refining them.
    mergeRegular=True merges rectangles of regular faces into one C² B-spline face each (the
    report's "faces" then lists a merged face's "control_faces").
    maxValence: EPs of higher valence are refused (0: no limit); solve: "fair" or "stepwise" (the
    paper's steps) for each EP's 1-ring. The defaults are the core's (optionSchema("gnurbs")).
    target: points (N×3, or a Points/Mesh object's points) to fit the cage to first, in fitRounds
    rounds; the report then holds "fit" (d_max_percent, d_avg_percent of the
    target's diagonal, ...) and "cage_vertices_fitted", the moved cage vertices."""
    import numpy as np
    v = np.asarray(vertices, dtype=float).reshape(-1, 3)
    q = np.asarray(quads, dtype=np.int32)
    if q.ndim != 2 or q.shape[1] != 4:
        raise HoleFillApp.HoleFillError("quads must be rows of 4 vertex indices, got shape %s" % (q.shape,))
    k = [(int(a), int(b), float(d)) for a, b, d in (knots or [])]
    s = [(int(a), int(b)) for a, b in sharpEdges]
    anc = {int(i): tuple(float(c) for c in p) for i, p in (anchors or {}).items()}
    options = dict(refine=bool(refine), mergeRegular=bool(mergeRegular), fitRounds=int(fitRounds), maxValence=int(maxValence),
                   solve=str(solve))
    extra = {}
    if target is not None:
        from HoleFill.pointcloud import _points
        extra["target"] = _points(target)
    brep, sidecar, report, fitted = HoleFillApp.gnurbsSurface(v, q, k, s, anc, options, 0, **extra)
    rep = json.loads(report)
    if target is not None:
        rep["cage_vertices_fitted"] = fitted
    rep["faces"] = json.loads(sidecar)["faces"]
    return _shape(brep), rep


def readCage(path):
    """A quad cage OBJ as a dict (vertices, quads, knots, sharpEdges, anchors), 0-based."""
    v, q, k, s, a = HoleFillApp.readCage(path)
    return {"vertices": v, "quads": q, "knots": k, "sharpEdges": s, "anchors": {i: tuple(p) for i, p in a.items()}}


def sampleCage(name):
    """One of the bundled cages (HoleFillApp.sampleCageNames()) as readCage gives it."""
    import os
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, name + ".obj")
        with open(path, "w") as f:
            f.write(HoleFillApp.sampleCageObj(name))
        return readCage(path)


def cageFromShape(shape, tolerance=None):
    """A Part shape made of quadrilateral faces (a shell, compound or solid, e.g. from an imported
    OBJ or a Draft/Part construction) as a cage dict: one cage vertex per distinct shape vertex,
    one quad per face, its corners in the order of the face's outer wire as the face is oriented.
    Faces with other than 4 vertices are refused by name."""
    if shape is None or shape.isNull() or not shape.Faces:
        raise HoleFillApp.HoleFillError("the shape has no faces: select a shell or compound of quadrilateral faces")
    tol = tolerance if tolerance is not None else 1e-7 * max(shape.BoundBox.DiagonalLength, 1e-12)
    points, index = [], {}

    def vid(p):
        key = (round(p.x / tol), round(p.y / tol), round(p.z / tol))
        if key not in index:
            index[key] = len(points)
            points.append((p.x, p.y, p.z))
        return index[key]

    quads = []
    faces = shape.Faces
    for n, face in enumerate(faces, 1):
        wire = face.OuterWire
        verts = [v.Point for v in wire.OrderedVertexes]
        if len(verts) != 4:
            raise HoleFillApp.HoleFillError("Face%d has %d corners; a G-NURBS cage must be all quads" % (n, len(verts)))
        ids = [vid(p) for p in verts]
        # The outer wire runs anticlockwise about the face's normal when the face is FORWARD.
        if face.Orientation == "Reversed":
            ids.reverse()
        quads.append(ids)
    # Orient every quad like the first one, across shared edges (a cage from an unoriented compound).
    quads = _orientConsistently(quads)
    # The cage edge behind each edge of the shape (EdgeK names, as FreeCAD's selection gives them).
    shapeEdges = {}
    for n, edge in enumerate(shape.Edges, 1):
        if len(edge.Vertexes) == 2:
            a, b = vid(edge.Vertexes[0].Point), vid(edge.Vertexes[1].Point)
            if a != b:
                shapeEdges["Edge%d" % n] = (min(a, b), max(a, b))
    return {"vertices": points, "quads": quads, "knots": [], "sharpEdges": [], "anchors": {}, "shapeEdges": shapeEdges}


def extraordinaryPoints(cage):
    """{vertex: valence} of the cage's interior vertices whose valence is not 4."""
    uses, nbr = {}, {}
    for q in cage["quads"]:
        for k in range(4):
            a, b = int(q[k]), int(q[(k + 1) % 4])
            e = (min(a, b), max(a, b))
            uses[e] = uses.get(e, 0) + 1
            nbr.setdefault(a, set()).add(b)
            nbr.setdefault(b, set()).add(a)
    boundary = {v for e, n in uses.items() if n == 1 for v in e}
    return {v: len(ns) for v, ns in nbr.items() if v not in boundary and len(ns) != 4}


def cageShell(cage):
    """The cage as a Part shell of bilinear (ruled) quads: how a cage read from a file is shown
    and edited in FreeCAD (its vertices and quads come back unchanged through cageFromShape)."""
    import FreeCAD
    import Part
    v = [FreeCAD.Vector(*[float(c) for c in p]) for p in cage["vertices"]]
    faces = [Part.makeRuledSurface(Part.makeLine(v[int(a)], v[int(b)]), Part.makeLine(v[int(d)], v[int(c)]))
             for a, b, c, d in cage["quads"]]
    return Part.makeShell(faces)


def importCage(path, doc=None, name="Cage"):
    """Reads a quad cage OBJ into a new Part::Feature of `doc` (the active document by default);
    returns (object, cage dict): its sharp edges and anchors (from '# sharp' / '# anchor' lines)
    numbered as cageFromShape numbers the object's shape."""
    import FreeCAD
    doc = doc or FreeCAD.ActiveDocument or FreeCAD.newDocument()
    cage = readCage(path)
    shell = cageShell(cage)
    back = cageFromShape(shell)
    # Renumber the file's sharp edges and anchors through positions (the shape's numbering).
    index = {tuple(round(c, 9) for c in p): i for i, p in enumerate(back["vertices"])}
    to = [index[tuple(round(float(c), 9) for c in p)] for p in cage["vertices"]]
    back["sharpEdges"] = [(to[a], to[b]) for a, b in cage["sharpEdges"]]
    back["anchors"] = {to[i]: p for i, p in cage["anchors"].items()}
    back["knots"] = [(to[a], to[b], d) for a, b, d in cage["knots"]]
    doc.openTransaction("Import quad cage")
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = shell
    doc.commitTransaction()
    doc.recompute()
    return obj, back


def _orientConsistently(quads):
    from collections import deque
    owner = {}
    for f, q in enumerate(quads):
        for k in range(4):
            owner.setdefault(frozenset((q[k], q[(k + 1) % 4])), []).append(f)
    seen = [False] * len(quads)
    out = [list(q) for q in quads]
    for start in range(len(quads)):
        if seen[start]:
            continue
        seen[start] = True
        todo = deque([start])
        while todo:
            f = todo.popleft()
            q = out[f]
            for k in range(4):
                a, b = q[k], q[(k + 1) % 4]
                for g in owner[frozenset((a, b))]:
                    if g == f or seen[g]:
                        continue
                    r = out[g]
                    # A consistently oriented neighbour runs the shared edge the other way (b -> a).
                    if any(r[m] == a and r[(m + 1) % 4] == b for m in range(4)):
                        r.reverse()
                    seen[g] = True
                    todo.append(g)
    return out


class GnurbsFeature(ParametricFeature):
    """A Part::FeaturePython whose Shape is the G² surface over its Source's quad faces, rebuilt
    whenever the source changes. SharpEdges and Anchors refer to cage vertices (0-based) as
    cageFromShape numbers them."""

    def setupProperties(self, obj):
        add = partial(ensureProperty, obj)

        add("App::PropertyLink", "Source", "G-NURBS", "Object whose faces are the quad cage")
        add("App::PropertyStringList", "SharpEdges", "G-NURBS", "Crease edges as 'i-j' (cage vertices, 0-based)")
        add("App::PropertyStringList", "Anchors", "G-NURBS", "Anchors as 'i: x y z' at sharp extraordinary points")
        add("App::PropertyStringList", "Knots", "G-NURBS", "Knot intervals as 'i-j: d' (default 1)")
        add("App::PropertyBool", "Refine", "G-NURBS", optionTip(GNURBS_OPTIONS["refine"]))
        for name, doc in (("Report", "construction and continuity report (JSON)"), ("Status", "ok, or the warnings")):
            add("App::PropertyString", name, "Report", doc)
            obj.setEditorMode(name, 1)
        for name, doc in (("G1", "max normal angle across spoke edges (rad)"), ("G2", "max relative curvature jump across spoke edges")):
            add("App::PropertyFloat", name, "Report", doc)
            obj.setEditorMode(name, 1)

    def execute(self, obj):
        if obj.Source is None or not hasattr(obj.Source, "Shape"):
            raise HoleFillApp.HoleFillError("G-NURBS surface has no source object with a shape")
        cage = cageFromShape(obj.Source.Shape)
        sharp = [tuple(int(x) for x in e.split("-")) for e in obj.SharpEdges]
        anchors = {}
        for a in obj.Anchors:
            head, rest = a.split(":")
            anchors[int(head)] = tuple(float(x) for x in rest.split())
        knots = []
        for k in (obj.Knots if hasattr(obj, "Knots") else []):
            edge, d = k.split(":")
            a, b = edge.split("-")
            knots.append((int(a), int(b), float(d)))
        shell, report = gnurbsSurface(cage["vertices"], cage["quads"], knots=knots, sharpEdges=sharp, anchors=anchors,
                                      refine=obj.Refine)
        obj.Shape = shell
        obj.G1 = report["continuity"]["g1_spokes"]
        obj.G2 = report["continuity"]["g2_spokes"]
        obj.Status = "; ".join(report["warnings"]) or "ok"
        obj.Report = json.dumps(report)



def makeGnurbs(source, sharpEdges=(), anchors=None, refine=True, name="GNurbs", knots=()):
    """A parametric G-NURBS surface over `source` (a document object with quad faces) in one undo
    transaction; the source is only read. Returns the new object, or raises with nothing added."""
    if source is None or not hasattr(source, "Shape"):
        raise HoleFillApp.HoleFillError("makeGnurbs needs a document object with a shape as source")

    def setup(obj):
        GnurbsFeature(obj)
        obj.Source = source
        obj.SharpEdges = ["%d-%d" % (int(a), int(b)) for a, b in sharpEdges]
        obj.Anchors = ["%d: %r %r %r" % (int(i), float(p[0]), float(p[1]), float(p[2])) for i, p in (anchors or {}).items()]
        obj.Refine = bool(refine)
        obj.Knots = ["%d-%d: %r" % (int(a), int(b), float(d)) for a, b, d in knots]

    from HoleFill.transaction import addParametric
    return addParametric(source.Document, "G-NURBS surface", name, setup, "the G-NURBS surface")
