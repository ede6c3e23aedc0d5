#!/usr/bin/env python3
"""Corpus of labeled trimmed regions for labeled fitting (issue 21): regions nobody here shaped to
the method, cut from known surfaces, meshed irregularly, with noise, in both orientations.

Each region is a shape in the unit parameter square (a convex blob, an L, a U-slot, a notch, a
crescent, a square with a corner bitten off by a concave arc, a 10:1 strip, a square with an inner
hole) mapped onto a surface (plane, cylinder, cone, sphere, torus, saddle, Gaussian bumps, a random
B-spline height field, a steep field of random cosines) and triangulated irregularly (Delaunay of jittered interior points and
boundary points at the same spacing), with 2,000 to 20,000 vertices. Noise is Gaussian, 0, 0.05%
or 0.2% of the region's diagonal; half the regions have their triangles turned clockwise seen from
the surface normal. Labels follow one rule (issue 21): the four corners are the outer boundary
vertices nearest the corners of the region's bounding box in the true parameters; S runs from SW
to SE, E from SE to NE, N from NE to NW, W from NW to SW along the anticlockwise loop. Regions with
four convex corners or more (turning by 30 degrees or more) come a second time, labeled by their
corner angles (the four sharpest), as a user labeling a part's sides would: id suffix _corners.

Plus regions of a real scan: the Stanford bunny as CGAL's demo data ships it (libcgal-demo's
data.tar.gz, bunny00.off), cut as balls around seed vertices where the scan is a height field over
its best-fit plane, as a blob and as an L, parameters from that plane (the scan's own density:
700-5,000 vertices); the truth is the scan itself, the band its vertices around the region.

Per region, in OUT/<id>/: region.obj, labels.json, band.xyz (points of the true surface in the band
around the region: the rest of its bounding rectangle grown by 10%, for the band deviation) and
truth.xyz (noise-free positions of the region's vertices). The index (id, surface, shape, noise,
orientation, vertex count, diagonal) goes to tests/corpus/labeled_regions_index.json.

  python3 tests/corpus/labeled_regions.py OUT [--index tests/corpus/labeled_regions_index.json]
Deterministic: one seed per region, from its position in the list.
"""
import json
import math
import os
import sys

import numpy as np
from scipy.interpolate import RectBivariateSpline
from scipy.spatial import Delaunay

# --- surfaces: (u, v) in [0, 1]^2 -> R^3, about 10 units across -------------------------------


def bspline_field(seed):
    rng = np.random.default_rng(1000 + seed)
    knots = np.linspace(0, 1, 7)
    heights = rng.normal(0, 1.2, (7, 7))
    spline = RectBivariateSpline(knots, knots, heights, kx=3, ky=3)
    return lambda u, v: np.stack([10 * u, 10 * v, spline.ev(u, v)], -1)


def waves_field(seed):
    """A steep wavy height field: cosines of random amplitudes, about one period across, slopes
    near 1 (twice the B-spline fields'): straight parameter lines turn along the surface here."""
    rng = np.random.default_rng(2000 + seed)
    a = rng.normal(0, 1, (4, 4))

    def f(u, v):
        z = np.zeros_like(np.asarray(u, float))
        for i in range(4):
            for j in range(4):
                z = z + 1.2 * a[i, j] * np.cos(2.2 * i * u + 0.3 * i) * np.cos(2.2 * j * v + 0.5 * j)
        return np.stack([10 * u, 10 * v, z], -1)
    return f


