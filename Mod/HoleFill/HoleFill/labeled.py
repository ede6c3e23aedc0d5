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
from functools import partial

import HoleFillApp
from HoleFill import optionDefaults, optionSchema, optionTip
from HoleFill.transaction import ParametricFeature, ensureProperty

__all__ = ["fitLabeled", "boundaryLoop", "cornerSplits", "segmentsOf", "makeBoundaryLabels", "makeLabeledFit"]


def _labelsJson(labels):
    if isinstance(labels, str):
        return labels
    if isinstance(labels, dict):
        return json.dumps(labels)
    return json.dumps({"segments": [{"label": str(l), "vertices": [int(v) for v in vs]} for l, vs in labels]})


FIT_OPTIONS = optionSchema("labeled_fit")
_FIT = optionDefaults(FIT_OPTIONS)
# The LabeledFit object's properties and the options they hold.
FIT_PROPERTIES = {"ControlPointsU": "controlU", "ControlPointsV": "controlV", "MaxControlPoints": "maxControl", "Tolerance": "tolerance",
                  "RelativeTolerance": "relativeTolerance",
                  "Extension": "extension", "Margin": "margin", "Reach": "reach", "Fairness": "fairness", "Isocurves": "isocurves",
                  "MeshFairness": "meshFairness", "Smoothing": "smoothing", "FramePlacement": "framePlacement",
                  "ReleaseDepth": "releaseDepth", "RelaxLabels": "relaxLabels"}


def fitLabeled(mesh, labels, controlPoints=(_FIT["controlU"], _FIT["controlV"]), extension=_FIT["extension"], margin=_FIT["margin"],
               fairness=_FIT["fairness"], smoothing=_FIT["smoothing"], framePlacement=_FIT["framePlacement"],
               meshFairness=_FIT["meshFairness"], maxControl=_FIT["maxControl"], tolerance=_FIT["tolerance"],
               releaseDepth=_FIT["releaseDepth"], relaxLabels=_FIT["relaxLabels"], reach=_FIT["reach"], isocurves=_FIT["isocurves"],
               relativeTolerance=_FIT["relativeTolerance"], isolated=False, progress=None):
    """(trimmed Part.Face, untrimmed Part.Face, report dict). `labels`: [(label, vertices), ...],
    or {"segments": [{"label": "N", "vertices": [...]}, ...]}, or that as JSON text; labels N, E,
    S, W. extension: "fit" (default: the region's extension to its four-sided domain sampled from a
    thin-plate fit of the region), "G2" or "G1" (the paper's continuation of the boundary, which
    fairness and meshFairness shape), or "none" (fit the region alone, for comparison).
    Weights: fairness (isocurve fairness of the continuation, relative to its polyharmonic energy),
    smoothing (thin-plate term of the fit), framePlacement (how firmly labeled vertices keep the
    guiding frame's placement along their sides), meshFairness (the paper's E_Mesh: how evenly the
    extension's triangles are distorted from their neighbours; 0 leaves it out). Control points:
    from controlPoints, refined by half again per direction while the data max exceeds tolerance
    (model units; 0: relativeTolerance of the region's diagonal), up to maxControl per direction (40 where the region's scan noise
    could be what the fit misses; 0: exactly controlPoints); the
    report's "refinements" lists the tries. releaseDepth: labeled vertices deeper than this
    fraction of their side's chord inside its line, past a sharp turn (a notch, slot, bite), are
    left free for the extension (negative: every labeled vertex held). relaxLabels: where the
    labeled map's fit misses the tolerance, has weak control points or is ill-conditioned, the fit
    over the labels relaxed (the region's free flattening, turned as the labels say) is tried and
    kept if it has none of those faults (the report's "labels_relaxed" says so, with a warning);
    False: the labeled map is kept. reach: how far the untrimmed surface reaches past the
    domain's rectangle, as a fraction of its larger side (the extension's margin; 0: to the
    rectangle and `margin` grid layers). isocurves: "grid" or "paper" (the continuation's fairness
    along the boundary and labeled isocurves, G2/G1 only). The defaults are the core's
    (optionSchema("labeled_fit"), as `holefill options labeled_fit` lists them). The report also holds "uv" (per vertex),
    "frame" ([(side letter, points)], the guiding frame's curves) and "extended" ((vertices,
    triangles) of the region extended to its four-sided domain). isolated: the fit runs in a
    process of its own (HoleFill.isolated), so that a crash in it cannot take FreeCAD down; the
    GUI's previews and recomputes ask for it; progress(fraction) -> False then cancels it."""
    from HoleFill.meshfill import _arrays
    from HoleFill import _shape
    v, t = _arrays(mesh)
    options = dict(controlU=int(controlPoints[0]), controlV=int(controlPoints[1]), extension=str(extension), margin=int(margin),
                   fairness=float(fairness), smoothing=float(smoothing), framePlacement=float(framePlacement),
                   meshFairness=float(meshFairness), maxControl=int(maxControl), tolerance=float(tolerance),
                   relativeTolerance=float(relativeTolerance), releaseDepth=float(releaseDepth), relaxLabels=bool(relaxLabels),
                   reach=float(reach), isocurves=str(isocurves))
    if isolated:
        from HoleFill import isolated as child
        face, untrimmed, report, uv, frame, ev, et = child.call("fitLabeled", v, t, _labelsJson(labels), options,
                                                                 progress=progress, what="the labeled fit")
    else:
        face, untrimmed, report, uv, frame, ev, et = HoleFillApp.fitLabeled(v, t, _labelsJson(labels), options)
    rep = json.loads(report)
    if rep.get("log10_condition") is None:
        rep["log10_condition"] = float("inf")  # JSON has no infinity: a singular normal matrix
    rep["uv"] = uv
    rep["frame"] = frame
    rep["extended"] = (ev, et)
    return _shape(face), _shape(untrimmed), rep


