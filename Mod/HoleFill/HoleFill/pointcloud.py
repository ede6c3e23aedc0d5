"""Point-cloud parameterization (bidgcn paper, sec. 3.2): (u, v) for every point of a scanned
cloud whose boundary points have known parameters, by convex combinations of neighbours within a
radius: shape-preserving (Floater; the default), inverse-distance or uniform weights.

    import HoleFill
    uv, report = HoleFill.parameterize(points, {0: (0, 0), 1: (0.1, 0), ...}, method="shape")
    print(report["radius"], report["min_neighbours"], report["max_neighbours"])

`points`: FreeCAD vectors, (x, y, z) tuples, a Points.Points or Mesh.Mesh (its vertices), or an
N×3 array; `boundary`: {point index: (u, v)} for the boundary points (at least 3). The radius is
in the cloud scaled into the unit cube (0: 3/sqrt(N)). Errors raise HoleFillError.
"""
import json

import HoleFillApp

__all__ = ["parameterize"]


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


def parameterize(points, boundary, method="shape", radius=0.0):
    """(uv, report): an N×2 array of parameters (boundary points keep theirs) and a dict."""
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
    uv, report = HoleFillApp.parameterizeCloud(p, flags, buv, str(method), float(radius))
    return uv, json.loads(report)
