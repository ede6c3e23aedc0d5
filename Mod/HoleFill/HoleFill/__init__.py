"""HoleFill: fill N-sided holes in B-rep models with one trimmed B-spline face.

Macro-friendly API (camelCase like FreeCAD's own):

    import HoleFill
    holes = HoleFill.findHoles(obj.Shape)                    # list of Hole
    face, sewn, report = HoleFill.fillHole(obj.Shape, holes[0], continuity="G1")
    (a, b), model, report = HoleFill.fillAdjacentHoles(obj.Shape, holes[0], sketch.Shape.Edges[0])
    print(report["achieved"], report["g0"], report["g1"])
    fill = HoleFill.makeFill(obj, ["Edge3"], method="auto")     # parametric document object
    HoleFill.renderImage(fill.Shape, "/tmp/fill.png", mode="zebra")  # headless inspection picture
    filled, report = HoleFill.fillMeshHoles(meshObj.Mesh)        # triangle-mesh holes (meshfill.py)
    shell, report = HoleFill.gnurbsSurface(vertices, quads)      # G² surface over a quad cage (gnurbs.py)

Shapes cross into the C++ core (module HoleFillApp) as BREP text and never come
back modified: every result is a new shape. Reports are plain dicts with the
fields of DESIGN.md (g0, g0_relative, g1, g2, requested, achieved, str, per_edge,
timings, ...). Errors raise HoleFillError with a message that says what to do.
"""
import collections
import json

from HoleFill import build_check

build_check.check()  # before the core is loaded: never two OCCTs in one process

import HoleFillApp  # noqa: E402

HoleFillError = HoleFillApp.HoleFillError


def optionSchema(set):
    """An option set's fields as the core declares them (HoleFillApp.optionSetNames(): "fill", ...):
    {name: {"flag", "kind", "unit", "doc", "choices", "minimum", "maximum", "default", ...}}, in the
    order the core lists them. Every door's defaults and tooltips are read from here."""
    return {f["name"]: f for f in json.loads(HoleFillApp.optionSchema(set))}


def optionDefaults(fields):
    """{name: default} of an optionSchema's fields: what the doors' signatures start from."""
    return {name: f["default"] for name, f in fields.items()}


def optionTip(field):
    """A field's tooltip: its doc, and its unit where it has one."""
    return field["doc"] + (" (%s)" % field["unit"] if field["unit"] else "")


FILL_OPTIONS = optionSchema("fill")
FILL_DEFAULTS = optionDefaults(FILL_OPTIONS)
_FILL = FILL_DEFAULTS
METHODS = tuple(FILL_OPTIONS["method"]["choices"])
CONTINUITIES = tuple(FILL_OPTIONS["continuity"]["choices"])


def raiseOnFailure(report, what):
    """The macro API's one rule for a Result's outcome (App/geometry/outcome.h): a report whose
    status is failed or cancelled raises HoleFillError naming `what`, the stage, the message and
    the elements at fault; any other status (ok, and the Result's own name for a missed goal,
    e.g. tolerance_not_met or warned) returns the report to be read."""
    if report.get("status") in ("failed", "cancelled"):
        stage = report.get("failed_stage")
        faulting = report.get("faulty_edges") or []
        raise HoleFillError("%s %s%s: %s%s" % (what, report["status"], " at stage '%s'" % stage if stage else "", report["message"],
                                               " (edges %s)" % ", ".join("Edge%d" % e for e in faulting) if faulting else ""))
    return report


def edgeContinuityEntries(edgeContinuity):
    """{"Edge5": "G0", 7: "G1"} (names or 1-based indices) -> ["Edge5=G0", "Edge7=G1"], as the
    core's edgeContinuity option and the Fill's EdgeContinuity property spell them."""
    return ["%s=%s" % (("Edge%d" % e) if isinstance(e, int) else e, c) for e, c in dict(edgeContinuity or {}).items()]


def pointList(points):
    """Points ((x, y, z) triples or FreeCAD.Vectors) as the core's points option spells them: "x,y,z;x,y,z"."""
    out = []
    for k, p in enumerate(points or []):
        try:
            x, y, z = (float(c) for c in p)
        except (TypeError, ValueError):
            raise HoleFillError("points: point %d (%r) is not three numbers x, y, z" % (k + 1, p)) from None
        out.append("%r,%r,%r" % (x, y, z))
    return ";".join(out)


