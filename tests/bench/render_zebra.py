"""Zebra pictures of benchmark holes where the parameterizers differ (run by scripts/bench.sh in
freecadcmd after bench_fill.py): for each chosen hole, the fills by NP, MVC and UVTran (G1
requested) with their neighbouring faces, striped by reflection lines computed from the exact
surface normals (not the mesh's), side by side in one PNG per hole in $BENCH_OUT/zebra/.
A stripe that kinks or breaks where the fill meets its neighbours is a G1 (kink: G2) defect."""
import json
import math
import os

import FreeCAD
import Part

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import HoleFill

OUT = os.environ.get("BENCH_OUT", "/tmp")
METHODS = ("np", "mvc", "uvtran")
STRICT = lambda r: r.get("ok") and r["g0r"] <= 1e-6 and r["g1"] <= 1e-3


def choose(results, count=3):
    """Holes where the methods' strict G1 outcomes differ, most different first."""
    scored = []
    for r in results:
        met = [STRICT(r[m]) for m in METHODS]
        if len(set(met)) > 1:
            scored.append((sum(met), r["name"]))
    return [n for _, n in sorted(scored)[:count]]


def stripes(face, view, tol, centre, radius):
    pts, tris = face.tessellate(tol)
    # Only what lies near the hole is drawn (neighbours can be whole sides of a model).
    tris = [t for t in tris if min((pts[i] - centre).Length for i in t) < radius]
    used = sorted({i for t in tris for i in t})
    vals = {}
    for i in used:
        p = pts[i]
        u, v = face.Surface.parameter(p)
        n = face.normalAt(u, v)
        r = view - n * (2 * view.dot(n))  # the view ray reflected
        vals[i] = r.x * 0.6 + r.y * 0.8
    polys, cols = [], []
    for t in tris:
        polys.append([(pts[i].x, pts[i].y, pts[i].z) for i in t])
        s = sum(vals[i] for i in t) / 3.0
        cols.append((0.05, 0.05, 0.05) if int(math.floor(s * 10)) % 2 else (0.97, 0.97, 0.97))
    return polys, cols


def render(name, shape):
    hole = HoleFill.findHoles(shape)[0]
    fills = {}
    for m in METHODS:
        try:
            fills[m] = HoleFill.fillHole(shape, hole, method=m, continuity="G1")
        except HoleFill.HoleFillError as e:
            fills[m] = (None, {"method": m, "message": str(e)})
    supports = [shape.Faces[i - 1] for i in sorted(set(hole["supportFaces"]))]
    ref = next((f for f, _ in fills.values() if f is not None), None)
    if ref is None:
        return None
    c = ref.CenterOfMass
    u0, u1, v0, v1 = ref.ParameterRange
    nrm = ref.normalAt(0.5 * (u0 + u1), 0.5 * (v0 + v1))
    view = FreeCAD.Vector(nrm).normalize()
    tol = hole["scale"] * 1e-3
    fig = plt.figure(figsize=(5 * len(METHODS), 5))
    for k, m in enumerate(METHODS):
        ax = fig.add_subplot(1, len(METHODS), k + 1, projection="3d")
        face, rep = fills[m]
        faces = supports + ([face] if face is not None else [])
        for f in faces:
            # The fill finely (its stripes are the point), the neighbours coarser (they are only context).
            polys, cols = stripes(f, view, tol if f is face else 3 * tol, c, 0.7 * hole["scale"])
            ax.add_collection3d(Poly3DCollection(polys, facecolors=cols, edgecolors="none"))
        r = hole["scale"] * 0.6
        ax.set_xlim(c.x - r, c.x + r); ax.set_ylim(c.y - r, c.y + r); ax.set_zlim(c.z - r, c.z + r)
        el = math.degrees(math.asin(max(-1, min(1, view.z))))
        az = math.degrees(math.atan2(view.y, view.x))
        ax.view_init(elev=el, azim=az)
        ax.set_axis_off()
        title = "%s: %s" % (m, rep.get("method", m))
        if face is not None:
            title += "\nG0 %.1e·scale  G1 %.1e rad" % (rep["g0_relative"], rep["g1"])
        else:
            title += "\nfailed"
        ax.set_title(title, fontsize=10)
    fig.suptitle(name)
    fig.tight_layout()
    path = os.path.join(OUT, "zebra", name + ".png")
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def main():
    data = json.load(open(os.path.join(OUT, "bench_fill.json")))
    os.makedirs(os.path.join(OUT, "zebra"), exist_ok=True)
    for name in choose(data["results"]):
        shape = Part.Shape()
        shape.read(os.path.join(OUT, "holes", name + ".brep"))
        print("zebra:", render(name, shape))


main()
os._exit(0)
