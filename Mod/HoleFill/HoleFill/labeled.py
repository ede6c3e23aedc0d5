"""Labeled fitting of trimmed mesh regions (mesh-extension paper): label boundary segments North,
East, South, West; a guiding frame, a labeled ARAP parameterization, the region's extension to
its four-sided domain and a cubic tensor-product fit give one trimmed B-spline face.

    import HoleFill
    face, surface, report = HoleFill.fitLabeled(meshObj.Mesh, [("S", [0, 1, 2, ...]), ("N", [...])],
                                                controlPoints=(12, 12), extension="G2")
    print(report["data_max"], report["weak_control_points"], report["log10_condition"])

Vertex indices are 0-based, each segment's vertices consecutive along the region's boundary.
The mesh is never modified. Errors raise HoleFillError.
"""
import json

import HoleFillApp

__all__ = ["fitLabeled"]


def _labelsJson(labels):
    if isinstance(labels, str):
        return labels
    if isinstance(labels, dict):
        return json.dumps(labels)
    return json.dumps({"segments": [{"label": str(l), "vertices": [int(v) for v in vs]} for l, vs in labels]})


def fitLabeled(mesh, labels, controlPoints=(12, 12), extension="G2", margin=0):
    """(trimmed Part.Face, untrimmed Part.Face, report dict). `labels`: [(label, vertices), ...],
    or {"segments": [{"label": "N", "vertices": [...]}, ...]}, or that as JSON text; labels N, E,
    S, W. extension: "G2" (default), "G1" or "none" (fit the region alone, for comparison)."""
    from HoleFill.meshfill import _arrays
    from HoleFill import _shape
    v, t = _arrays(mesh)
    face, untrimmed, report, uv = HoleFillApp.fitLabeled(v, t, _labelsJson(labels), int(controlPoints[0]), int(controlPoints[1]),
                                                        str(extension), int(margin))
    rep = json.loads(report)
    rep["uv"] = uv
    return _shape(face), _shape(untrimmed), rep
