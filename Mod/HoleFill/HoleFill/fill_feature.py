"""The parametric Fill document object (App side): a Part::FeaturePython whose
Shape is the filling face (or the source with the face sewn in), recomputed from
its Source link whenever the source changes. The source is only read."""
import json
from functools import partial

import FreeCAD

import HoleFill
from HoleFill.transaction import ParametricFeature, ensureProperty

OUTPUTS = ("Face", "Sewn")  # what a Fill object holds: the patch alone, or the source with it sewn in


def edgeContinuityDict(entries):
    """["Edge5=G0", ...] (the EdgeContinuity property) -> {"Edge5": "G0", ...}."""
    out = {}
    for item in entries or []:
        name, sep, value = item.partition("=")
        if not sep:
            raise HoleFill.HoleFillError("EdgeContinuity entry '%s': write Edge5=G0" % item)
        out[name.strip()] = value.strip()
    return out


def edgeMidpoints(shape, indices, placement=None):
    """The midpoints (by parameter) of `shape`'s 1-based edges `indices`, in the frame of
    `placement` (the source object's: where they are whatever the object's Placement)."""
    inv = placement.inverse() if placement is not None else None
    out = []
    for i in indices:
        e = shape.Edges[i - 1]
        p = e.valueAt(0.5 * (e.FirstParameter + e.LastParameter))
        out.append(inv.multVec(p) if inv is not None else p)
    return out


def holeSignature(shape, picked, loop, placement=None):
    """What a Fill keeps of its hole to find it again (HoleSignature): the midpoints of the picked
    edges, in their order, then those of the loop's other edges, in the source's own frame."""
    return edgeMidpoints(shape, list(picked) + [i for i in loop if i not in picked], placement)


def followHole(shape, edges, signature, placement=None):
    """The picked edges of a hole whose source was rebuilt: (edges, message). Edge numbers are not
    stable (a source rebuilt or re-imported may number its edges anew; FreeCAD 0.20 has no element
    map, 1.0 follows a renaming itself only where the shape has a history), so when a picked edge's
    midpoint is no longer one of the signature's (holeSignature), every hole is scored by how far
    the signature's midpoints lie from its edges' (the largest distance), and the picks move to
    the best hole only when it is clearly nearer than the hole they name (under half its score):
    a hole whose surroundings changed shape keeps its names. Each pick becomes the best hole's
    edge nearest the pick's old midpoint, and the message says so. With no signature (a document
    of an older version) or no holes the names stand, and the fill judges them."""
    picked = [int(e[4:]) for e in edges if isinstance(e, str) and e.startswith("Edge") and e[4:].isdigit()]
    if not signature or len(picked) != len(edges) or len(signature) < len(picked):
        return edges, None
    n = len(shape.Edges)
    tol = 1e-7 * max(shape.BoundBox.DiagonalLength, 1e-300)

    def near(p, pts):
        return min((p - q).Length for q in pts)

    valid = all(1 <= i <= n for i in picked)
    if valid and all(near(m, signature) <= tol for m in edgeMidpoints(shape, picked, placement)):
        return edges, None
    scored = []
    for h in HoleFill.findHoles(shape, includeOuter=True):
        mids = edgeMidpoints(shape, h["edge_indices"], placement)
        scored.append((max(near(p, mids) for p in signature), h["edge_indices"], mids))
    if not scored:
        return edges, None
    best, indices, mids = min(scored, key=lambda x: x[0])
    named = [x[0] for x in scored if valid and picked[0] in x[1]]
    if named and not best < 0.5 * named[0]:
        return edges, None
    renamed = []
    for target in signature[:len(picked)]:
        name = "Edge%d" % indices[min(range(len(indices)), key=lambda j: (mids[j] - target).Length)]
        if name not in renamed:
            renamed.append(name)
    if renamed == list(edges):
        return edges, None
    return renamed, "the source's edges were renumbered: the hole was found again by position, %s is now %s" % (
        ", ".join(edges), ", ".join(renamed))


