#!/usr/bin/env python3
"""Writes the fuzz harnesses' seed corpora (tests/fuzz/corpus/NAME/), deterministically.

    /usr/bin/python3 tests/fuzz/seeds.py HOLEFILL [OUT]     (OUT: tests/fuzz/corpus)

Seeds are small valid inputs of each format (libFuzzer mutates from them: a small seed means many
executions a second) and the bad inputs issue 22 listed (cut-off and inflated BREP text, NUL bytes,
a PLY whose body outruns its header), so the smoke replays those classes on every test run.
The models, cages and the labeled region come from `holefill samples`; meshes and clouds are
written here. Inputs the fuzzers found sit beside the seeds under names that say what they broke.
"""
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile


def grid(n, height, hole=None):
    """An n x n grid of triangles over [0,1]^2 lifted by height(x, y); hole: cells (i, j) left out."""
    v = [(i / (n - 1), j / (n - 1), height(i / (n - 1), j / (n - 1))) for j in range(n) for i in range(n)]
    f = []
    for j in range(n - 1):
        for i in range(n - 1):
            if hole and (i, j) in hole:
                continue
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
            f += [(a, b, c), (a, c, d)]
    return v, f


def obj(v, f):
    return "".join("v %.9g %.9g %.9g\n" % p for p in v) + "".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in f)


def off(v, f):
    return "OFF\n%d %d 0\n" % (len(v), len(f)) + "".join("%.9g %.9g %.9g\n" % p for p in v) + \
        "".join("3 %d %d %d\n" % t for t in f)


def ply_ascii(v, f):
    head = "ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n" \
           "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(v), len(f))
    return head + "".join("%.9g %.9g %.9g\n" % p for p in v) + "".join("3 %d %d %d\n" % t for t in f)


def ply_binary(v, f):
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(v), len(f))).encode()
    return head + b"".join(struct.pack("<3f", *p) for p in v) + b"".join(struct.pack("<B3i", 3, *t) for t in f)


def stl_ascii(v, f):
    out = "solid seed\n"
    for t in f:
        out += " facet normal 0 0 1\n  outer loop\n" + "".join("   vertex %.9g %.9g %.9g\n" % v[k] for k in t) + \
               "  endloop\n endfacet\n"
    return out + "endsolid seed\n"


def stl_binary(v, f):
    return b"\0" * 80 + struct.pack("<I", len(f)) + b"".join(
        struct.pack("<3f", 0, 0, 1) + b"".join(struct.pack("<3f", *v[k]) for k in t) + b"\0\0" for t in f)


def cloud(n, flags, uv, height):
    lines = []
    for j in range(n):
        for i in range(n):
            x, y = i / (n - 1), j / (n - 1)
            p = "%.9g %.9g %.9g" % (x, y, height(x, y))
            edge = i in (0, n - 1) or j in (0, n - 1)
            if flags:
                p += " %d" % edge
                if uv and edge:
                    p += " %.9g %.9g" % (x, y)
            lines.append(p)
    return "\n".join(lines) + "\n"