SURFACES = {
    "plane": lambda u, v: np.stack([10 * u, 10 * v * 0.8, 0.3 * (10 * u) + 0.1 * (10 * v)], -1),
    "cylinder": lambda u, v: np.stack([3 * np.cos(np.pi * u), 3 * np.sin(np.pi * u), 10 * v], -1),
    "cone": lambda u, v: np.stack([(1 + 3 * v) * np.cos(1.2 * np.pi * u), (1 + 3 * v) * np.sin(1.2 * np.pi * u), 8 * v], -1),
    "sphere": lambda u, v: np.stack([5 * np.cos(1.2 * (v - .5)) * np.cos(1.6 * (u - .5)),
                                     5 * np.cos(1.2 * (v - .5)) * np.sin(1.6 * (u - .5)), 5 * np.sin(1.2 * (v - .5))], -1),
    "torus": lambda u, v: np.stack([(6 + 2 * np.cos(2.5 * (v - .5))) * np.cos(1.5 * (u - .5)),
                                    (6 + 2 * np.cos(2.5 * (v - .5))) * np.sin(1.5 * (u - .5)), 2 * np.sin(2.5 * (v - .5))], -1),
    "saddle": lambda u, v: np.stack([10 * u, 10 * v, 8 * ((u - .5) ** 2 - (v - .5) ** 2)], -1),
    "bumps": lambda u, v: np.stack([10 * u, 10 * v, 1.5 * np.exp(-((u - .3) ** 2 + (v - .4) ** 2) / .02)
                                    - 1.0 * np.exp(-((u - .7) ** 2 + (v - .6) ** 2) / .03)
                                    + 0.8 * np.exp(-((u - .5) ** 2 + (v - .85) ** 2) / .01)], -1),
    "bspline": None,  # per region, seeded
    "waves": None,  # per region, seeded
}

# --- shapes: outer loop (anticlockwise) and inner loops (clockwise), in [0, 1]^2 ---------------


def circle(cx, cy, r, n=256, start=0.0, stop=2 * np.pi):
    t = np.linspace(start, stop, n, endpoint=False)
    return np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], -1)


def arc(cx, cy, r, a0, a1, n):
    t = np.linspace(a0, a1, n)
    return np.stack([cx + r * np.cos(t), cy + r * np.sin(t)], -1)


def shape(name):
    sq = np.array([[.1, .1], [.9, .1], [.9, .9], [.1, .9]])
    if name == "blob":
        t = np.linspace(0, 2 * np.pi, 256, endpoint=False)
        r = 0.38 + 0.05 * np.sin(3 * t) + 0.02 * np.cos(5 * t)
        return np.stack([.5 + r * np.cos(t), .5 + r * np.sin(t)], -1), []
    if name == "lshape":
        return np.array([[.1, .1], [.9, .1], [.9, .5], [.5, .5], [.5, .9], [.1, .9]]), []
    if name == "uslot":
        return np.array([[.1, .1], [.9, .1], [.9, .9], [.6, .9], [.6, .3], [.4, .3], [.4, .9], [.1, .9]]), []
    if name == "notch":
        return np.array([[.1, .1], [.9, .1], [.9, .4], [.55, .5], [.9, .6], [.9, .9], [.1, .9]]), []
    if name == "crescent":
        # the disk of radius .4 at (.5, .5) less the disk of radius .3 at (.7, .5): a C open towards +u.
        # The circles cross at angle 0.812 of the first and 1.318 of the second.
        a1, a2 = math.atan2(0.2905, 0.275), math.atan2(0.2905, 0.075)
        outer = arc(.5, .5, .4, a1, 2 * np.pi - a1, 200)
        inner = arc(.7, .5, .3, 2 * np.pi - a2, a2, 140)[1:-1]  # clockwise, through its leftmost point
        return np.vstack([outer, inner]), []
    if name == "corner":
        bite = arc(.9, .9, .45, -0.5 * np.pi, -np.pi, 80)  # concave: from (.9, .45) round to (.45, .9)
        return np.vstack([[[.1, .1], [.9, .1]], bite, [[.1, .9]]]), []
    if name == "strip":
        return np.array([[.05, .455], [.95, .455], [.95, .545], [.05, .545]]), []
    if name == "ring":
        return sq, [circle(.5, .5, .15, 96)[::-1]]
    raise ValueError(name)


SHAPES = ["blob", "lshape", "uslot", "notch", "crescent", "corner", "strip", "ring"]
NOISE = [0.0, 5e-4, 2e-3]
SIZES = [2000, 5000, 10000, 20000]


