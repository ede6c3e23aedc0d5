"""Point clouds (bidgcn paper): parameterization and adaptive spline fitting.

`parameterize` gives (u, v) for every point of a scanned cloud whose boundary points have known
parameters: by convex combinations of neighbours within a radius — shape-preserving (Floater;
the default), inverse-distance or uniform weights (sec. 3.2) — or by the learned BIDGCN network
(sec. 4, method="bidgcn"). `fitPoints` fits a THB-spline surface to a cloud (sec. 5): boundary
found when not given, parameters as above, adaptive refinement and parameter correction until
the largest point error is within the tolerance.

    import HoleFill
    uv, report = HoleFill.parameterize(points, {0: (0, 0), 1: (0.1, 0), ...}, method="shape")
    face, report = HoleFill.fitPoints(doc.Points.Points, method="bidgcn", tolerance=0.05)  # mm
    print(report["iterations"][-1]["dof"], max(report["errors"]))

`points`: FreeCAD vectors, (x, y, z) tuples, a Points.Points or Mesh.Mesh (its vertices), or an
N×3 array. The radius is in the cloud scaled into the unit cube (0: 3/sqrt(N)); `tolerance` is in
model units, `relativeTolerance` of the cloud's diagonal. Errors raise HoleFillError.
"""
import json

import HoleFillApp
from HoleFill import _shape, optionDefaults, optionSchema, optionTip
from HoleFill.transaction import ParametricFeature

__all__ = ["parameterize", "fitPoints", "makePointCloudFit"]


def _points(points):
    import numpy as np
    if hasattr(points, "Points") and not isinstance(points, (list, tuple)):
        points = points.Points
    out = []
    for p in points:
        if hasattr(p, "Vector"):
            p = p.Vector
        out.append((float(p[0]), float(p[1]), float(p[2])) if not hasattr(p, "x") else (p.x, p.y, p.z))
    return np.array(out, dtype=float).reshape(-1, 3)


def parameterize(points, boundary, method="shape", radius=0.0, weights=""):
    """(uv, report): an N×2 array of parameters (boundary points keep theirs) and a dict.
    `boundary`: {point index: (u, v)} for the boundary points (at least 3); `weights`: a BIDGCN
    weights file (empty: the shipped one)."""
    import numpy as np
    p = _points(points)
    flags = [False] * len(p)
    buv = np.zeros((len(p), 2))
    for k, uv in dict(boundary).items():
        k = int(k)
        if not 0 <= k < len(p):
            raise HoleFillApp.HoleFillError("boundary index %d is not a point of the cloud (0..%d)" % (k, len(p) - 1))
        flags[k] = True
        buv[k] = (float(uv[0]), float(uv[1]))
    uv, report = HoleFillApp.parameterizeCloud(p, flags, buv, str(method), float(radius), str(weights))
    return uv, json.loads(report)


POINT_FIT_OPTIONS = optionSchema("point_fit")
_PF = optionDefaults(POINT_FIT_OPTIONS)
# The PointCloudFit object's properties and the options they hold.
POINT_FIT_PROPERTIES = {"Method": "method", "Tolerance": "tolerance", "RelativeTolerance": "relativeTolerance", "Degree": "degree",
                        "Adaptive": "adaptive", "Iterations": "iterations", "Weights": "weights"}


def fitPoints(points, boundary=None, corners=None, method=_PF["method"], tolerance=_PF["tolerance"],
              relativeTolerance=_PF["relativeTolerance"], degree=_PF["degree"], adaptive=_PF["adaptive"], cells=_PF["cells"],
              iterations=_PF["iterations"], radius=_PF["radius"], weights=_PF["weights"], smoothing=_PF["smoothing"]):
    """(face, report): a Part.Face of the fitted B-spline (exact at the finest level) and a dict
    with the parameterization's report, per-iteration degrees of freedom, MSE and max error
    (relative to the diagonal), `levels`, `met_tolerance`, `tolerance` (model units),
    `relative_tolerance`, `diagonal`, `folds` (domain samples of 65 × 65 where the surface folds
    over), `uv` and `errors` per point (model units), `cells` (the hierarchical mesh: (level, u0,
    v0, u1, v1) rows) and `boundary` (the boundary point indices used).

    `boundary`: None — a Mesh's outer boundary loop, else found (alpha shape); a list of point
    indices (their parameters by chord length between `corners`, four indices, or the four
    sharpest turns); or {index: (u, v)}. `tolerance`: the largest point distance wanted, in model
    units (0: `relativeTolerance` of the bounding-box diagonal). `adaptive=False` fits one uniform
    level. The defaults are the core's (optionSchema("point_fit"), as `holefill options point_fit`
    lists them)."""
    import numpy as np
    mesh = points if hasattr(points, "Topology") else None
    p = _points(points)
    n = len(p)
    flags, buv, given = [], np.zeros((n, 2)), False
    if boundary is None and mesh is not None:
        from HoleFill.labeled import boundaryLoop
        boundary = boundaryLoop(mesh)[0]
    if boundary is not None:
        flags = [False] * n
        items = dict(boundary).items() if isinstance(boundary, dict) else [(k, None) for k in boundary]
        for k, uv in items:
            k = int(k)
            if not 0 <= k < n:
                raise HoleFillApp.HoleFillError("boundary index %d is not a point of the cloud (0..%d)" % (k, n - 1))
            flags[k] = True
            if uv is not None:
                buv[k] = (float(uv[0]), float(uv[1]))
        given = isinstance(boundary, dict)
    options = dict(method=str(method), tolerance=float(tolerance), relativeTolerance=float(relativeTolerance), degree=int(degree),
                   adaptive=bool(adaptive), cells=int(cells), iterations=int(iterations), radius=float(radius), weights=str(weights),
                   smoothing=float(smoothing))
    brep, report, uv, errors, rects, used = HoleFillApp.fitPointCloud(p, flags, buv, given, [int(c) for c in (corners or [])], options)
    r = json.loads(report)
    r.update(uv=uv, errors=errors, cells=rects, boundary=[k for k in range(n) if used[k]])
    return _shape(brep).Faces[0], r