def main():
    holefill = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    tmp = tempfile.mkdtemp()
    subprocess.run([holefill, "samples", tmp], check=True, stdout=subprocess.DEVNULL)
    # A STEP model for the file harness: the smallest sample's fill, written as STEP.
    subprocess.run([holefill, "fill", os.path.join(tmp, "box_minus_face.brep"), "--out", os.path.join(tmp, "box.step")],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def read(name):
        with open(os.path.join(tmp, name), "rb") as fh:
            return fh.read()

    # Files are (over)written, never removed: the corpora also hold the inputs fuzzing found
    # (copied there by hand from build-fuzz/fuzz/NAME/, docs/fuzzing.md), which are regression tests.
    def put(harness, name, data):
        os.makedirs(os.path.join(out, harness), exist_ok=True)
        with open(os.path.join(out, harness, name), "wb") as fh:
            fh.write(data.encode() if isinstance(data, str) else data)

    small_models = ["box_minus_face", "closed_box", "open_cylinder", "non_manifold_fin", "bezier_patch_with_hole",
                    "filleted_box_adjacent_holes.divider"]
    box = read("box_minus_face.brep")
    for m in small_models:
        put("brep_text", m, read(m + ".brep"))
        put("model_file", m, b"\0" + read(m + ".brep"))
    put("brep_text", "cut_off", box[: len(box) // 2])
    put("brep_text", "inflated_count", box.replace(b"TShapes 31", b"TShapes 3100000", 1))
    put("brep_text", "nul_bytes", box[:200] + b"\0\0\0" + box[200:])
    # The STEP header's time stamp is fixed, so the seeds do not change from run to run.
    step = re.sub(rb"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d", b"2026-01-01T00:00:00", read("box.step"))
    put("model_file", "box_step", b"\1" + step)
    put("model_file", "box_step_cut_off", b"\1" + step[:3000])
    for m in ["box_minus_face", "open_cylinder", "bezier_patch_with_hole", "sheet_two_holes"]:
        put("fill", m, read(m + ".brep"))

    flat = grid(6, lambda x, y: 0.0, hole={(2, 2)})
    bump = grid(7, lambda x, y: 0.3 * math.exp(-8 * ((x - .5) ** 2 + (y - .5) ** 2)), hole={(2, 2), (3, 2), (3, 3)})
    edge_hole = grid(5, lambda x, y: 0.1 * x * y, hole={(0, 1), (1, 1)})
    for name, (v, f) in {"flat_hole": flat, "bump_hole": bump, "edge_notch": edge_hole}.items():
        put("mesh_obj", name, obj(v, f))
        put("mesh_off", name, off(v, f))
        put("mesh_ply", name + "_ascii", ply_ascii(v, f))
        put("mesh_ply", name + "_binary", ply_binary(v, f))
        put("mesh_stl", name + "_ascii", stl_ascii(v, f))
        put("mesh_stl", name + "_binary", stl_binary(v, f))
        put("mesh_fill", name, obj(v, f))
    put("mesh_ply", "body_outruns_header", ply_ascii(*flat) + "0 0 0\n")
    put("mesh_off", "body_outruns_header", off(*flat) + "3 0 1 2\n")

    for c in ["cage_cube", "cage_valence3", "cage_valence5"]:
        put("cage", c, read(c + ".obj"))
        put("gnurbs", c, read(c + ".obj"))
    marked = read("cage_valence3.obj").decode() + "# sharp 1 2\n# knot 2 3 2.5\n# anchor 1 0 0 0.5\n"
    put("cage", "comments", marked)
    put("gnurbs", "comments", marked)

    put("json", "labels", read("labeled_region.labels.json"))
    put("json", "sharp", "[[1, 2], [2, 3]]\n")
    put("json", "anchors", "[[1, 0.5, -1e-3, 2e+2]]\n")
    put("json", "escapes", '{"a": "\\u00e9\\n\\"", "b": [true, false, null, -0.5e-7, {}], "c": []}\n')

    # A small labeled region: the 7x7 bump without its hole, its boundary labeled S, E, N, W.
    v, f = grid(7, lambda x, y: 0.3 * math.exp(-8 * ((x - .5) ** 2 + (y - .5) ** 2)))
    n = 7
    side = lambda label, ks: '{"label": "%s", "vertices": [%s]}' % (label, ", ".join(map(str, ks)))
    labels = '{"segments": [%s]}' % ", ".join([
        side("S", [i for i in range(n)]), side("E", [j * n + n - 1 for j in range(n)]),
        side("N", [(n - 1) * n + i for i in reversed(range(n))]), side("W", [j * n for j in reversed(range(n))])])
    put("fit", "bump_square", obj(v, f) + "---\n" + labels + "\n")
    put("fit", "sample_region", read("labeled_region.obj") + b"---\n" + read("labeled_region.labels.json"))

    height = lambda x, y: 0.2 * math.sin(3 * x) * y
    put("cloud", "flags_uv", cloud(8, True, True, height))
    put("cloud", "flags", cloud(8, True, False, height))
    put("cloud", "bare", cloud(8, False, False, height))
    put("points", "flags_uv", cloud(12, True, True, height))
    put("points", "bare", cloud(12, False, False, height))
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main()
