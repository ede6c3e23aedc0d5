"""Openings bounded by more than one loop (issue 25, item 6), measured on inputs we did not make:
every face with exactly two wires (an annulus: a washer's top, a flange) of OCCT's sample models
removed in turn must be refused with the message naming both loops, and none of the B-rep
corpus's one-loop holes (tests/corpus/brep_holes.py, corpus-out/brep) may be. Run with freecadcmd
and the addon installed: CORPUS=corpus-out/brep freecadcmd tests/bench/bench_opening_loops.py."""
import glob
import json
import os
import time

import HoleFill
import Part

MODELS = "/usr/share/opencascade/data/occ/*.brep"


def read(path):
    s = Part.Shape()
    s.read(path)
    return s


def annular_openings():
    """(name, shell without the face, its loops) for every two-wire face of the sample parts."""
    for path in sorted(glob.glob(MODELS)):
        try:
            model = read(path)
        except Exception:
            continue
        for pi, part in enumerate(list(model.Solids) or list(model.Shells)):
            faces = part.Faces
            if len(faces) > 300:
                continue
            for i, f in enumerate(faces):
                if len(f.Wires) != 2:
                    continue
                try:
                    holed = Part.Shell([g for j, g in enumerate(faces) if j != i])
                    loops = HoleFill.findHoles(holed, includeOuter=True)
                except Exception:
                    continue
                if len(loops) == 2:
                    yield "%s_p%d_f%d" % (os.path.basename(path)[:-5], pi, i + 1), holed, loops


def main():
    t0 = time.time()
    rows = {"annular": [0, 0, []], "corpus": [0, 0, []]}  # cases, refused, others' ids
    for name, holed, loops in annular_openings():
        for loop in loops:  # either loop picked
            rows["annular"][0] += 1
            try:
                HoleFill.fillHole(holed, loop["edges"][:1], sewn=False)
                rows["annular"][2].append(name + " (filled)")
            except HoleFill.HoleFillError as e:
                if "boundary loops" in str(e):
                    rows["annular"][1] += 1
                else:
                    rows["annular"][2].append("%s (%s)" % (name, str(e)[:80]))
    corpus = os.environ.get("CORPUS", "corpus-out/brep")
    index = os.path.join(corpus, "index.json")
    for h in json.load(open(index))["holes"] if os.path.exists(index) else []:
        rows["corpus"][0] += 1
        shape = read(os.path.join(corpus, h["id"], "hole.brep"))
        try:
            HoleFill.prepareHole(shape, 1)
        except HoleFill.HoleFillError as e:
            if "boundary loops" in str(e):
                rows["corpus"][1] += 1
                rows["corpus"][2].append(h["id"])
    print("\n| inputs | loops picked | refused as one opening of several loops | should be |")
    print("|---|---|---|---|")
    print("| OCCT sample parts, each two-wire face removed | %d | %d | all |" % tuple(rows["annular"][:2]))
    print("| B-rep corpus holes (one-loop faces removed) | %d | %d | none |" % tuple(rows["corpus"][:2]))
    for key, (_, _, odd) in rows.items():
        for x in odd[:10]:
            print("%s: %s" % (key, x))
    print("(%.0f s)" % (time.time() - t0))


main()