class FillFeature(ParametricFeature):
    viewProvider = "FillViewProvider"
    computedFrom = ("Source", "Method", "Continuity", "Tolerance", "AngularTolerance", "EdgeContinuity", "Output", "Weights", "Points")

    def setupProperties(self, obj):
        add = partial(ensureProperty, obj)

        add("App::PropertyLinkSub", "Source", "Fill", "Object and edges of the hole (one edge names its whole loop)")
        tip = {name: HoleFill.optionTip(f) for name, f in HoleFill.FILL_OPTIONS.items()}
        default = HoleFill.FILL_DEFAULTS
        add("App::PropertyEnumeration", "Method", "Fill", tip["method"])
        if list(obj.getEnumerationsOfProperty("Method")) != list(HoleFill.METHODS):
            # New methods appear in documents saved by older versions; the chosen one is kept.
            current = obj.Method if obj.getEnumerationsOfProperty("Method") else default["method"]
            obj.Method = list(HoleFill.METHODS)
            obj.Method = current if current in HoleFill.METHODS else default["method"]
        add("App::PropertyEnumeration", "Continuity", "Fill", tip["continuity"])
        if not obj.getEnumerationsOfProperty("Continuity"):
            obj.Continuity = list(HoleFill.CONTINUITIES)
            obj.Continuity = default["continuity"]
        add("App::PropertyLength", "Tolerance", "Fill", tip["tolerance"], default["tolerance"])
        add("App::PropertyFloat", "AngularTolerance", "Fill", tip["angularTolerance"], default["angularTolerance"])
        add("App::PropertyVectorList", "HoleSignature", "Fill", "Midpoints of the hole's edges, picked ones first: "
            "where the hole is found again when the source numbers its edges anew")
        obj.setEditorMode("HoleSignature", 2)
        add("App::PropertyStringList", "EdgeContinuity", "Fill", tip["edgeContinuity"])
        add("App::PropertyEnumeration", "Output", "Fill", "Face: the patch alone; Sewn: the source with the patch sewn in")
        if not obj.getEnumerationsOfProperty("Output"):
            obj.Output = list(OUTPUTS)
        add("App::PropertyFile", "Weights", "Fill", tip["weights"])
        add("App::PropertyVectorList", "Points", "Fill", "Points inside the hole the face passes through (global coordinates, "
            "as Surface Filling's vertex constraints); each one's distance to the face is in the Report")
        for name, doc in (("Status", "ok, tolerance_not_met or the failure"), ("Achieved", "continuity reached"),
                          ("Report", "full continuity report (JSON)")):
            add("App::PropertyString", name, "Report", doc)
            obj.setEditorMode(name, 1)
        for name, doc in (("G0", "max position gap (model units)"), ("G1", "max normal angle (rad)"),
                          ("G2", "max relative curvature deviation")):
            add("App::PropertyFloat", name, "Report", doc)
            obj.setEditorMode(name, 1)

    def execute(self, obj):
        src, subs = obj.Source if obj.Source else (None, [])
        if src is None or not hasattr(src, "Shape"):
            raise HoleFill.HoleFillError("Fill has no source object with a shape")
        edges = [s for s in subs if s.startswith("Edge")] or 1
        moved = None
        if edges != 1:
            edges, moved = followHole(src.Shape, edges, list(obj.HoleSignature), getattr(src, "Placement", None))
            if moved:  # renamed without touching the Fill: this recompute is the one that uses it
                obj.setPropertyStatus("Source", "NoRecompute")
                try:
                    obj.Source = (src, edges)
                finally:
                    obj.setPropertyStatus("Source", "-NoRecompute")
        res = self.prepared(src.Shape, edges).fill(method=obj.Method, continuity=obj.Continuity,
                                                   tolerance=float(obj.Tolerance), angularTolerance=obj.AngularTolerance,
                                                   sewn=obj.Output == "Sewn",
                                                   edgeContinuity=edgeContinuityDict(obj.EdgeContinuity),
                                                   weights=obj.Weights, points=list(getattr(obj, "Points", [])))
        obj.Shape = res[1] if obj.Output == "Sewn" else res[0]
        report = res[-1]
        obj.Status = report["status"]
        obj.Achieved = report["achieved"]
        obj.G0, obj.G1, obj.G2 = report["g0"], report["g1"], report["g2"]
        if edges != 1:
            obj.HoleSignature = holeSignature(src.Shape, [int(e[4:]) for e in edges], report["edges"],
                                              getattr(src, "Placement", None))
        if moved:
            report.setdefault("warnings", []).append(moved)
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, moved))
        obj.Report = json.dumps(report)
        self.markComputed(obj)
        if report["status"] != "ok":
            FreeCAD.Console.PrintWarning("%s: %s\n" % (obj.Label, report["message"]))

    def prepared(self, shape, edges):
        """The source's hole, prepared once while the source shape and the picked edges stay the
        same: a Preview that changes the method, continuity, tolerance or output reuses the model
        read, the hole found, its samples and parameterizations (HoleFill.PreparedHole). Not saved."""
        last = getattr(self, "_prepared", None)
        if last is not None and last[2].isFor(shape, edges):
            return last[2]
        hole = HoleFill.prepareHole(shape, edges)
        self.keepPrepared(shape, edges, hole)
        return hole

    def keepPrepared(self, shape, edges, hole):
        """Takes `hole`, prepared elsewhere (the task panel's Previews) for `shape` and `edges`, as
        this object's: its next recompute reuses it instead of reading the model again."""
        self._prepared = (edges if edges == 1 else tuple(edges), shape, hole)


