"""The B-rep hole corpus (issue 20): real holes cut from real models that ship in Debian's packages.

Every eligible face of every part of every source model is removed in turn; the part without it
is one corpus hole, the removed face is its truth. Eligible: one wire of 3..10 edges, a surface
that is not a plane (fillets, vertex blends, cylinders, cones, spheres, tori, surfaces of
revolution/extrusion, B-spline and Bezier patches), and a part whose remaining faces leave exactly
this one hole. For each hole the truth's continuity with its neighbour is measured per edge with
the same report every fill is measured by (HoleFill.continuityReport, DESIGN.md metrics), so each
edge is known to be a crease (truth G1 > 1e-2 rad), tangent, or curvature continuous
(truth G2 <= 0.1): the continuity a fill can be asked for there.

Sources (nothing designed here): OCCT's sample models (occt-misc: /usr/share/opencascade/data)
and the STEP/IGES component models that ship with FreeCAD (freecad-common: Mod/Idf/Idflibs).
Debian's kicad-packages3d STEP models are kept out: they are the independent check.

Run inside freecadcmd with the HoleFill addon (scripts/make_corpus.sh does both):
  CORPUS_OUT=DIR freecadcmd tests/corpus/brep_holes.py
writes DIR/<id>/hole.brep (the part without the face) and DIR/<id>/truth.brep (the face), and
DIR/index.json; tests/corpus/brep_holes_index.json is the committed copy of the index (the
files themselves are regenerated, not committed). CORPUS_MAX_PER_PART bounds the holes taken
from one part (default 40, spread evenly over its eligible faces) so a 600-face model does
not drown the others.
"""
import glob
import json
import os
import sys
import time

import Part

import HoleFill

OUT = os.environ.get("CORPUS_OUT", "/tmp/holefill-corpus")
MAX_PER_PART = int(os.environ.get("CORPUS_MAX_PER_PART", "40"))
MAX_PART_FACES = int(os.environ.get("CORPUS_MAX_PART_FACES", "3000"))
OCC = "/usr/share/opencascade/data"
IDF = "/usr/share/freecad/Mod/Idf/Idflibs"
PLANAR = ("Plane",)
CREASE = 1e-2   # truth G1 above this (rad): the original model is sharp there
G2_OK = 0.1     # truth G2 at or below this: the original is curvature continuous there


def sources():
    paths = sorted(glob.glob(OCC + "/occ/*.brep")) + sorted(glob.glob(OCC + "/step/*.step")) + \
        sorted(glob.glob(OCC + "/iges/*.iges")) + sorted(glob.glob(IDF + "/*.stp")) + sorted(glob.glob(IDF + "/*.igs"))
    return [p for p in paths if "kicad" not in p]


def surface_kind(face):
    s = face.Surface
    name = s.__class__.__name__
    if name == "Cylinder":
        return "cylinder"
    if name in ("BSplineSurface", "BezierSurface"):
        return "bspline"
    if name == "Toroid":
        return "torus"
    if name in ("SurfaceOfRevolution", "SurfaceOfExtrusion", "OffsetSurface"):
        return "swept"
    return name.lower()


def eligible(face):
    if len(face.Wires) != 1:
        return False
    n = len(face.OuterWire.Edges)
    if not 3 <= n <= 10:
        return False
    try:
        return face.Surface.__class__.__name__ not in PLANAR and face.Area > 0
    except Exception:
        return False


def read(path):
    shape = Part.Shape()
    shape.read(path)
    return shape


def parts_of(shape):
    parts = list(shape.Solids) or list(shape.Shells)
    if not parts and shape.Faces:
        try:
            parts = Part.Shell(shape.Faces).Shells or []
        except Exception:
            parts = []
    return parts


def truth_edges(truth, holed, hole):
    """Per loop edge: the truth face's measured continuity with the neighbour and its class."""
    rep = HoleFill.continuityReport(truth, holed, hole)
    edges = []
    for e in rep["per_edge"]:
        cls = "crease" if e["g1"] > CREASE else ("g2" if e["g2"] <= G2_OK else "g1")
        edges.append({"edge": e["edge"], "g0": e["g0"], "g1": e["g1"], "g2": e["g2"], "class": cls})
    return rep, edges


def main():
    os.makedirs(OUT, exist_ok=True)
    index = {"generator": "tests/corpus/brep_holes.py", "max_per_part": MAX_PER_PART, "holes": [], "skipped": {}}
    skipped = index["skipped"]

    def skip(why):
        skipped[why] = skipped.get(why, 0) + 1

    t0 = time.time()
    stems = set()
    for path in sources():
        rel = os.path.relpath(path, "/usr/share")
        try:
            model = read(path)
        except Exception:
            skip("model unreadable")
            continue
        stem, ext = os.path.splitext(os.path.basename(path))
        # One model may ship in two formats (occ/hammer.brep and iges/hammer.iges): the second
        # gets its format in its ids, so that its holes neither share ids nor overwrite folders.
        if stem in stems:
            stem = "%s_%s" % (stem, ext.lstrip(".").lower())
        stems.add(stem)
        for pi, part in enumerate(parts_of(model)):
            faces = part.Faces
            if len(faces) > MAX_PART_FACES:
                skip("part too large")
                continue
            cands = [i for i, f in enumerate(faces) if eligible(f)]
            step = max(1, -(-len(cands) // MAX_PER_PART))
            for i in cands[::step]:
                truth = faces[i]
                try:
                    holed = Part.Shell([f for j, f in enumerate(faces) if j != i])
                    holes = HoleFill.findHoles(holed)
                except Exception:
                    skip("part without the face is no shell")
                    continue
                # The part must have been closed: the removed face's loop is then its only hole.
                if len(holes) != 1:
                    skip("part was open or loop not found")
                    continue
                hole = holes[0]
                if len(hole["edges"]) != len(truth.OuterWire.Edges):
                    skip("hole loop differs from the face's wire")
                    continue
                try:
                    rep, edges = truth_edges(truth, holed, hole)
                except Exception:
                    skip("truth continuity not measurable")
                    continue
                hid = "%s_p%d_f%d" % (stem, pi, i + 1)
                d = os.path.join(OUT, hid)
                os.makedirs(d, exist_ok=True)
                holed.exportBrep(os.path.join(d, "hole.brep"))
                truth.exportBrep(os.path.join(d, "truth.brep"))
                classes = [e["class"] for e in edges]
                index["holes"].append({
                    "id": hid, "source": rel, "part": pi, "face": i + 1, "kind": surface_kind(truth),
                    "N": hole["corners"], "edges": len(hole["edges"]), "scale": hole["scale"],
                    "part_faces": len(faces), "part_valid": bool(part.isValid()),
                    "truth_g0_relative": rep["g0_relative"], "truth_g1": rep["g1"], "truth_g2": rep["g2"],
                    "surround": "crease" if "crease" in classes else ("g2" if all(c == "g2" for c in classes) else "g1"),
                    "per_edge": edges})
        print("%-40s %4d holes so far, %.0f s" % (rel, len(index["holes"]), time.time() - t0))
        sys.stdout.flush()
    with open(os.path.join(OUT, "index.json"), "w") as f:
        json.dump(index, f, indent=1)
    print("%d holes in %s (%.0f s); skipped: %s" % (len(index["holes"]), OUT, time.time() - t0, skipped))


main()
os._exit(0)
