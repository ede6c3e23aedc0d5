"""Headless FreeCAD tests of the G-NURBS door: HoleFill.gnurbsSurface on arrays, cages taken
from Part shells of quads, the parametric object that follows its cage, and bad cages."""
import json

import FreeCAD
import Part

import fcharness
import HoleFill


def cage_shell(cage):
    """The cage as a Part shell of bilinear (ruled) quads, as a user might have built it."""
    v = [FreeCAD.Vector(*p) for p in cage["vertices"]]
    faces = []
    for a, b, c, d in cage["quads"]:
        # Ruled between edge a-b and edge d-c: corners a, b, c, d in order.
        faces.append(Part.makeRuledSurface(Part.makeLine(v[a], v[b]), Part.makeLine(v[d], v[c])))
    return Part.makeShell(faces)


def test_surface_from_arrays_is_g2_valid_and_in_control_face_order():
    cage = HoleFill.sampleCage("cage_valence5")
    shell, rep = HoleFill.gnurbsSurface(cage["vertices"], cage["quads"])
    assert shell.isValid() and shell.ShapeType == "Shell", shell.ShapeType
    assert len(shell.Faces) == rep["brep"]["faces"] == len(rep["faces"]) == 5 * 4 + 40, len(shell.Faces)
    c = rep["continuity"]
    assert c["g1_spokes"] < 1e-8 and c["g2_spokes"] < 1e-6 and c["g1_elsewhere"] < 1e-8 and c["g2_elsewhere"] < 1e-6, c
    assert rep["extraordinary_points"] == [0] and rep["warnings"] == []
    assert rep["faces"][0] == {"name": "Face1", "control_face": 0, "sub_patch": 0, "input_face": 0}, rep["faces"][0]
    bb = shell.BoundBox
    assert bb.XLength > 3 and bb.YLength > 3
    merged, mrep = HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], mergeRegular=True)
    assert merged.isValid() and len(merged.Faces) == 30 and abs(merged.Area - shell.Area) < 1e-6 * shell.Area, len(merged.Faces)
    # A crease ending inside the cage (at spoke vertex 1) is a dart: built, with a warning.
    dart, drep = HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], sharpEdges=[(0, 1)])
    assert dart.isValid() and any("dart" in w and "vertex 1" in w for w in drep["warnings"]), drep["warnings"]
    # An anchor places the EP: Face1's corner (0, 0) is the EP.
    peak, prep = HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], sharpEdges=[(0, 1), (1, 2), (2, 3)],
                                        anchors={0: (0.0, 0.0, 1.5)})
    corner = peak.Faces[0].Surface.value(0, 0)
    assert (corner - FreeCAD.Vector(0, 0, 1.5)).Length < 1e-9, corner


def test_a_cage_fitted_to_target_points_moves_to_them():
    # The macro door fits as the CLI's --fit does (one core pipeline): points sampled from the
    # surface of a cage, and that cage with its vertices lifted, fitted back to them.
    import random
    cage = HoleFill.sampleCage("cage_valence5")
    truth, _ = HoleFill.gnurbsSurface(cage["vertices"], cage["quads"])
    rnd = random.Random(4)
    target = []
    for f in truth.Faces:
        u0, u1, v0, v1 = f.ParameterRange
        for _ in range(6):
            target.append(tuple(f.valueAt(u0 + rnd.random() * (u1 - u0), v0 + rnd.random() * (v1 - v0))))
    lifted = [(x, y, z + 0.05 * rnd.uniform(-1, 1)) for x, y, z in cage["vertices"]]
    shell, rep = HoleFill.gnurbsSurface(lifted, cage["quads"], target=target, fitRounds=4)
    assert shell.isValid(), rep["brep"]
    fit = rep["fit"]
    assert fit["points"] == len(target) and fit["d_max_percent"] < 0.1, fit
    moved = rep["cage_vertices_fitted"]
    assert len(moved) == len(lifted)
    assert max(abs(m[2] - l[2]) for m, l in zip(moved, lifted)) > 1e-3, "the cage did not move"
    plain, prep = HoleFill.gnurbsSurface(cage["vertices"], cage["quads"])
    assert "fit" not in prep and "cage_vertices_fitted" not in prep
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], target=[]), "no points")