def _sourcePoints(obj):
    """The cloud of a Points object or the Mesh of a Mesh object (placement applied)."""
    if hasattr(obj, "Points") and hasattr(obj.Points, "Points"):
        pts = obj.Points.copy()
        pts.Placement = obj.Placement
        return [p for p in pts.Points]
    if hasattr(obj, "Mesh"):
        m = obj.Mesh.copy()
        m.Placement = obj.Placement
        return m
    raise HoleFillApp.HoleFillError("%s is neither a Points nor a Mesh object" % getattr(obj, "Label", obj))


class PointCloudFitFeature(ParametricFeature):
    """A B-spline face fitted to a Points or Mesh object (fitPoints); recomputes when the source
    or the options change. Report holds the fit's numbers (JSON)."""

    def setupProperties(self, obj):
        from functools import partial
        from HoleFill.transaction import ensureProperty
        add = partial(ensureProperty, obj)
        tip = {prop: optionTip(POINT_FIT_OPTIONS[name]) for prop, name in POINT_FIT_PROPERTIES.items()}
        default = {prop: POINT_FIT_OPTIONS[name]["default"] for prop, name in POINT_FIT_PROPERTIES.items()}
        add("App::PropertyLink", "Source", "Fit", "The Points or Mesh object fitted")
        if "Method" not in obj.PropertiesList:
            obj.addProperty("App::PropertyEnumeration", "Method", "Fit", tip["Method"])
            obj.Method = POINT_FIT_OPTIONS["method"]["choices"]
            obj.Method = default["Method"]
        add("App::PropertyLength", "Tolerance", "Fit", tip["Tolerance"], default["Tolerance"])
        add("App::PropertyFloat", "RelativeTolerance", "Fit", tip["RelativeTolerance"], default["RelativeTolerance"])
        f = POINT_FIT_OPTIONS["degree"]
        add("App::PropertyIntegerConstraint", "Degree", "Fit", tip["Degree"], (default["Degree"], int(f["minimum"]), int(f["maximum"]), 1))
        add("App::PropertyBool", "Adaptive", "Fit", tip["Adaptive"], default["Adaptive"])
        f = POINT_FIT_OPTIONS["iterations"]
        add("App::PropertyIntegerConstraint", "Iterations", "Fit", tip["Iterations"],
            (default["Iterations"], int(f["minimum"]), int(f["maximum"]), 1))
        add("App::PropertyFile", "Weights", "Fit", tip["Weights"], default["Weights"])
        add("App::PropertyString", "Report", "Result", "Fit report (JSON)")
        obj.setEditorMode("Report", 1)

    def execute(self, obj):
        if obj.Source is None:
            raise HoleFillApp.HoleFillError("the point-cloud fit has no source")
        face, rep = fitPoints(_sourcePoints(obj.Source), **{name: getattr(obj, prop) for prop, name in POINT_FIT_PROPERTIES.items()})
        obj.Shape = face
        obj.Report = json.dumps({k: v for k, v in rep.items() if k not in ("uv", "errors", "cells", "boundary")})


def makePointCloudFit(source, method=_PF["method"], tolerance=_PF["tolerance"], relativeTolerance=_PF["relativeTolerance"],
                      degree=_PF["degree"], adaptive=_PF["adaptive"], iterations=_PF["iterations"], name="PointCloudFit",
                      weights=_PF["weights"]):
    """A parametric fit of a Points or Mesh object in one undo step (tolerance in model units,
    0: relativeTolerance of the diagonal; weights: BIDGCN's weights file, "" for the shipped one)."""
    _sourcePoints(source)  # refuse other objects before touching the document

    def setup(obj):
        PointCloudFitFeature(obj)
        obj.Source = source
        obj.Method = str(method)
        obj.Tolerance = float(tolerance)
        obj.RelativeTolerance = float(relativeTolerance)
        obj.Degree = int(degree)
        obj.Adaptive = bool(adaptive)
        obj.Iterations = int(iterations)
        obj.Weights = str(weights)

    from HoleFill.transaction import addParametric
    return addParametric(source.Document, "Fit point cloud", name, setup, "the point-cloud fit")