# -- boundary segments and labels -------------------------------------------------------------

LABELS = ("N", "E", "S", "W")
LABEL_COLORS = {"N": (0.85, 0.10, 0.10), "E": (0.10, 0.55, 0.10), "S": (0.10, 0.25, 0.90), "W": (0.80, 0.55, 0.00),
                "-": (0.85, 0.15, 0.85)}  # unlabeled: magenta, which shows on a grey, green or white mesh alike


def boundaryLoop(mesh):
    """The outer boundary loop of a mesh region (the longest), as 0-based point indices, and
    its points: (loop, points). Raises HoleFillError for a closed or empty mesh."""
    from HoleFill.meshfill import meshHoles
    holes = meshHoles(mesh)
    if not holes:
        raise HoleFillApp.HoleFillError("the mesh has no open boundary: label the boundary of a trimmed region, not a closed mesh")
    return list(holes[0]["loop"]), [tuple(p) for p in holes[0]["points"]]


def cornerSplits(points, angle=35.0):
    """Loop positions where the boundary turns by more than `angle` degrees (measured between
    the directions to the neighbours two steps away, so a jagged scan edge is not a corner),
    keeping the sharpest of neighbouring candidates."""
    import math
    n = len(points)
    if n < 6:
        return list(range(n))

    def sub(a, b):
        return (a[0] - b[0], a[1] - b[1], a[2] - b[2])

    def turn(k):
        a, b = sub(points[k], points[(k - 2) % n]), sub(points[(k + 2) % n], points[k])
        la, lb = math.sqrt(sum(x * x for x in a)), math.sqrt(sum(x * x for x in b))
        if la == 0 or lb == 0:
            return 0.0
        c = sum(x * y for x, y in zip(a, b)) / (la * lb)
        return math.degrees(math.acos(max(-1.0, min(1.0, c))))

    t = [turn(k) for k in range(n)]
    return [k for k in range(n) if t[k] > angle and t[k] >= t[(k - 1) % n] and t[k] > t[(k + 1) % n]]


