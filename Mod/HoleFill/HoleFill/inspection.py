"""Inspection from macros and batch runs: curvature maps, zebra pictures and continuity
along shared edges, on any Part shape (our fills, FreeCAD faces, imported STEP).

    import HoleFill
    report = HoleFill.renderImage(obj.Shape, "/tmp/fill.png", mode="zebra", stripes=20)
    cmap = HoleFill.curvatureMap(obj.Shape, quantity="gauss")   # arrays + colours + scale
    cont = HoleFill.faceContinuity(obj.Shape, 3, 5)            # G0/G1/G2 across Face3|Face5

All numbers come from the exact surfaces (not from a mesh); the shape is never modified.
"""
import json

import HoleFillApp

QUANTITIES = ("mean", "gauss", "max", "min", "direction")
RENDER_MODES = ("zebra", "curvature", "shaded")
# How the workbench's zebra overlay draws its stripes: "shader" per pixel by a GLSL shader (sharp at
# any tessellation); "vertex" per vertex of the inspection mesh, recomputed when the camera moves,
# for OpenGL without shaders (remote X, old drivers), where the shader draws nothing.
ZEBRA_RENDERERS = ("shader", "vertex")
VIEWS = ("iso", "top", "bottom", "front", "back", "left", "right")


def _brep(shape):
    from HoleFill import _brep as brep
    return brep(shape)


def _faceIndices(faces):
    out = []
    for f in faces or ():
        if isinstance(f, str):
            if not f.startswith("Face") or not f[4:].isdigit():
                raise HoleFillApp.HoleFillError("'%s' is not a face name: use names like 'Face3'" % f)
            out.append(int(f[4:]))
        else:
            out.append(int(f))
    return out


def inspectionMesh(shape, faces=None, maxNormalAngle=2.0, maxVertices=0, timeLimit=0.0, progress=None):
    """Adaptive tessellation of `shape` (or of the given faces, "FaceK" names or 1-based indices)
    whose neighbouring vertex normals differ by at most maxNormalAngle degrees, with the exact
    surface fields per vertex: a dict of NumPy arrays points, normals, k1, k2 (principal
    curvatures, k1 >= k2, convex positive), d1 (direction of k1), triangles, triangleFace,
    vertexFace, plus edges [(edgeIndex, polyline)], and the reached normal angles (radians).
    The refinement stops before passing maxVertices (0: 1,000,000) or, by its measured rate,
    timeLimit seconds (0: none); then stoppedByBudget is True and warnings say what was not
    reached. progress(fraction) -> False cancels (HoleFillError)."""
    return HoleFillApp.inspectionMesh(_brep(shape), _faceIndices(faces), float(maxNormalAngle), int(maxVertices),
                                      float(timeLimit), progress)


def curvatureMap(shape, quantity="mean", faces=None, percentiles=(2.0, 98.0), valueRange=None, symmetric=None,
                 direction=(1.0, 0.0, 0.0), maxNormalAngle=2.0, mesh=None):
    """Curvature map of `shape`: inspectionMesh plus values (per vertex), colors (n x 3, 0..1) and
    the scale (low, high, diverging, ticks, labels, ramp). quantity: mean, gauss, max, min or
    direction (normal curvature along `direction`). The colour range is clamped at the given
    percentiles, or set by valueRange=(low, high). symmetric: None = by quantity (Gaussian and
    mean get a symmetric diverging scale), True or False. Pass mesh= to reuse a tessellation."""
    if quantity not in QUANTITIES:
        raise HoleFillApp.HoleFillError("unknown quantity '%s': use one of %s" % (quantity, ", ".join(QUANTITIES)))
    m = dict(mesh) if mesh is not None else inspectionMesh(shape, faces, maxNormalAngle)
    values, signed = HoleFillApp.curvatureValues(m["normals"], m["k1"], m["k2"], m["d1"], quantity,
                                                 [float(x) for x in direction])
    low, high = (None, None) if valueRange is None else (float(valueRange[0]), float(valueRange[1]))
    scale = HoleFillApp.colorScale(values, signed, float(percentiles[0]), float(percentiles[1]), low, high,
                                   -1 if symmetric is None else int(bool(symmetric)))
    m.update(values=values, colors=scale.pop("colors"), scale=scale, quantity=quantity)
    return m


def renderImage(shape, path=None, mode="zebra", quantity="mean", size=(1024, 768), view="iso", faces=None,
                stripes=16, stripeWidth=0.5, stripeAngle=0.0, stripeMode="reflection", isophoteDirection=(0, 0, 1),
                percentiles=(2.0, 98.0), valueRange=None, symmetric=None, maxNormalAngle=2.0, edges=True,
                legend=True):
    """Render a PNG of `shape` without a display (software renderer in the core): mode zebra
    (reflection lines or isophotes), curvature (with a legend) or shaded. view: iso, top, bottom,
    front, back, left, right or a view direction (dx, dy, dz). Writes `path` atomically and
    returns the report dict; with path=None returns (png_bytes, report)."""
    opts = {"mode": mode, "quantity": quantity, "size": "%dx%d" % (int(size[0]), int(size[1])),
            "stripes": int(stripes), "stripe-width": float(stripeWidth), "stripe-angle": float(stripeAngle),
            "stripe-mode": stripeMode, "isophote-direction": ",".join(repr(float(x)) for x in isophoteDirection),
            "normal-angle": float(maxNormalAngle), "edges": int(bool(edges)), "legend": int(bool(legend))}
    opts["view"] = view if isinstance(view, str) else ",".join(repr(float(x)) for x in view)
    if valueRange is not None:
        opts["scale-range"] = "%r,%r" % (float(valueRange[0]), float(valueRange[1]))
    else:
        opts["scale-percentile"] = "%r,%r" % (float(percentiles[0]), float(percentiles[1]))
    if symmetric is not None:
        opts["symmetric"] = "yes" if symmetric else "no"
    if faces:
        opts["faces"] = ",".join(str(i) for i in _faceIndices(faces))
    png, rep = HoleFillApp.renderImage(_brep(shape), opts, path or "")
    report = json.loads(rep)
    return report if path else (png, report)


def _continuity(result):
    rep, samples, edges = result
    report = json.loads(rep)
    report["samples_along"] = samples
    report["sample_edges"] = edges
    return report


def faceContinuity(shape, faceA, faceB, samplesPerEdge=50):
    """G0/G1/G2 (DESIGN.md) of faceB against faceA of `shape` along the edges they share
    ("FaceK" names or 1-based indices). The report adds samples_along (k x 11 array: x y z g0 g1 g2,
    then faceB's unit normal nx ny nz turned to agree with faceA's, and the normal curvatures
    across the edge of faceB and of faceA, signed against that normal; NaN where a normal is
    singular) and sample_edges (the edge index of each sample)."""
    a, b = _faceIndices([faceA, faceB])
    return _continuity(HoleFillApp.faceContinuity(_brep(shape), a, b, int(samplesPerEdge)))


def continuityAlong(face, shape, edges):
    """continuityReport of a filling face against the hole of `shape` holding `edges` (1-based
    indices), with samples_along and sample_edges as in faceContinuity."""
    return _continuity(HoleFillApp.continuityAlong(_brep(face), _brep(shape), [int(e) for e in edges]))
