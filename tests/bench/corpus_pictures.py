"""Zebra pictures of real corpus holes before (the original part, truth face in place) and after
(our fill sewn in, and GeomPlate's face beside the part), rendered by `holefill render`, one row
per hole in bench-out/corpus/<id>_{before,ours,geomplate}.png. Run in freecadcmd by
scripts/bench.sh after the corpus benchmark: CORPUS_PICTURES="id1 id2 ...".
Each picture shows the filled face and its neighbours only (--faces), seen along the mean normal."""
import os
import subprocess
import sys

import FreeCAD
import Part

import HoleFill

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else "tests/bench")
from geomplate import surface_filling  # noqa: E402

CORPUS = os.environ.get("BENCH_CORPUS", "corpus-out/brep")
OUT = os.path.join(os.environ.get("BENCH_OUT", "/tmp"), "corpus")
CLI = os.environ.get("HOLEFILL_CLI", "holefill")
IDS = os.environ.get("CORPUS_PICTURES", "").split()


def render(shape, faces, path, view):
    tmp = path + ".brep"
    shape.exportBrep(tmp)
    subprocess.run([CLI, "render", tmp, "--out", path, "--mode", "zebra", "--size", "640x480", "--faces=" + ",".join(str(f) for f in faces), "--view", view, "--stripes", "16"], check=False,
                   capture_output=True, text=True)
    os.remove(tmp)


def index_of(shape, face):
    for i, f in enumerate(shape.Faces):
        if f.isSame(face):
            return i + 1
    return None


def near(shape, centre, radius):
    return [i + 1 for i, f in enumerate(shape.Faces) if f.BoundBox.Center.distanceToPoint(centre) < radius]


def main():
    os.makedirs(OUT, exist_ok=True)
    doc = FreeCAD.newDocument("Pictures")
    for hid in IDS:
        d = os.path.join(CORPUS, hid)
        holed, truth = Part.Shape(), Part.Shape()
        holed.read(os.path.join(d, "hole.brep"))
        truth.read(os.path.join(d, "truth.brep"))
        truth = truth.Faces[0]
        hole = HoleFill.findHoles(holed)[0]
        n = truth.normalAt(*[0.5 * (a + b) for a, b in zip(truth.ParameterRange[0::2], truth.ParameterRange[1::2])])
        view = "%g,%g,%g" % (-n.x, -n.y, -n.z)
        centre, radius = truth.BoundBox.Center, 1.5 * truth.BoundBox.DiagonalLength
        before = Part.Compound(holed.Faces + [truth])
        render(before, near(before, centre, radius), os.path.join(OUT, hid + "_before.png"), view)
        try:
            face, sewn, rep = HoleFill.fillHole(holed, hole, sewn=True)
            render(sewn, near(sewn, centre, radius), os.path.join(OUT, hid + "_ours.png"), view)
            print("%s ours %s %s g0r %.1e g1 %.1e" % (hid, rep["status"], rep["method"], rep["g0_relative"], rep["g1"]))
        except HoleFill.HoleFillError as e:
            print("%s ours failed: %s" % (hid, e))
        f, _ = surface_filling(doc, holed, hole, 1)
        if f.isValid() and not f.Shape.isNull() and f.Shape.Faces:
            plate = Part.Compound(holed.Faces + [f.Shape.Faces[0]])
            render(plate, near(plate, centre, radius), os.path.join(OUT, hid + "_geomplate.png"), view)
        for o in list(doc.Objects):
            doc.removeObject(o.Name)


main()
os._exit(0)