def inside(loops, pts):
    """Even-odd containment of pts (n, 2) in the union of loops."""
    res = np.zeros(len(pts), bool)
    x, y = pts[:, 0], pts[:, 1]
    for loop in loops:
        a, b = loop, np.roll(loop, -1, 0)
        for (x0, y0), (x1, y1) in zip(a, b):
            cross = ((y0 > y) != (y1 > y)) & (x < (x1 - x0) * (y - y0) / (y1 - y0 + 1e-300) + x0)
            res ^= cross
    return res


def seg_dist(pts, loops):
    d = np.full(len(pts), np.inf)
    for loop in loops:
        a, b = loop, np.roll(loop, -1, 0)
        for p0, p1 in zip(a, b):
            e = p1 - p0
            t = np.clip(((pts - p0) @ e) / max(e @ e, 1e-300), 0, 1)
            d = np.minimum(d, np.linalg.norm(pts - (p0 + t[:, None] * e), axis=1))
    return d


def resample(loop, h):
    out = []
    for p0, p1 in zip(loop, np.roll(loop, -1, 0)):
        n = max(1, int(math.ceil(np.linalg.norm(p1 - p0) / h)))
        for k in range(n):
            out.append(p0 + (p1 - p0) * k / n)
    return np.array(out)


def area(loop):
    x, y = loop[:, 0], loop[:, 1]
    return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)


def boundary_loops(tris):
    """Directed boundary edges of an oriented triangle list, chained into loops."""
    edges = {}
    for t in tris:
        for k in range(3):
            a, b = int(t[k]), int(t[(k + 1) % 3])
            edges[(a, b)] = edges.get((a, b), 0) + 1
    nxt = {}
    for (a, b) in edges:
        if (b, a) not in edges:
            if a in nxt:
                return None  # a vertex on two boundary stretches: not a manifold boundary
            nxt[a] = b
    loops, seen = [], set()
    for s in nxt:
        if s in seen:
            continue
        loop, v = [], s
        while v not in seen:
            seen.add(v)
            loop.append(v)
            v = nxt.get(v)
            if v is None:
                return None
        loops.append(loop)
    return loops


def sides_between(ring, corners):
    """The S, E, N, W segments of the loop `ring` between its four corner positions, in loop order."""
    def run(i, j):
        out = [int(ring[i])]
        while i != j:
            i = (i + 1) % len(ring)
            out.append(int(ring[i]))
        return out
    return [{"label": L, "vertices": run(corners[k], corners[(k + 1) % 4])} for k, L in enumerate("SENW")]


def labels_by_rule(uv, ring):
    """The issue's rule: corners at the loop vertices nearest the corners of the parameter box; S from
    SW to SE, E from SE to NE, N from NE to NW, W from NW to SW along the anticlockwise loop `ring`.
    None when two corners fall on one vertex."""
    ring = np.asarray(ring)
    lo, hi = uv.min(0), uv.max(0)

    def nearest(q):
        return int(np.argmin(np.linalg.norm(uv[ring] - np.array(q), axis=1)))
    corners = [nearest((lo[0], lo[1])), nearest((hi[0], lo[1])), nearest((hi[0], hi[1])), nearest((lo[0], hi[1]))]
    if len(set(corners)) < 4:
        return None
    return sides_between(ring, corners)


def labels_by_corners(uv, ring, min_turn=np.radians(30)):
    """Labels by corner angles: the four vertices of the anticlockwise loop `ring` where the boundary
    turns left most sharply (by at least min_turn, in the true parameters) are the corners, S the
    side that starts at the one nearest the parameter box's SW corner, then E, N, W. None when the
    loop has fewer than four such corners (a blob, a crescent)."""
    ring = np.asarray(ring)
    p = uv[ring]
    a, b = p - np.roll(p, 1, 0), np.roll(p, -1, 0) - p
    turn = np.arctan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0], (a * b).sum(1))  # > 0: a left (convex) turn
    candidates = np.where(turn >= min_turn)[0]
    if len(candidates) < 4:
        return None
    corners = sorted(candidates[np.argsort(-turn[candidates])[:4]])
    lo = uv.min(0)
    first = int(np.argmin([np.linalg.norm(p[c] - lo) for c in corners]))
    corners = corners[first:] + corners[:first]
    return sides_between(ring, corners)