def _fillOptions(method, continuity, tolerance, angularTolerance, curvatureTolerance, maxControlPoints,
                 edgeContinuity=None, detectCreases=None, modelAccuracy=None, weights=None, points=None):
    """fillHole's keywords as the core's option dict (checked there, by the schema)."""
    o = dict(method=str(method), continuity=str(continuity), tolerance=float(tolerance),
             angularTolerance=float(angularTolerance), curvatureTolerance=float(curvatureTolerance),
             maxControlPoints=int(maxControlPoints))
    if edgeContinuity:
        o["edgeContinuity"] = ",".join(edgeContinuityEntries(edgeContinuity))
    for name, value in (("detectCreases", detectCreases), ("modelAccuracy", modelAccuracy)):
        if value is not None:
            o[name] = bool(value)
    if weights is not None:
        o["weights"] = str(weights)
    if points:
        o["points"] = pointList(points)
    return o

__all__ = ["optionSchema", "optionTip", "FILL_OPTIONS", "findHoles", "fillHole", "fillHoles", "prepareHole", "PreparedHole", "FilledHole", "fillAdjacentHoles", "projectionSurface", "learnInfo", "continuityReport", "makeFill", "Hole", "HoleFillError", "METHODS",
           "CONTINUITIES", "renderImage", "curvatureMap", "inspectionMesh", "faceContinuity", "continuityAlong", "meshHoles",
           "fillMeshHoles", "makeMeshFill", "readMesh", "writeMesh", "MeshHole", "gnurbsSurface", "cageFromShape", "readCage",
           "sampleCage", "makeGnurbs", "cageShell", "importCage", "extraordinaryPoints", "fitLabeled"]


class Hole(dict):
    """One free-boundary loop: index (1-based), edges ("EdgeK" names in loop order),
    edgeIndices, corners (N), length and scale (model units), supportFaces."""

    @property
    def edges(self):
        return self["edges"]

    @property
    def corners(self):
        return self["corners"]

    def __repr__(self):
        return "Hole(%d: N=%d, %d edges, length %.6g)" % (self["index"], self["corners"], len(self["edges"]),
                                                          self["length"])


def _brep(shape):
    if shape is None or shape.isNull():
        raise HoleFillError("the shape is empty: select a shell, an open solid or a compound of faces")
    return shape.exportBrepToString()


def _shape(brep):
    import Part
    s = Part.Shape()
    s.importBrepFromString(brep.decode() if isinstance(brep, bytes) else brep)
    return s


def _hole(d):
    h = Hole(d)
    h["edgeIndices"] = d["edge_indices"]
    h["supportFaces"] = d["support_faces"]
    return h


def findHoles(shape, includeOuter=False, cornerAngle=5.0):
    """Holes of a shape (shell, open solid, compound of faces): a list of Hole.
    Outer boundaries of open sheets are left out unless includeOuter is True.
    cornerAngle (degrees) is the tangent break that counts as a corner."""
    d = json.loads(HoleFillApp.findHoles(_brep(shape), includeOuter, float(cornerAngle)))
    holes = [_hole(h) for h in d["holes"]]
    if includeOuter:
        known = {tuple(h["edge_indices"]) for h in d["holes"]}
        holes += [_hole(h) for h in d["outer_boundaries"] if tuple(h["edge_indices"]) not in known]
    return holes


def _edgeIndices(shape, hole):
    """Accepts a Hole, a 1-based hole number, "EdgeK" names or 1-based edge indices."""
    if isinstance(hole, dict):
        return list(hole["edge_indices"])
    if isinstance(hole, int):
        holes = findHoles(shape)
        if not holes:
            raise HoleFillError("the shape has no holes")
        if hole < 1 or hole > len(holes):
            raise HoleFillError("hole %d does not exist: the shape has %d hole(s)" % (hole, len(holes)))
        return list(holes[hole - 1]["edge_indices"])
    if isinstance(hole, str):
        hole = [hole]
    out = []
    for e in hole:
        if isinstance(e, str):
            if not e.startswith("Edge") or not e[4:].isdigit():
                raise HoleFillError("'%s' is not an edge name: use names like 'Edge3'" % e)
            out.append(int(e[4:]))
        else:
            out.append(int(e))
    if not out:
        raise HoleFillError("no edges given: name at least one edge of the hole")
    return out


def _holeKey(hole):
    """What a hole argument names, comparable: a number, or its edges."""
    if isinstance(hole, int):
        return hole
    if isinstance(hole, dict):
        return tuple(hole["edges"])
    return tuple(hole)


