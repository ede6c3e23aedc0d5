"""Headless FreeCAD tests of point clouds from Python: a planar jittered grid gets its own
parameters back (shape-preserving), a wavy Points cloud gets parameters inside the unit square
with every method (BIDGCN included), a Points cloud without a boundary and a Mesh are fitted
within a tolerance in model units, bad input raises clear errors."""
import json
import math
import random

import FreeCAD
import Part
import Points

import fcharness
import HoleFill


def grid(lift, m=16, seed=2):
    random.seed(seed)
    pts, boundary, truth = [], {}, []
    for j in range(m + 1):
        for i in range(m + 1):
            rim = i in (0, m) or j in (0, m)
            u = (i + (0 if rim else random.uniform(-.3, .3))) / m
            v = (j + (0 if rim else random.uniform(-.3, .3))) / m
            if rim:
                boundary[len(pts)] = (u, v)
            pts.append(FreeCAD.Vector(u, v, lift(u, v)))
            truth.append((u, v))
    return pts, boundary, truth


def test_planar_grid_gets_its_own_parameters_back():
    pts, boundary, truth = grid(lambda u, v: 0.0)
    uv, rep = HoleFill.parameterize(pts, boundary)
    assert uv.shape == (len(pts), 2), uv.shape
    err = max(abs(a - b) for p, q in zip(uv.tolist(), truth) for a, b in zip(p, q))
    assert err < 1e-9, err
    assert rep["fallbacks"] == 0 and rep["radius"] > 0, rep


def test_a_points_object_gets_parameters_inside_the_square_with_every_method():
    pts, boundary, _ = grid(lambda u, v: 0.3 * math.sin(3 * u) * math.cos(2 * v))
    cloud = Points.Points()
    cloud.addPoints(pts)
    for method in ("shape", "invdist", "uniform", "bidgcn"):
        uv, rep = HoleFill.parameterize(cloud, boundary, method=method)
        assert uv.min() >= -1e-12 and uv.max() <= 1 + 1e-12, (method, uv.min(), uv.max())
        assert rep["method"] == method, rep
        if method != "bidgcn":
            assert rep["min_neighbours"] >= 3, rep


def bump_cloud(scale=20.0, n=1500, seed=3):
    random.seed(seed)
    pts = []
    for _ in range(n):
        u, v = random.random(), random.random()
        pts.append(FreeCAD.Vector(scale * u, scale * v, scale * (0.2 * math.sin(2.5 * u) * math.cos(1.8 * v)
                                                             + 0.08 * math.exp(-40 * ((u - .6) ** 2 + (v - .4) ** 2)))))
    return pts


def test_a_points_cloud_without_boundary_is_fitted_within_a_model_unit_tolerance():
    cloud = Points.Points()
    cloud.addPoints(bump_cloud())
    face, rep = HoleFill.fitPoints(cloud, tolerance=0.02)  # 20 mm sheet, 0.02 mm
    assert face.isValid() and face.Area > 390, face.Area
    assert rep["met_tolerance"] and max(rep["errors"]) <= 0.02 + 1e-12, (rep["met_tolerance"], max(rep["errors"]))
    assert rep["folds"] == 0, rep["folds"]
    assert rep["boundary_found"] > 40 and len(rep["boundary"]) == rep["boundary_found"], rep["boundary_found"]
    assert rep["levels"] > 1 and len(rep["cells"]) > 16, (rep["levels"], len(rep["cells"]))
    dofs = [it["dof"] for it in rep["iterations"]]
    assert dofs == sorted(dofs) and dofs[-1] > dofs[0], dofs
    # The fitted face passes within the tolerance of every point.
    worst = max(face.distToShape(Part.Vertex(p))[0] for p in cloud.Points[::50])
    assert worst <= 0.02 + 1e-6, worst


def test_a_mesh_is_fitted_through_its_own_boundary_with_bidgcn():
    import Mesh
    pts, _, _ = grid(lambda u, v: 0.2 * math.sin(2 * u) * v, m=30)
    facets = []
    for j in range(30):
        for i in range(30):
            a = j * 31 + i
            facets += [[pts[a], pts[a + 1], pts[a + 32]], [pts[a], pts[a + 32], pts[a + 31]]]
    mesh = Mesh.Mesh(facets)
    face, rep = HoleFill.fitPoints(mesh, method="bidgcn", tolerance=1e-3)
    assert rep["parameterization"]["method"] == "bidgcn", rep["parameterization"]
    assert len(rep["boundary"]) == 120 and rep["boundary_found"] == -1, (len(rep["boundary"]), rep["boundary_found"])
    assert rep["met_tolerance"], rep["iterations"]
    assert face.isValid()


def test_a_parametric_fit_follows_its_options_and_leaves_nothing_when_it_fails():
    doc = FreeCAD.newDocument("PointFit")
    doc.UndoMode = 1
    src = doc.addObject("Points::Feature", "Scan")
    src.Points = Points.Points(bump_cloud(n=1200))
    box = doc.addObject("Part::Box", "Box")
    doc.recompute()
    count = len(doc.Objects)
    fcharness.expect_error(lambda: HoleFill.makePointCloudFit(box), "neither a Points nor a Mesh")
    assert len(doc.Objects) == count
    fit = HoleFill.makePointCloudFit(src, tolerance=0.05)
    rep = json.loads(fit.Report)
    assert fit.Method == "shape" and rep["met_tolerance"] and fit.Shape.isValid(), rep
    dof = rep["iterations"][-1]["dof"]
    fit.Tolerance = 0.5
    doc.recompute()
    looser = json.loads(fit.Report)
    assert looser["iterations"][-1]["dof"] < dof and looser["met_tolerance"], (dof, looser["iterations"])
    fit.Degree = 0  # refused by the constraint, kept at 1..7
    assert fit.Degree >= 1, fit.Degree
    doc.undo()
    assert len(doc.Objects) == count, [o.Name for o in doc.Objects]
    FreeCAD.closeDocument(doc.Name)


def test_bad_clouds_give_clear_errors():
    pts, boundary, _ = grid(lambda u, v: 0.0)
    fcharness.expect_error(lambda: HoleFill.parameterize(pts, {}), "boundary points")
    fcharness.expect_error(lambda: HoleFill.parameterize(pts[:8], {0: (0, 0), 1: (1, 0), 2: (0, 1)}), "at least 10")
    fcharness.expect_error(lambda: HoleFill.parameterize(pts, boundary, method="bidgcnx"), "unknown parameterization method")
    fcharness.expect_error(lambda: HoleFill.parameterize(pts, {len(pts) + 3: (0, 0)}), "not a point of the cloud")
    twice = list(pts) + [pts[20]]
    fcharness.expect_error(lambda: HoleFill.parameterize(twice, boundary), "coincide")
    fcharness.expect_error(lambda: HoleFill.parameterize(pts, boundary, method="bidgcn", weights="/nonexistent/w.pt"), "weights not found")
    fcharness.expect_error(lambda: HoleFill.fitPoints(pts[:8]), "at least 10")
    fcharness.expect_error(lambda: HoleFill.fitPoints(pts, tolerance=-1), "tolerance must be")
    fcharness.expect_error(lambda: HoleFill.fitPoints(pts, relativeTolerance=0), "relativeTolerance must be")
    line = [FreeCAD.Vector(k, 2 * k, 0) for k in range(30)]
    fcharness.expect_error(lambda: HoleFill.fitPoints(line), "line")


fcharness.run(globals())