def write_region(out_dir, rid, header, r, entry):
    """region.obj, labels.json, band.xyz and truth.xyz of one region; its index entry."""
    d = os.path.join(out_dir, rid)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "region.obj"), "w") as f:
        f.write("# labeled region %s: %s\n" % (rid, header))
        for p in r["xyz"]:
            f.write("v %.10g %.10g %.10g\n" % tuple(p))
        for t in r["tri"]:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
    with open(os.path.join(d, "labels.json"), "w") as f:
        json.dump({"segments": r["segments"]}, f)
    np.savetxt(os.path.join(d, "band.xyz"), r["band"], fmt="%.10g")
    np.savetxt(os.path.join(d, "truth.xyz"), r["truth"], fmt="%.10g")
    entry = dict({"id": rid}, **entry)
    entry.update({"vertices": int(len(r["xyz"])), "triangles": int(len(r["tri"])), "diagonal": round(r["diag"], 6),
                  "band_points": int(len(r["band"]))})
    return entry


def make_region(idx, surface, shape_name, noise, clockwise, target):
    rng = np.random.default_rng(idx)
    outer, inners = shape(shape_name)
    loops = [outer] + inners
    a = abs(area(outer)) - sum(abs(area(l)) for l in inners)
    h = math.sqrt(a / target * 1.15)  # about `target` vertices (a triangle mesh has ~2 triangles per vertex)
    bnd = [resample(l, h) for l in loops]
    gx = np.arange(0, 1 + h, h)
    g = np.stack(np.meshgrid(gx, np.arange(0, 1 + h, h * math.sqrt(3) / 2)), -1).reshape(-1, 2)
    g[:, 0] += (np.round(g[:, 1] / (h * math.sqrt(3) / 2)) % 2) * h / 2
    g += rng.uniform(-0.3 * h, 0.3 * h, g.shape)  # irregular
    g = g[inside(loops, g) & (seg_dist(g, loops) > 0.6 * h)]
    pts = np.vstack(bnd + [g])
    tri = Delaunay(pts).simplices
    c = pts[tri].mean(1)
    tri = tri[inside(loops, c)]
    # orient anticlockwise in (u, v)
    p0, p1, p2 = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    sgn = (p1[:, 0] - p0[:, 0]) * (p2[:, 1] - p0[:, 1]) - (p1[:, 1] - p0[:, 1]) * (p2[:, 0] - p0[:, 0])
    tri = tri[sgn > 1e-14 * h * h]
    used = np.unique(tri)
    remap = -np.ones(len(pts), int)
    remap[used] = np.arange(len(used))
    uv, tri = pts[used], remap[tri]
    f = bspline_field(idx) if surface == "bspline" else waves_field(idx) if surface == "waves" else SURFACES[surface]
    xyz = f(uv[:, 0], uv[:, 1])
    # The surface's normal side: the map's Jacobian orientation decides which way "anticlockwise in uv" faces.
    lo, hi = xyz.min(0), xyz.max(0)
    diag = float(np.linalg.norm(hi - lo))
    noisy = xyz + rng.normal(0, noise * diag, xyz.shape) if noise > 0 else xyz
    loops_v = boundary_loops(tri)
    if loops_v is None or len(loops_v) != 1 + len(inners):
        return None
    # the outer loop: the one with the largest |area| in uv; anticlockwise since triangles are
    outer_loop = max(loops_v, key=lambda l: abs(area(uv[l])))
    segments = labels_by_rule(uv, outer_loop)
    if segments is None:
        return None
    corner_segments = labels_by_corners(uv, outer_loop)
    if clockwise:
        tri = tri[:, ::-1]
    # band: the true surface over the region's parameter bbox grown by 10%, outside the region
    ul, vl = uv.min(0)
    uh, vh = uv.max(0)
    du, dv = 0.1 * (uh - ul), 0.1 * (vh - vl)
    bu = np.linspace(ul - du, uh + du, 60)
    bv = np.linspace(vl - dv, vh + dv, 60)
    bq = np.stack(np.meshgrid(bu, bv), -1).reshape(-1, 2)
    bq = bq[~inside(loops, bq) & (seg_dist(bq, loops) > 2 * h)]
    band = f(bq[:, 0], bq[:, 1])
    return {"uv": uv, "xyz": noisy, "truth": xyz, "tri": tri, "segments": segments, "band": band, "diag": diag,
            "corner_segments": corner_segments}