def fourCorners(points, normal):
    """Four corners and their sides for a boundary loop that corner angles cut badly (a jagged scan
    edge gives 13-20 segments at the default angle, and on some regions no angle gives 4): the
    boundary vertices nearest the corners of its least-area bounding rectangle on its best-fit
    plane, as the corpus labels its regions. `normal`: the region's side (its mean face normal),
    so that S, E, N, W run anticlockwise seen from it. Returns {loop position: label} for the four
    splits, each labeling the side that starts there in loop order."""
    import math
    import numpy as np
    p = np.asarray(points, dtype=float)
    if len(p) < 4:
        raise HoleFillApp.HoleFillError("a boundary of fewer than 4 vertices has no four corners")
    c = p.mean(axis=0)
    _, _, axes = np.linalg.svd(p - c, full_matrices=False)
    u, v = axes[0], axes[1]
    if u[np.argmax(np.abs(u))] < 0:
        u = -u  # the SVD's sign is arbitrary: the same labels on every machine
    if np.dot(np.cross(u, v), np.asarray(normal, dtype=float)) < 0:
        v = -v  # u, v, normal right-handed: anticlockwise in (u, v) is anticlockwise seen from the normal
    q = np.stack([(p - c) @ u, (p - c) @ v], axis=1)
    # The core's least-area rectangle (geometry/polygon2d.h); of its four quarter turns, the one
    # turned least from the plane's principal axes, so that S lies along the first axis, at its low side.
    a = HoleFillApp.leastAreaRectangleAngle(q)
    if a > math.pi / 4:
        a -= math.pi / 2
    rot = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    r = q @ rot.T
    lo, hi = r.min(axis=0), r.max(axis=0)
    corners = {"SW": (lo[0], lo[1]), "SE": (hi[0], lo[1]), "NE": (hi[0], hi[1]), "NW": (lo[0], hi[1])}
    chosen = {}
    for name, xy in corners.items():
        d = np.linalg.norm(r - np.asarray(xy), axis=1)
        for k in np.argsort(d):
            if int(k) not in chosen.values():
                chosen[name] = int(k)
                break
    sides = {("SW", "SE"): "S", ("SE", "NE"): "E", ("NE", "NW"): "N", ("NW", "SW"): "W"}
    byPosition = sorted((k, name) for name, k in chosen.items())
    out = {}
    for i, (k, name) in enumerate(byPosition):
        nxt = byPosition[(i + 1) % 4][1]
        out[k] = sides.get((name, nxt)) or sides.get((nxt, name))
    if None in out.values():
        raise HoleFillApp.HoleFillError("the corners of the boundary's bounding rectangle do not follow each other around it "
                                        "(a crescent, a deep slot): place the corners by clicking boundary vertices")
    return out


def segmentsOf(loopLength, splits):
    """Segments as lists of loop positions, from sorted split positions (each segment starts at a
    split and ends at the next, sharing it); one segment over the whole loop without splits."""
    s = sorted(set(int(x) % loopLength for x in splits))
    if not s:
        return [list(range(loopLength)) + [0]]
    out = []
    for i, a in enumerate(s):
        b = s[(i + 1) % len(s)]
        seg, k = [a], a
        while True:
            k = (k + 1) % loopLength
            seg.append(k)
            if k == b:
                break
        out.append(seg)
    return out


def labelsJsonOf(loop, splits, labels):
    """{"segments": [...]} of the labeled segments (unlabeled ones left out) for fitLabeled."""
    segs = []
    for seg, label in zip(segmentsOf(len(loop), splits), labels):
        if label in LABELS:
            vs = [loop[k] for k in seg]
            if vs[0] == vs[-1]:
                vs = vs[:-1]
            segs.append({"label": label, "vertices": vs})
    return json.dumps({"segments": segs})


