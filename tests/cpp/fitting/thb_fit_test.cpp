#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "brep/thb_faces.h"
#include "fitting/thb_fit.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Face.hxx>
#include "geometry/bspline_basis.h"
#include "geometry/error.h"

using namespace holefill;

namespace {

// A bicubic Bézier patch, sampled at random parameters.
BSplineSurface patch() {
  BSplineSurface s;
  s.knotsU = clampedUniformKnots(3, 1, 0, 1);
  s.knotsV = clampedUniformKnots(3, 1, 0, 1);
  s.poles.resize(16, 3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s.poles.row(i * 4 + j) << i / 3.0, j / 3.0, 0.4 * std::sin(1.7 * i + 0.9 * j) - 0.1 * i * j;
  return s;
}

}  // namespace

TEST(ThbFit, ACloudFromABicubicPatchConvergesWithParameterCorrection) {
  const BSplineSurface s = patch();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  const int n = 600;
  Eigen::MatrixX3d pts(n, 3);
  Eigen::MatrixX2d uv(n, 2);
  for (int k = 0; k < n; ++k) {
    const double a = U(rng), b = U(rng);
    pts.row(k) = s.point(a, b).transpose();
    // Start from distorted parameters (still in the square, corners kept).
    uv.row(k) << a + 0.06 * std::sin(M_PI * a) * std::sin(M_PI * b), b - 0.05 * std::sin(M_PI * a) * std::sin(2 * M_PI * b);
  }
  ThbFitOptions o;
  o.baseCells = 3;
  o.relativeTolerance = 1e-12;  // keep correcting
  o.smoothing = 1e-12;
  o.maxIterations = 40;
  o.maxLevels = 1;  // the patch is in the base space: what is left to gain is in the parameters
  const ThbFitResult with = fitThb(pts, uv, o);
  o.correctParameters = false;
  o.maxIterations = 1;
  const ThbFitResult without = fitThb(pts, uv, o);
  for (const auto& h : with.history) std::printf("  dof %d: mse %.2e, max %.2e, refined %d, corrected %d\n", h.dof, h.mse, h.maxError, h.refinedCells, h.correctedParameters);
  std::printf("bicubic cloud: MSE %.2e with parameter correction (%zu iterations), %.2e without\n", with.history.back().mse, with.history.size(),
              without.history.back().mse);
  EXPECT_LT(with.history.back().mse, 1e-8);
  EXPECT_GT(without.history.back().mse, 10 * with.history.back().mse);
  EXPECT_TRUE(with.surface.poles.allFinite());
}

TEST(ThbFit, RefinesWhereTheErrorIsAndRefusesBadInput) {
  // A ridge along u = 0.7 needs finer cells there only.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> U(0, 1);
  const int n = 3000;
  Eigen::MatrixX3d pts(n, 3);
  Eigen::MatrixX2d uv(n, 2);
  for (int k = 0; k < n; ++k) {
    const double a = U(rng), b = U(rng);
    pts.row(k) << a, b, 0.1 * std::exp(-200 * (a - 0.7) * (a - 0.7));
    uv.row(k) << a, b;
  }
  ThbFitOptions o;
  o.relativeTolerance = 1e-3;
  o.correctParameters = false;
  const ThbFitResult r = fitThb(pts, uv, o);
  const int uniformFinest = (r.space.cellsU(r.space.levels() - 1) + 3) * (r.space.cellsV(r.space.levels() - 1) + 3);
  std::printf("ridge: %d levels, %d THB functions (a uniform space at the finest level: %d), max error %.2e, met %d\n", r.space.levels(),
              r.history.back().dof, uniformFinest, r.history.back().maxError, r.metTolerance);
  EXPECT_GT(r.space.levels(), 1);
  EXPECT_LT(r.history.back().dof, 0.6 * uniformFinest);  // measured 655 of 1225
  EXPECT_LT(r.history.back().maxError, r.history.front().maxError);
  // The errors reported per point are those of the last iteration, the leaf cells tile the square.
  EXPECT_NEAR(r.errors.maxCoeff(), r.history.back().maxError, 1e-15);
  double area = 0;
  for (const auto& [l, i, j] : r.space.leafCells()) area += 1.0 / (r.space.cellsU(l) * r.space.cellsV(l));
  EXPECT_NEAR(area, 1.0, 1e-12);
  // Exported as one face per cell: one shell, the same surface (area of the single face).
  const TopoDS_Shape faces = thbCellFaces(r.space, r.surface);
  int count = 0;
  for (TopExp_Explorer e(faces, TopAbs_FACE); e.More(); e.Next()) ++count;
  EXPECT_EQ(count, static_cast<int>(r.space.leafCells().size()));
  GProp_GProps a, b;
  BRepGProp::SurfaceProperties(faces, a, 1e-9);  // adaptive integration: the default order differs on small and large faces
  BRepGProp::SurfaceProperties(BRepBuilderAPI_MakeFace(toOcct(r.surface), 1e-7).Face(), b, 1e-9);
  EXPECT_NEAR(a.Mass(), b.Mass(), 1e-6 * b.Mass());
  Eigen::MatrixX2d bad = uv;
  bad(3, 0) = 1.5;
  EXPECT_THROW(fitThb(pts, bad, o), Error);
  EXPECT_THROW(fitThb(pts.topRows(5), uv.topRows(5), o), Error);
}