_FILL = HoleFill.FILL_DEFAULTS


def makeFill(source, edges=None, method=_FILL["method"], continuity=_FILL["continuity"], tolerance=_FILL["tolerance"],
             angularTolerance=_FILL["angularTolerance"], output="Face", doc=None, edgeContinuity=None, weights=_FILL["weights"],
             prepared=None, points=None):
    if source is None or not hasattr(source, "Shape"):
        raise HoleFill.HoleFillError("makeFill needs a document object with a shape as source")
    doc = doc or source.Document
    if isinstance(edges, str):
        edges = [edges]
    if not edges:
        holes = HoleFill.findHoles(source.Shape)
        if not holes:
            raise HoleFill.HoleFillError("%s has no holes" % source.Label)
        edges = holes[0]["edges"][:1]

    def setup(obj):
        FillFeature(obj)
        _setFill(obj, source, edges, method, continuity, tolerance, angularTolerance, output, edgeContinuity, weights, prepared, points)

    from HoleFill.transaction import addParametric
    return addParametric(doc, "Fill hole", "Fill", setup, "the fill")


def changeFill(obj, source, edges, method=_FILL["method"], continuity=_FILL["continuity"], tolerance=_FILL["tolerance"],
               angularTolerance=_FILL["angularTolerance"], output="Face", edgeContinuity=None, weights=_FILL["weights"],
               prepared=None, points=None):
    """Sets an existing Fill's hole and options in one undo step and recomputes it; on failure
    the Fill is left as it was and HoleFillError is raised."""
    from HoleFill.transaction import changeParametric
    return changeParametric(obj, "Edit fill", lambda o: _setFill(o, source, edges, method, continuity, tolerance, angularTolerance,
                                                                 output, edgeContinuity, weights, prepared, points), "the fill")


def _setFill(obj, source, edges, method, continuity, tolerance, angularTolerance, output, edgeContinuity, weights, prepared,
             points=None):
    if prepared is not None:
        asked = {int(e[4:]) if isinstance(e, str) else int(e) for e in edges}
        kept = set(prepared.edges)
        if not prepared.shape.isSame(source.Shape) or not (asked <= kept or kept <= asked):
            raise HoleFill.HoleFillError("the prepared hole (edges %s) is not the one %s of %s name" % (
                ", ".join("Edge%d" % e for e in sorted(kept)), ", ".join(str(e) for e in edges), source.Label))
    obj.Source = (source, list(edges))
    obj.Method = method
    obj.Continuity = continuity
    obj.Tolerance = tolerance
    obj.AngularTolerance = angularTolerance
    obj.Output = output
    obj.Weights = weights
    obj.EdgeContinuity = HoleFill.edgeContinuityEntries(edgeContinuity)
    obj.Points = [FreeCAD.Vector(*p[:3]) if not isinstance(p, FreeCAD.Vector) else p for p in (points or [])]
    if prepared is not None:  # a hole read and found for these edges already (the task panel's)
        obj.Proxy.keepPrepared(source.Shape, list(edges), prepared)