FilledHole = collections.namedtuple("FilledHole", "face sewn report")
FilledHole.__doc__ = """What fillHole and PreparedHole.fill return, always the same three: `face` (a Part.Face),
`sewn` (a copy of the model with the face sewn in; None when asked with sewn=False) and `report`
(a dict: status, achieved, per-edge continuity, warnings). Unpacks as face, sewn, report."""


class PreparedHole:
    """A hole of a shape, read and found once and filled as often as asked (prepareHole): its
    boundary samples and parameterizations (UVTran's network, MVC's interior references) are kept
    between fills, so a fill that changes only the method, continuity, tolerances or per-edge
    requests pays for the solve, build and check alone. The shape is never modified."""

    def __init__(self, shape, hole=1):
        self.shape = shape  # what it was read from (a Fill handed this hole checks it is its source's)
        self.asked = _holeKey(hole)
        self.edges = _edgeIndices(shape, hole)
        self._prepared = HoleFillApp.PreparedHole(_brep(shape), self.edges)

    def isFor(self, shape, hole):
        """Whether this is the hole `hole` names of this very `shape` (a kept one can be reused)."""
        return self.asked == _holeKey(hole) and self.shape.isSame(shape)

    def computed(self):
        """(boundary samplings, parameterizations) computed so far; the rest were reused."""
        return self._prepared.computed()

    def fill(self, method=_FILL["method"], continuity=_FILL["continuity"], tolerance=_FILL["tolerance"],
             angularTolerance=_FILL["angularTolerance"], curvatureTolerance=_FILL["curvatureTolerance"],
             maxControlPoints=_FILL["maxControlPoints"], progress=None, sewn=True, edgeContinuity=None,
             detectCreases=_FILL["detectCreases"], modelAccuracy=_FILL["modelAccuracy"], weights=_FILL["weights"],
             points=None):
        """As fillHole, on this hole: a FilledHole (face, sewn, report)."""
        options = _fillOptions(method, continuity, tolerance, angularTolerance, curvatureTolerance, maxControlPoints,
                               edgeContinuity, detectCreases, modelAccuracy, weights, points)
        # The last fill is kept: asked again with the same options (a Preview, then OK), it is
        # returned as it was, not solved again.
        key = (json.dumps(options, sort_keys=True), bool(sewn))
        last = getattr(self, "_last", None)
        if last is not None and last[0] == key:
            face, model, rep = last[1]
        else:
            face, model, rep = self._prepared.fill(options, progress, bool(sewn))
        report = raiseOnFailure(json.loads(rep), "fill")
        self._last = (key, (face, model, rep))
        return FilledHole(_shape(face).Faces[0], _shape(model) if sewn else None, report)


    def alternatives(self, method, continuity, progress=None, **options):
        """What else fills this hole: each other method at `continuity`, then every method at
        each lower continuity, filled with the other `options` as given (fill's keywords; not
        sewn). Returns those that reach a tier, best first (the higher tier, then the smaller
        position gap), as dicts: method, continuity, achieved, g0 (model units), g0_relative and
        g1. A fill that reaches no tier (a parameterization that leaves a gap along the loop
        or folds) is what a user asks this for; the hole's last fill is kept as it was.
        progress: callable(fraction) -> bool over all the trials; False cancels the rest."""
        lower = CONTINUITIES[:CONTINUITIES.index(continuity) + 1]
        trials = [(m, continuity) for m in METHODS if m != method]
        trials += [(m, c) for c in reversed(lower[:-1]) for m in METHODS]
        rank = {c: k for k, c in enumerate(("none",) + CONTINUITIES)}
        last = getattr(self, "_last", None)
        found = []
        try:
            for k, (m, c) in enumerate(trials):
                if progress is not None and not progress(k / len(trials)):
                    break
                try:
                    _, _, report = self.fill(method=m, continuity=c, sewn=False, **options)
                except HoleFillError:
                    continue
                if report["achieved"] == "none":
                    continue
                found.append(dict(method=m, continuity=c, achieved=report["achieved"], g0=report["g0"],
                                  g0_relative=report["g0_relative"], g1=report["g1"]))
        finally:
            self._last = last
        found.sort(key=lambda a: (-rank[a["achieved"]], a["g0_relative"]))
        return found