class BoundaryLabelsFeature(ParametricFeature):
    """A mesh region's boundary cut into segments labeled N/E/S/W (or unlabeled), shown as
    coloured polylines; what LabeledFit objects fit by. Changing Splits or Labels recomputes the
    fits that use it."""
    viewProvider = "LabelsViewProvider"

    def setupProperties(self, obj):
        add = partial(ensureProperty, obj)

        add("App::PropertyLink", "Source", "Labels", "The mesh region (Mesh feature) whose boundary is labeled")
        add("App::PropertyIntegerList", "Loop", "Labels", "The outer boundary loop (0-based mesh points, in order)")
        add("App::PropertyIntegerList", "Splits", "Labels", "Loop positions where segments start")
        add("App::PropertyStringList", "Labels", "Labels", "Per segment, from the first split on: N, E, S, W or -")
        add("App::PropertyString", "LabelsJson", "Labels", "The labeled segments as fitLabeled takes them")
        obj.setEditorMode("LabelsJson", 1)
        obj.setEditorMode("Loop", 1)

    def execute(self, obj):
        import FreeCAD
        import Part
        if obj.Source is None or not hasattr(obj.Source, "Mesh"):
            raise HoleFillApp.HoleFillError("the boundary labels have no source mesh")
        loop, points = boundaryLoop(obj.Source.Mesh)
        if list(obj.Loop) != loop:
            raise HoleFillApp.HoleFillError("the mesh's boundary changed since it was labeled: label it again")
        segs = segmentsOf(len(loop), obj.Splits)
        if len(obj.Labels) != len(segs):
            raise HoleFillApp.HoleFillError("%d labels for %d segments" % (len(obj.Labels), len(segs)))
        for l in obj.Labels:
            if l not in LABELS and l != "-":
                raise HoleFillApp.HoleFillError("label '%s' is not N, E, S, W or -" % l)
        wires = []
        for seg in segs:
            wires.append(Part.makePolygon([FreeCAD.Vector(*points[k]) for k in seg]))
        obj.Shape = Part.makeCompound(wires)
        obj.LabelsJson = labelsJsonOf(loop, obj.Splits, list(obj.Labels))



def makeBoundaryLabels(meshObj, splits=None, labels=None, cornerAngle=35.0, name="BoundaryLabels"):
    """Boundary labels of a Mesh feature in one undo step: segments split at `splits` (loop
    positions; default: corners turning more than cornerAngle), `labels` one per segment (default
    all '-'). The mesh is only read."""
    if meshObj is None or not hasattr(meshObj, "Mesh"):
        raise HoleFillApp.HoleFillError("makeBoundaryLabels needs a Mesh feature")
    loop, points = boundaryLoop(meshObj.Mesh)
    if splits is None:
        splits = cornerSplits(points, cornerAngle)
    count = len(segmentsOf(len(loop), splits))
    labels = list(labels) if labels is not None else ["-"] * count

    def setup(obj):
        BoundaryLabelsFeature(obj)
        obj.Source = meshObj
        obj.Loop = loop
        obj.Splits = sorted(set(int(s) for s in splits))
        obj.Labels = labels

    from HoleFill.transaction import addParametric
    return addParametric(meshObj.Document, "Label boundary", name, setup, "the boundary labels")


