#!/usr/bin/env python3
"""Corpus of triangle meshes with holes for mesh hole filling (issue 26): meshes nobody here made,
as they ship, and holes cut from closed ones with the cut-away triangles kept as ground truth.

Sources
  CGAL's demo data (Debian libcgal-demo, data.tar.gz: meshes/*.off, scans and CAD-like meshes,
  polygons split into fans) and assimp's test models (Debian assimp-testmodels: OFF, PLY, STL,
  OBJ), every one that reads as a triangle mesh of 100 to 400,000 triangles.
Classes
  real        a source mesh that has holes, as it is (holes touching at seams or singular
              vertices, open borders, non-manifold edges included); no ground truth.
  round       one hole: the triangles whose centroid lies within 3 mean edge lengths of a vertex.
  large       one hole of about 6% of the triangles (a ball around a vertex grown until then).
  crease      a round hole centred on a vertex of a sharp edge (dihedral above 40°), where the
              mesh has one: the hole crosses the crease.
  strip       an elongated hole: within 1.5 edge lengths of a segment 14 edge lengths long.
  touching    two round holes whose centres are 2 radii apart along the surface's tangent plane:
              where they meet at one vertex, the holes share a singular vertex.
  seam        the mesh split along a plane through its centre (the triangles on one side on copies
              of the vertices both sides use, as an exporter writes a texture seam), then a round
              hole centred on the seam: the hole runs into the seam's two boundaries.
Cut classes take the closed, manifold source meshes (no boundary edge, no edge of three
triangles), each class on every mesh in turn, seeded by the case's position (deterministic).

Per case, in OUT/<id>/: input.off (the mesh to fill) and truth.off (the cut-away triangles;
empty for real). OUT/index.json lists per case: id, class, source, vertices, triangles, holes (as
HoleFillApp.meshHoles finds them), fillable holes, notes. tests/corpus/mesh_holes_index.json is
a committed copy.

  PYTHONPATH=build/App /usr/bin/python3 tests/corpus/mesh_holes.py OUT [--per-class N]
"""
import json
import os
import sys
import tarfile
import tempfile

import numpy as np

import HoleFillApp

CGAL_TAR = "/usr/share/doc/libcgal-demo/data.tar.gz"
ASSIMP = "/usr/share/assimp/models"
MIN_TRIANGLES, MAX_TRIANGLES = 100, 400_000
CUT_CLASSES = ("round", "large", "crease", "strip", "touching", "seam")


def sources(work):
    """[(name, path)] of every candidate mesh file, CGAL's meshes extracted into `work`."""
    out = []
    if os.path.exists(CGAL_TAR):
        with tarfile.open(CGAL_TAR) as tar:
            members = [m for m in tar.getmembers() if m.isfile() and m.name.startswith("data/meshes/") and m.name.endswith(".off")]
            tar.extractall(work, members=members)
        for m in sorted(members, key=lambda m: m.name):
            out.append(("cgal_" + os.path.basename(m.name)[:-4], os.path.join(work, m.name)))
    for sub, ext in (("OFF", ".off"), ("PLY", ".ply"), ("STL", ".stl"), ("OBJ", ".obj")):
        folder = os.path.join(ASSIMP, sub)
        for f in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
            if f.lower().endswith(ext) and "invalid" not in f.lower():
                out.append(("assimp_%s_%s" % (sub.lower(), os.path.splitext(f)[0]), os.path.join(folder, f)))
    return out


def read(path):
    """(vertices, triangles) or None where the file does not read as a triangle mesh."""
    try:
        v, t = HoleFillApp.readMesh(path)
    except Exception:  # a reader's refusal: not a mesh this corpus can use
        return None
    v, t = np.asarray(v, float), np.asarray(t, np.int64)
    if not (MIN_TRIANGLES <= len(t) <= MAX_TRIANGLES) or not np.isfinite(v).all():
        return None
    return v, t


def edge_facts(t):
    """(boundary edge count, non-manifold edge count) by vertex index."""
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    _, counts = np.unique(e, axis=0, return_counts=True)
    return int((counts == 1).sum()), int((counts > 2).sum())