def test_cage_from_a_part_shell_gives_the_same_surface():
    cage = HoleFill.sampleCage("cage_valence3")
    shell = cage_shell(cage)
    back = HoleFill.cageFromShape(shell)
    assert len(back["vertices"]) == len(cage["vertices"]) and len(back["quads"]) == len(cage["quads"])
    s1, r1 = HoleFill.gnurbsSurface(cage["vertices"], cage["quads"])
    s2, r2 = HoleFill.gnurbsSurface(back["vertices"], back["quads"])
    assert r2["extraordinary_points"] and r2["continuity"]["g2_spokes"] < 1e-6
    assert abs(s1.Area - s2.Area) < 1e-9 * s1.Area, (s1.Area, s2.Area)
    # A cube of Part faces (closed): refined once, a closed shell.
    box = Part.makeBox(2, 2, 2)
    cube = HoleFill.cageFromShape(box)
    s3, r3 = HoleFill.gnurbsSurface(cube["vertices"], cube["quads"])
    assert r3["refinements"] == 1 and r3["brep"]["closed"] and s3.isClosed(), r3["brep"]
    solid = Part.Solid(s3)
    # A smooth, rounded cube inside the 2×2×2 box (measured volume 2.62), symmetric like the cage.
    bb = s3.BoundBox
    assert solid.isValid() and 2 < abs(solid.Volume) < 8, solid.Volume
    assert abs(bb.XLength - bb.YLength) < 1e-6 and abs(bb.XLength - bb.ZLength) < 1e-6 and bb.XLength < 2, bb
    assert (bb.Center - FreeCAD.Vector(1, 1, 1)).Length < 1e-6, bb.Center


def test_parametric_object_follows_its_cage_and_undo_removes_it():
    doc = FreeCAD.newDocument("Gnurbs")
    doc.UndoMode = 1
    cage = HoleFill.sampleCage("cage_valence5")
    src = doc.addObject("Part::Feature", "Cage")
    src.Shape = cage_shell(cage)
    doc.recompute()
    obj = HoleFill.makeGnurbs(src)
    name = obj.Name
    assert obj.isValid() and obj.Status == "ok" and obj.G2 < 1e-6, (obj.Status, obj.G2)
    area = obj.Shape.Area
    assert json.loads(obj.Report)["extraordinary_points"]
    # Lift the EP: the surface follows on recompute; the cage object itself is untouched by us.
    moved = [list(p) for p in cage["vertices"]]
    moved[0][2] += 0.8
    src.Shape = cage_shell({"vertices": moved, "quads": cage["quads"]})
    doc.recompute()
    assert abs(obj.Shape.Area - area) > 1e-3 * area, (obj.Shape.Area, area)
    assert obj.G2 < 1e-6
    doc.undo()  # the source change
    doc.undo()  # the object
    assert doc.getObject(name) is None, [o.Name for o in doc.Objects]
    FreeCAD.closeDocument(doc.Name)


def test_bad_cages_give_clear_errors_and_add_nothing():
    cage = HoleFill.sampleCage("cage_valence5")
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(cage["vertices"], [[0, 1, 2]]), "4 vertex indices")
    bad = [list(p) for p in cage["vertices"]]
    bad[3][1] = float("nan")
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(bad, cage["quads"]), "non-finite")
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], knots=[(0, 1, 0.0)]), "positive")
    fcharness.expect_error(lambda: HoleFill.gnurbsSurface(cage["vertices"], cage["quads"], anchors={5: (0, 0, 1)}),
                           "vertex 5", "not an extraordinary point")
    tri = Part.makeShell([Part.Face(Part.makePolygon([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(1, 0, 0),
                                                      FreeCAD.Vector(0, 1, 0), FreeCAD.Vector(0, 0, 0)]))])
    fcharness.expect_error(lambda: HoleFill.cageFromShape(tri), "Face1", "3 corners")
    fcharness.expect_error(lambda: HoleFill.cageFromShape(Part.Shape()), "no faces")
    doc = FreeCAD.newDocument("GnurbsBad")
    src = doc.addObject("Part::Feature", "Tri")
    src.Shape = tri
    doc.recompute()
    count = len(doc.Objects)
    fcharness.expect_error(lambda: HoleFill.makeGnurbs(src), "corners")
    assert len(doc.Objects) == count
    FreeCAD.closeDocument(doc.Name)


fcharness.run(globals())