# --- a real scan: regions cut from the Stanford bunny as CGAL's demo data ships it -------------

BUNNY_TAR = "/usr/share/doc/libcgal-demo/data.tar.gz"
BUNNY_MEMBER = "data/meshes/bunny00.off"


def load_bunny():
    import tarfile
    with tarfile.open(BUNNY_TAR) as tar:
        text = tar.extractfile(BUNNY_MEMBER).read().decode()
    tok = text.split()
    assert tok[0] == "OFF"
    nv, nf = int(tok[1]), int(tok[2])
    v = np.array(tok[4:4 + 3 * nv], float).reshape(nv, 3)
    f = np.array(tok[4 + 3 * nv:4 + 3 * nv + 4 * nf], int).reshape(nf, 4)[:, 1:]
    return v, f


def scan_region(bunny, seed, cut_quadrant, noise, clockwise, idx):
    """The bunny's triangles within a ball around vertex `seed` (the component holding it), grown
    while it stays a height field over its best-fit plane; parameters: that plane's coordinates
    (so the labeling rule has its box corners). cut_quadrant: the quadrant of the parameter box
    beyond the centre removed (an L). The band: the bunny's vertices near the region, outside it."""
    v, f = bunny
    rng = np.random.default_rng(idx)
    centre = v[seed]
    best = None
    size = float(np.linalg.norm(v.max(0) - v.min(0)))
    for r in np.linspace(0.02, 0.3, 15) * size:
        near = np.linalg.norm(v - centre, axis=1) < r
        tri = f[near[f].all(1)]
        used = np.unique(tri)
        if len(used) < 3:
            continue
        p = v[used] - v[used].mean(0)
        _, _, vt = np.linalg.svd(p, full_matrices=False)
        uvall = np.zeros((len(v), 2))
        uvall[used] = p @ vt[:2].T
        a, b, c = uvall[tri[:, 0]], uvall[tri[:, 1]], uvall[tri[:, 2]]
        sgn = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        if (sgn > 0).all() or (sgn < 0).all():  # a height field over the plane (no triangle turned over)
            best = (r, tri, uvall, vt, sgn[0] < 0)
        else:
            break
    if best is None or len(np.unique(best[1])) < 1000:
        return None
    r, tri, uvall, vt, flipped = best
    if flipped:  # anticlockwise in (u, v)
        uvall[:, 1] *= -1
    if cut_quadrant:
        cu = uvall[np.unique(tri)].mean(0)
        c = uvall[tri].mean(1)
        tri = tri[~((c[:, 0] > cu[0]) & (c[:, 1] > cu[1]))]
    # the component holding the seed's triangles, and one boundary loop
    loops = boundary_loops(tri)
    if loops is None or len(loops) != 1:
        return None
    used = np.unique(tri)
    remap = -np.ones(len(v), int)
    remap[used] = np.arange(len(used))
    xyz, uv, t = v[used], uvall[used], remap[tri]
    outer_loop = boundary_loops(t)[0]
    diag = float(np.linalg.norm(xyz.max(0) - xyz.min(0)))
    ul, vl = uv.min(0)
    uh, vh = uv.max(0)
    segments = labels_by_rule(uv, outer_loop)
    if segments is None:
        return None
    noisy = xyz + rng.normal(0, noise * diag, xyz.shape) if noise > 0 else xyz
    if clockwise:
        t = t[:, ::-1]
    # band: bunny vertices within 1.25 r of the seed, not in the region, over the region's grown box
    near = np.linalg.norm(v - centre, axis=1) < 1.25 * r
    near[used] = False
    q = (v[near] - v[used].mean(0)) @ vt[:2].T
    if flipped:
        q[:, 1] *= -1
    du, dv = 0.1 * (uh - ul), 0.1 * (vh - vl)
    keep = (q[:, 0] > ul - du) & (q[:, 0] < uh + du) & (q[:, 1] > vl - dv) & (q[:, 1] < vh + dv)
    return {"xyz": noisy, "truth": xyz, "tri": t, "segments": segments, "band": v[near][keep], "diag": diag}