class LabeledFitFeature(ParametricFeature):
    """A trimmed B-spline face fitted to the labels' mesh region (fitLabeled); recomputes when the
    labels, the mesh or the options change. The untrimmed surface is kept in Untrimmed."""

    def setupProperties(self, obj):
        add = partial(ensureProperty, obj)

        add("App::PropertyLink", "Labels", "Fit", "The boundary labels (and through them the mesh region)")
        tip = {prop: optionTip(FIT_OPTIONS[name]) for prop, name in FIT_PROPERTIES.items()}
        default = {prop: FIT_OPTIONS[name]["default"] for prop, name in FIT_PROPERTIES.items()}
        for prop in ("ControlPointsU", "ControlPointsV", "MaxControlPoints", "Margin"):
            f = FIT_OPTIONS[FIT_PROPERTIES[prop]]
            add("App::PropertyIntegerConstraint", prop, "Fit", tip[prop], (default[prop], int(f["minimum"]), int(f["maximum"]), 1))
        for prop in ("Extension", "Isocurves"):
            choices = FIT_OPTIONS[FIT_PROPERTIES[prop]]["choices"]
            if prop not in obj.PropertiesList:
                obj.addProperty("App::PropertyEnumeration", prop, "Fit", tip[prop])
                setattr(obj, prop, choices)
                setattr(obj, prop, default[prop])
            elif list(obj.getEnumerationsOfProperty(prop)) != choices:
                # A document saved before a choice existed keeps its own, with the new ones offered.
                kept = getattr(obj, prop)
                setattr(obj, prop, choices)
                setattr(obj, prop, kept if kept in choices else default[prop])
        if "Tolerance" in obj.PropertiesList and "RelativeTolerance" not in obj.PropertiesList:
            # A document saved when Tolerance was relative to the diagonal: that value is the
            # relative tolerance now, and Tolerance (model units) starts unset.
            relative = float(obj.Tolerance)
            obj.removeProperty("Tolerance")
            add("App::PropertyFloat", "RelativeTolerance", "Fit", tip["RelativeTolerance"], relative)
        add("App::PropertyLength", "Tolerance", "Fit", tip["Tolerance"], default["Tolerance"])
        for prop in ("RelativeTolerance", "Reach", "ReleaseDepth"):
            add("App::PropertyFloat", prop, "Fit", tip[prop], default[prop])
        for prop in ("Fairness", "MeshFairness", "Smoothing", "FramePlacement"):
            add("App::PropertyFloat", prop, "Weights", tip[prop], default[prop])
        add("App::PropertyBool", "RelaxLabels", "Fit", tip["RelaxLabels"], default["RelaxLabels"])
        add("Part::PropertyPartShape", "Untrimmed", "Result", "The untrimmed fitted surface")
        add("App::PropertyString", "Report", "Result", "Fit report (JSON)")
        for n in ("Untrimmed", "Report"):
            obj.setEditorMode(n, 1)

    def execute(self, obj):
        lab = obj.Labels
        if lab is None or not hasattr(lab, "LabelsJson") or lab.Source is None:
            raise HoleFillApp.HoleFillError("the labeled fit has no boundary labels")
        # The options by name, as FIT_PROPERTIES maps them (fitLabeled takes the two counts as one pair).
        options = {name: getattr(obj, prop) for prop, name in FIT_PROPERTIES.items() if name not in ("controlU", "controlV")}
        import FreeCAD
        # In the GUI the fit runs in a process of its own: a crash in it must not take the user's
        # unsaved work down (HoleFill.isolated).
        face, untrimmed, rep = fitLabeled(lab.Source.Mesh, lab.LabelsJson, isolated=FreeCAD.GuiUp,
                                          controlPoints=(obj.ControlPointsU, obj.ControlPointsV),
                                          **options)
        obj.Shape = face
        obj.Untrimmed = untrimmed
        for k in ("uv", "frame", "extended"):
            rep.pop(k, None)
        obj.Report = json.dumps(rep)



def makeLabeledFit(labelsObj, controlPoints=(_FIT["controlU"], _FIT["controlV"]), extension=_FIT["extension"], margin=_FIT["margin"],
                   fairness=_FIT["fairness"], smoothing=_FIT["smoothing"], framePlacement=_FIT["framePlacement"],
                   meshFairness=_FIT["meshFairness"], maxControl=_FIT["maxControl"], tolerance=_FIT["tolerance"],
                   releaseDepth=_FIT["releaseDepth"], relaxLabels=_FIT["relaxLabels"], reach=_FIT["reach"], name="LabeledFit",
                   isocurves=_FIT["isocurves"], relativeTolerance=_FIT["relativeTolerance"]):
    """A parametric labeled fit of a BoundaryLabels object's region in one undo step."""
    if labelsObj is None or not hasattr(labelsObj, "LabelsJson"):
        raise HoleFillApp.HoleFillError("makeLabeledFit needs a BoundaryLabels object (HoleFill → Label boundary)")

    def setup(obj):
        LabeledFitFeature(obj)
        obj.Labels = labelsObj
        obj.ControlPointsU, obj.ControlPointsV = int(controlPoints[0]), int(controlPoints[1])
        obj.Extension = str(extension)
        obj.Margin = int(margin)
        obj.Fairness, obj.Smoothing, obj.FramePlacement = float(fairness), float(smoothing), float(framePlacement)
        obj.MeshFairness = float(meshFairness)
        obj.MaxControlPoints, obj.Tolerance, obj.ReleaseDepth = int(maxControl), float(tolerance), float(releaseDepth)
        obj.RelativeTolerance = float(relativeTolerance)
        obj.RelaxLabels = bool(relaxLabels)
        obj.Reach = float(reach)
        obj.Isocurves = str(isocurves)

    from HoleFill.transaction import addParametric
    return addParametric(labelsObj.Document, "Fit labeled surface", name, setup, "the labeled fit")