def prepareHole(shape, hole=1):
    """A PreparedHole: `hole` of `shape` (as in fillHole) read and found once, for several fills
    (prepared.fill(...) takes fillHole's options), e.g. a Preview that tries continuities."""
    return PreparedHole(shape, hole)


def fillHole(shape, hole=1, method=_FILL["method"], continuity=_FILL["continuity"], tolerance=_FILL["tolerance"],
             angularTolerance=_FILL["angularTolerance"], curvatureTolerance=_FILL["curvatureTolerance"],
             maxControlPoints=_FILL["maxControlPoints"], progress=None, sewn=True, edgeContinuity=None,
             detectCreases=_FILL["detectCreases"], modelAccuracy=_FILL["modelAccuracy"], weights=_FILL["weights"],
             points=None):
    """Fill one hole of `shape` with a trimmed B-spline face.

    hole: a Hole from findHoles, its 1-based number, or edge names/indices on its loop.
    method: "auto" (np for height-field-like holes, else mvc), "np" (nearest plane),
    "mvc" (regular N-gon with mean value mapping) or "uvtran" (learned projection surface;
    falls back to mvc with a warning in the report when it cannot be used).
    continuity: "G0", "G1" or "G2"; tolerance (model units, 0 = 1e-6 x hole size) for G0,
    angularTolerance (radians) for G1, curvatureTolerance (relative) for G2.
    progress: callable(fraction) -> bool; return False to cancel.
    continuity is the most any edge is asked for: edges where the loop's corners show the model
    was sharp (creases) are asked G0 unless detectCreases is False; edgeContinuity, e.g.
    {"Edge5": "G0", "Edge7": "G1"}, sets edges explicitly. report["edge_continuity"] lists per
    edge what was asked, why (request, crease, override) and what was reached.
    modelAccuracy: an edge of an inexact model (its own BRep tolerance above the G0 tolerance, or a
    neighbour meeting its curve at an angle, report["per_edge"][k]["g1_floor"]) is judged no
    stricter than the model is there, and the message names such edges; False: the tiers alone.
    weights: UVTran's weights file (.pt, from `holefill train uvtran`); "" for the shipped one.
    maxControlPoints: the most poles the solver's refinement may reach.
    points: (x, y, z) points inside the hole (model units) the face passes through, as Surface
    Filling's vertex constraints; report["point_distances"] gives each one's distance to the face,
    and a point missed by more than the G0 tolerance makes the fill tolerance_not_met.
    The defaults are the core's (optionSchema("fill"), as `holefill options fill` lists them).
    Returns a FilledHole (face, sewn, report): the Part.Face, a copy of the model with the face sewn
    in (None with sewn=False, which saves the sewing), and the report.
    The report says what was achieved; a fill that misses the request is returned with
    report["status"] == "tolerance_not_met". A failed fill raises HoleFillError."""
    return PreparedHole(shape, hole).fill(method, continuity, tolerance, angularTolerance, curvatureTolerance,
                                          maxControlPoints, progress, sewn, edgeContinuity, detectCreases,
                                          modelAccuracy, weights, points)


def fillHoles(shape, method=_FILL["method"], continuity=_FILL["continuity"], tolerance=_FILL["tolerance"],
              angularTolerance=_FILL["angularTolerance"], curvatureTolerance=_FILL["curvatureTolerance"],
              maxControlPoints=_FILL["maxControlPoints"], progress=None, detectCreases=_FILL["detectCreases"],
              modelAccuracy=_FILL["modelAccuracy"], weights=_FILL["weights"]):
    """Every hole of `shape`, one after the other, each filled into the model the one before
    returned (as `holefill fill --hole all`): (Part.Shape with all of them sewn in, [report per
    hole]). Options as in fillHole. A fill that fails raises HoleFillError naming its hole; the
    shape is never modified."""
    options = _fillOptions(method, continuity, tolerance, angularTolerance, curvatureTolerance, maxControlPoints,
                           None, detectCreases, modelAccuracy, weights)
    model, reports = HoleFillApp.fillHoles(_brep(shape), options, progress)
    reports = [json.loads(r) for r in reports]
    for k, r in enumerate(reports):
        raiseOnFailure(r, "fill of hole %d of %d" % (k + 1, len(reports)))
    return _shape(model), reports


