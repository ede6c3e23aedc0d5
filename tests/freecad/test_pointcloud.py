"""Headless FreeCAD tests of point-cloud parameterization from Python: a planar jittered grid gets
its own parameters back (shape-preserving), a wavy Points cloud gets parameters inside the unit
square with every method, bad input raises clear errors."""
import math
import random

import FreeCAD
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
    for method in ("shape", "invdist", "uniform"):
        uv, rep = HoleFill.parameterize(cloud, boundary, method=method)
        assert uv.min() >= -1e-12 and uv.max() <= 1 + 1e-12, (method, uv.min(), uv.max())
        assert rep["method"] == method and rep["min_neighbours"] >= 3, rep


def test_bad_clouds_give_clear_errors():
    pts, boundary, _ = grid(lambda u, v: 0.0)
    fcharness.expect_error(lambda: HoleFill.parameterize(pts, {}), "boundary points")
    fcharness.expect_error(lambda: HoleFill.parameterize(pts[:8], {0: (0, 0), 1: (1, 0), 2: (0, 1)}), "at least 10")
    fcharness.expect_error(lambda: HoleFill.parameterize(pts, boundary, method="bidgcnx"), "unknown parameterization method")
    fcharness.expect_error(lambda: HoleFill.parameterize(pts, {len(pts) + 3: (0, 0)}), "not a point of the cloud")
    twice = list(pts) + [pts[20]]
    fcharness.expect_error(lambda: HoleFill.parameterize(twice, boundary), "coincide")


fcharness.run(globals())