def mean_edge(v, t):
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    return float(np.linalg.norm(v[e[:, 0]] - v[e[:, 1]], axis=1).mean())


def face_normals(v, t):
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)


def sharp_vertices(v, t, degrees=40.0):
    """Vertices on edges whose dihedral angle exceeds `degrees`."""
    n = face_normals(v, t)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    owner = np.tile(np.arange(len(t)), 3)
    key = np.sort(e, axis=1)
    order = np.lexsort((key[:, 1], key[:, 0]))
    key, owner = key[order], owner[order]
    same = (key[1:] == key[:-1]).all(axis=1)
    a, b = owner[:-1][same], owner[1:][same]
    sharp = np.einsum("ij,ij->i", n[a], n[b]) < np.cos(np.radians(degrees))
    return np.unique(key[:-1][same][sharp])


def compact(v, tris):
    used = np.unique(tris)
    remap = -np.ones(len(v), np.int64)
    remap[used] = np.arange(len(used))
    return v[used].copy(), remap[tris]


def split(v, t, remove):
    """(input, truth): the mesh without the triangles `remove` (a mask), compacted, and those."""
    return compact(v, t[~remove]), compact(v, t[remove])


def ball(v, t, centre, radius):
    return np.linalg.norm(v[t].mean(axis=1) - centre, axis=1) < radius


def tangent_at(v, t, c, rng):
    """A random unit direction in the surface's tangent plane at its vertex nearest `c`."""
    k = int(np.argmin(np.linalg.norm(v - c, axis=1)))
    normal = face_normals(v, t)[np.any(t == k, axis=1)].sum(axis=0)
    d = np.cross(normal, rng.normal(size=3))
    return d / max(np.linalg.norm(d), 1e-300)


def cut(cls, v, t, rng):
    """The triangles to remove for a cut class (a mask) and a note; None where the class does not
    apply to this mesh."""
    h = mean_edge(v, t)
    pick = lambda pool: v[pool[rng.integers(len(pool))]]
    if cls == "round":
        return ball(v, t, pick(np.arange(len(v))), 3 * h), "radius 3 edges"
    if cls == "large":
        c = pick(np.arange(len(v)))
        d = np.sort(np.linalg.norm(v[t].mean(axis=1) - c, axis=1))
        return ball(v, t, c, d[int(0.06 * len(t))]), "6% of the triangles"
    if cls == "crease":
        sharp = sharp_vertices(v, t)
        if len(sharp) == 0:
            return None
        return ball(v, t, pick(sharp), 3 * h), "radius 3 edges on a sharp edge"
    if cls == "strip":
        c = pick(np.arange(len(v)))
        direction = tangent_at(v, t, c, rng)
        a, b = c - 7 * h * direction, c + 7 * h * direction
        p = v[t].mean(axis=1)
        s = np.clip((p - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1)
        return np.linalg.norm(p - (a + s[:, None] * (b - a)), axis=1) < 1.5 * h, "capsule 14 x 3 edges"
    if cls == "touching":
        c = pick(np.arange(len(v)))
        tangent = tangent_at(v, t, c, rng)
        r = 2.5 * h
        return ball(v, t, c + r * tangent, r) | ball(v, t, c - r * tangent, r), "two balls of 2.5 edges meeting at a vertex"
    return None


def seam(v, t, rng):
    """The mesh with a seam: triangles on the + side of a plane through the centre on copies of
    the vertices both sides use. Returns (v, t, the seam's original vertex indices)."""
    normal = rng.normal(size=3)
    normal /= np.linalg.norm(normal)
    side = (v[t].mean(axis=1) - v.mean(axis=0)) @ normal > 0
    shared = np.intersect1d(np.unique(t[side]), np.unique(t[~side]))
    if len(shared) < 3:
        return None
    copy = -np.ones(len(v), np.int64)
    copy[shared] = len(v) + np.arange(len(shared))
    t2 = t.copy()
    upper = t2[side]
    t2[side] = np.where(copy[upper] >= 0, copy[upper], upper)
    return np.vstack([v, v[shared]]), t2, shared


def write_off(path, v, t):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(v), len(t)))
        np.savetxt(f, v, fmt="%.17g")
        np.savetxt(f, np.hstack([np.full((len(t), 1), 3), t]), fmt="%d")