def fillAdjacentHoles(shape, hole, divider, method=_FILL["method"], continuity=_FILL["continuity"],
                      tolerance=_FILL["tolerance"], angularTolerance=_FILL["angularTolerance"],
                      curvatureTolerance=_FILL["curvatureTolerance"], maxControlPoints=_FILL["maxControlPoints"],
                      progress=None):
    """Two adjacent holes: the loop of `hole` (as in fillHole) split by `divider`, an edge (e.g. a
    sketch's) running across it from one vertex of the loop to another, filled as two faces that
    share that edge: the first side is asked G0 along it, the second side `continuity` there as on
    its other edges, so the two faces meet at the second fill's tolerances.
    Returns ((Part.Face, Part.Face), the model with both faces as a Part.Shape, report); the
    report holds "fills" (the two sides' reports), "across" (the continuity the two faces share
    along "shared_edge") and "status". A failed fill raises HoleFillError."""
    options = _fillOptions(method, continuity, tolerance, angularTolerance, curvatureTolerance, maxControlPoints)
    edges = _edgeIndices(shape, hole)
    faces, model, rep = HoleFillApp.fillAdjacentHoles(_brep(shape), edges, _brep(divider), options, progress)
    report = raiseOnFailure(json.loads(rep), "adjacent fill")
    fs = _shape(faces).Faces
    return (fs[0], fs[1]), _shape(model), report


def projectionSurface(shape, hole=1, weights=""):
    """UVTran's predicted projection surface for a hole (a Part.Face over its whole domain):
    the surface the "uvtran" method projects the hole boundary onto to get the pcurve.
    hole as in fillHole; weights: a .pt file, "" for the shipped ones."""
    return _shape(HoleFillApp.uvtranSurface(_brep(shape), _edgeIndices(shape, hole), weights)).Faces[0]


def learnInfo():
    """The learned-model backend, e.g. "libtorch 1.13.1 (2 threads) from .../libholefill_learn.so"."""
    return HoleFillApp.learnInfo()


def continuityReport(face, shape, hole=None):
    """G0/G1/G2 of `face` (any face, e.g. a Surface Filling result) against a hole of `shape`.
    hole as in fillHole; None takes the only hole of the shape."""
    if hole is None:
        holes = findHoles(shape)
        if len(holes) != 1:
            raise HoleFillError("the shape has %d holes: say which one" % len(holes))
        hole = holes[0]
    return json.loads(HoleFillApp.continuityReport(_brep(face), _brep(shape), _edgeIndices(shape, hole)))


def makeFill(source, edges=None, method=_FILL["method"], continuity=_FILL["continuity"], tolerance=_FILL["tolerance"],
             angularTolerance=_FILL["angularTolerance"], output="Face", doc=None, edgeContinuity=None,
             weights=_FILL["weights"], prepared=None, points=None):
    """Create a parametric Fill object on `source` (a document object with a Shape).
    edges: "EdgeK" names on the hole's loop (one edge is enough); None takes hole 1.
    edgeContinuity: per-edge requests as in fillHole, kept in the EdgeContinuity property;
    weights: UVTran's weights file as in fillHole, kept in the Weights property.
    points: points the face passes through as in fillHole, kept in the Points property.
    prepared: a PreparedHole (prepareHole) of this source's shape and these edges, e.g. the one
    a Preview filled: the object's first recompute then neither reads the model nor finds the hole
    again, and solves nothing when its options are those of the prepared hole's last fill.
    The object recomputes when the source changes; the source is never modified.
    Runs inside an undo transaction; on failure the document is left as it was and
    HoleFillError is raised."""
    from HoleFill import fill_feature
    return fill_feature.makeFill(source, edges, method, continuity, tolerance, angularTolerance, output, doc,
                                 edgeContinuity, weights, prepared, points)


from HoleFill.inspection import continuityAlong, curvatureMap, faceContinuity, inspectionMesh, renderImage  # noqa: E402
from HoleFill.meshfill import (MeshHole, SEAM_WELD, defaultMaxBoundary, fillMeshHoles, makeMeshFill, meshHoles, readMesh,  # noqa: E402
                               weldVertices, writeMesh)
from HoleFill.labeled import fitLabeled, boundaryLoop, cornerSplits, makeBoundaryLabels, makeLabeledFit  # noqa: E402
from HoleFill.pointcloud import fitPoints, makePointCloudFit, parameterize  # noqa: E402
from HoleFill.gnurbs import (cageFromShape, cageShell, extraordinaryPoints, gnurbsSurface, importCage, makeGnurbs,  # noqa: E402
                             readCage, sampleCage)