# Seeds: the first three of every 1,500th vertex whose neighbourhood is a height field of at least
# 1,000 vertices (the scan's own density); each as a blob and as an L, noise and orientation cycling.
SCAN_SEEDS = 3
SCAN_VARIANTS = [(False, 0.0, False), (True, 5e-4, True), (False, 2e-3, True), (True, 0.0, False), (False, 0.0, True),
                 (True, 5e-4, False)]  # (L-cut, noise, clockwise) per seed pair


def regions():
    """The corpus's list: every surface with every shape, noise and size cycling, orientation alternating."""
    out = []
    names = list(SURFACES)
    for si, s in enumerate(names):
        for hi, sh in enumerate(SHAPES):
            k = si * len(SHAPES) + hi
            out.append((k, s, sh, NOISE[(si + hi) % 3], (si + hi) % 2 == 1, SIZES[(si * 3 + hi) % 4]))
    return out


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    out_dir = sys.argv[1]
    index_path = None
    if "--index" in sys.argv:
        index_path = sys.argv[sys.argv.index("--index") + 1]
    index = []
    for k, s, sh, noise, cw, size in regions():
        rid = "%s_%s_%s%s" % (s, sh, ("n%g" % (noise * 100)).replace(".", "p") if noise else "clean", "_cw" if cw else "")
        r = None
        for attempt in range(12):  # a Delaunay that left a pinched boundary: jitter again
            r = make_region(k * 10 + attempt, s, sh, noise, cw, size)
            if r is not None:
                break
        if r is None:
            print("skipped %s: no manifold region" % rid, file=sys.stderr)
            continue
        index.append(write_region(out_dir, rid, "%s surface, %s shape, noise %g of the diagonal, %s"
                                  % (s, sh, noise, "clockwise" if cw else "anticlockwise"), r,
                                  {"surface": s, "shape": sh, "noise": noise, "clockwise": cw}))
        # The same region labeled by its corner angles, where it has four convex corners or more.
        if r["corner_segments"] is not None:
            rc = dict(r, segments=r["corner_segments"])
            index.append(write_region(out_dir, rid + "_corners", "%s surface, %s shape, noise %g of the diagonal, %s, labeled "
                                      "by corner angles" % (s, sh, noise, "clockwise" if cw else "anticlockwise"), rc,
                                      {"surface": s, "shape": sh, "noise": noise, "clockwise": cw, "labels": "corners"}))
    if os.path.exists(BUNNY_TAR):
        bunny = load_bunny()
        made, k = [], 0
        for seed in range(0, len(bunny[0]), 1500):
            if len(made) >= 2 * SCAN_SEEDS:
                break
            pair = []
            for cut in (False, True):
                _, noise, cw = SCAN_VARIANTS[len(made) + len(pair)]
                r = scan_region(bunny, seed, cut, noise, cw, 5000 + seed)
                if r is None:
                    break
                pair.append((seed, cut, noise, cw, r))
            if len(pair) == 2:
                made += pair
        for seed, cut, noise, cw, r in made:
            rid = "scan_bunny%d_%s_%s%s" % (seed, "lshape" if cut else "blob",
                                            ("n%g" % (noise * 100)).replace(".", "p") if noise else "clean", "_cw" if cw else "")
            index.append(write_region(out_dir, rid, "cut from CGAL's bunny00.off (libcgal-demo)", r,
                                      {"surface": "scan", "shape": "lshape" if cut else "blob", "noise": noise, "clockwise": cw}))
    else:
        print("no real scan regions: %s is missing (apt-get install libcgal-demo)" % BUNNY_TAR, file=sys.stderr)
    if index_path:
        with open(index_path, "w") as f:
            json.dump({"generator": "tests/corpus/labeled_regions.py", "regions": index}, f, indent=1)
            f.write("\n")
    print("%d regions in %s" % (len(index), out_dir))
    return 0


if __name__ == "__main__":
    sys.exit(main())