def holes_of(v, t):
    d = json.loads(HoleFillApp.meshHoles(v, t.astype(np.int32)))
    notes = sorted({h["message"].split(":")[0] for h in d["holes"] if h["message"]})
    return len(d["holes"]), sum(1 for h in d["holes"] if h["fillable"]), notes


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    out = args[0]
    per_class = int(args[args.index("--per-class") + 1]) if "--per-class" in args else 16
    os.makedirs(out, exist_ok=True)
    cases, closed = [], []
    with tempfile.TemporaryDirectory() as work:
        for name, path in sources(work):
            mesh = read(path)
            if mesh is None:
                continue
            v, t = mesh
            boundary, nonmanifold = edge_facts(t)
            if boundary == 0 and nonmanifold == 0:
                closed.append((name, v, t))
            elif boundary > 0:
                cases.append(dict(id="real_" + name, cls="real", source=path, v=v, t=t, gv=np.zeros((0, 3)),
                                  gt=np.zeros((0, 3), np.int64), note="%d boundary, %d non-manifold edges" % (boundary, nonmanifold)))
    # Each class over closed meshes spread evenly over their sizes (sorted by triangle count, every
    # k-th, each class starting one further along), so that a class's cases span small to large.
    closed.sort(key=lambda c: len(c[2]))
    print("%d closed, manifold source meshes (%d to %d triangles)" % (len(closed), len(closed[0][2]), len(closed[-1][2])))
    step = max(1, len(closed) // per_class)
    for ci, cls in enumerate(CUT_CLASSES):
        made = 0
        order = [(k * step + ci) % len(closed) for k in range(len(closed))]
        order = list(dict.fromkeys(order + list(range(len(closed)))))  # every mesh, the spread ones first
        for k in order:
            name, v, t = closed[k]
            if made >= per_class:
                break
            rng = np.random.default_rng(1000 * ci + k)
            note = ""
            sv, st = v, t
            if cls == "seam":
                seamed = seam(v, t, rng)
                if seamed is None:
                    continue
                sv, st, shared = seamed
                remove = ball(sv, st, v[shared[rng.integers(len(shared))]], 3 * mean_edge(v, t))
                note = "seam of %d duplicated vertices, hole of radius 3 edges on it" % len(shared)
            else:
                r = cut(cls, v, t, rng)
                if r is None:
                    continue
                remove, note = r
            if remove.sum() < 2 or remove.sum() > 0.5 * len(st):
                continue
            (iv, it), (gv, gt) = split(sv, st, remove)
            cases.append(dict(id="%s_%s" % (cls, name), cls=cls, source=name, v=iv, t=it, gv=gv, gt=gt, note=note))
            made += 1
    index = []
    for c in cases:
        folder = os.path.join(out, c["id"])
        os.makedirs(folder, exist_ok=True)
        write_off(os.path.join(folder, "input.off"), c["v"], c["t"])
        write_off(os.path.join(folder, "truth.off"), c["gv"], c["gt"])
        holes, fillable, notes = holes_of(c["v"], c["t"])
        index.append(dict(id=c["id"], cls=c["cls"], source=os.path.basename(str(c["source"])), vertices=len(c["v"]),
                          triangles=len(c["t"]), truth_triangles=len(c["gt"]), holes=holes, fillable=fillable,
                          notes=[c["note"]] + notes))
        print("%-45s %-9s %7d triangles %4d holes" % (c["id"], c["cls"], len(c["t"]), holes))
    json.dump(dict(generator="tests/corpus/mesh_holes.py", cases=index), open(os.path.join(out, "index.json"), "w"), indent=1)
    counts = {}
    for c in index:
        counts[c["cls"]] = counts.get(c["cls"], 0) + 1
    print("%d cases: %s" % (len(index), ", ".join("%s %d" % kv for kv in sorted(counts.items()))))


if __name__ == "__main__":
    main()
