#include <gtest/gtest.h>

#include <cmath>

#include "fitting/free_flattening.h"
#include "geometry/error.h"
#include "test_regions.h"

using namespace holefill;

namespace {

double edgeLengthError(const TriangleMesh& m, const Eigen::MatrixX2d& uv) {
  double worst = 0;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles(t, k), b = m.triangles(t, (k + 1) % 3);
      const double l3 = (m.vertices.row(a) - m.vertices.row(b)).norm(), l2 = (uv.row(a) - uv.row(b)).norm();
      worst = std::max(worst, std::abs(l2 - l3) / l3);
    }
  return worst;
}

int negativeTriangles(const TriangleMesh& m, const Eigen::MatrixX2d& uv) {
  int n = 0;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) {
    const Eigen::Vector2d a = uv.row(m.triangles(t, 1)) - uv.row(m.triangles(t, 0)), b = uv.row(m.triangles(t, 2)) - uv.row(m.triangles(t, 0));
    n += a.x() * b.y() - a.y() * b.x() <= 0;
  }
  return n;
}

}  // namespace

// A developable region flattens without distortion: a U-slot rolled onto a half cylinder (its
// slot's walls and an L's inner corner are what a labeled map presses onto a line) and a ring
// with an inner hole on a cone-like roll, every edge keeping its length, no triangle turned.
TEST(FreeFlattening, ADevelopableRegionFlattensIsometrically) {
  Eigen::MatrixX2d truth;
  const TriangleMesh slot = testregions::gridRegion(
      30, 30, 1.0 / 30, [](double x, double y) { return !(x > 0.35 && x < 0.65 && y > 0.3); },
      [](double x, double y) { return Eigen::Vector3d(std::cos(M_PI * x), std::sin(M_PI * x), 2 * y); }, truth);
  const FreeFlattening f = flattenFree(slot);
  EXPECT_LT(edgeLengthError(slot, f.uv), 1e-6);
  EXPECT_EQ(f.flippedTriangles, 0);
  EXPECT_EQ(negativeTriangles(slot, f.uv), 0);  // anticlockwise stays anticlockwise
  EXPECT_LT(f.arapEnergy, 1e-10);
  const TriangleMesh ring = testregions::gridRegion(
      24, 24, 1.0 / 24, [](double x, double y) { return std::hypot(x - 0.5, y - 0.5) > 0.2; },
      [](double x, double y) { return Eigen::Vector3d(x, 0.5 * std::cos(2 * y), 0.5 * std::sin(2 * y)); }, truth);
  const FreeFlattening g = flattenFree(ring);
  EXPECT_LT(edgeLengthError(ring, g.uv), 1e-6);
  EXPECT_EQ(g.flippedTriangles, 0);
}

// A doubly curved region cannot flatten without distortion; the map spreads it and folds nothing.
// Measured on this cap of a unit sphere (half its radius across): ARAP energy 1.1e-5, edges within 0.9%.
TEST(FreeFlattening, ACurvedRegionFlattensWithoutFolds) {
  Eigen::MatrixX2d truth;
  const TriangleMesh cap = testregions::gridRegion(
      20, 20, 0.05, [](double x, double y) { return std::hypot(x - 0.5, y - 0.5) < 0.5; },
      [](double x, double y) {
        const double a = 0.5 * (x - 0.5), b = 0.5 * (y - 0.5);
        return Eigen::Vector3d(a, b, std::sqrt(1 - a * a - b * b));
      },
      truth);
  const FreeFlattening f = flattenFree(cap);
  EXPECT_EQ(f.flippedTriangles, 0);
  EXPECT_EQ(negativeTriangles(cap, f.uv), 0);
  EXPECT_GT(f.arapEnergy, 0);
  EXPECT_LT(f.arapEnergy, 1e-4);
  EXPECT_LT(edgeLengthError(cap, f.uv), 0.02);
  std::printf("sphere cap: ARAP energy %.3g, worst edge length error %.3g\n", f.arapEnergy, edgeLengthError(cap, f.uv));
}

TEST(FreeFlattening, RefusesWhatCannotBeFlattened) {
  TriangleMesh one;
  one.vertices.resize(3, 3);
  one.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  one.triangles.resize(1, 3);
  one.triangles << 0, 1, 2;
  EXPECT_THROW(flattenFree(one), Error);
  TriangleMesh tetra;
  tetra.vertices.resize(4, 3);
  tetra.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  tetra.triangles.resize(4, 3);
  tetra.triangles << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
  EXPECT_THROW(flattenFree(tetra), Error);  // closed: no boundary
  TriangleMesh unused = tetra;
  unused.triangles.conservativeResize(2, 3);
  unused.vertices.conservativeResize(5, 3);
  unused.vertices.row(4) << 5, 5, 5;
  EXPECT_THROW(flattenFree(unused), Error);
  TriangleMesh nan = tetra;
  nan.triangles.conservativeResize(2, 3);
  nan.vertices(3, 2) = std::nan("");
  EXPECT_THROW(flattenFree(nan), Error);
}

// A U-slot of the corpus's saddle: flattened from the conformal start, one leg's boundary runs
// over the other's across the slot although no triangle folds (ARAP is blind to it). Started from
// a one-to-one map (here the region's own parameters; relaxLabels gives the labeled map), every
// step that would make the boundary cross is stepped back, and the map stays one to one.
TEST(FreeFlattening, StartedFromAOneToOneMapTheBoundaryNeverOverlaps) {
  Eigen::MatrixX2d truth;
  const TriangleMesh slot = testregions::gridRegion(
      50, 50, 1.0 / 50, [](double x, double y) { return !(x > 0.4 && x < 0.6 && y > 0.3); },
      [](double u, double v) { return Eigen::Vector3d(10 * u, 10 * v, 8 * ((u - .5) * (u - .5) - (v - .5) * (v - .5))); }, truth);
  const FreeFlattening conformal = flattenFree(slot);
  EXPECT_TRUE(conformal.boundaryCrosses);
  EXPECT_EQ(conformal.flippedTriangles, 0);
  FreeFlatteningOptions o;
  o.start = 10 * truth;
  const FreeFlattening f = flattenFree(slot, o);
  EXPECT_FALSE(f.boundaryCrosses);
  EXPECT_EQ(f.flippedTriangles, 0);
  EXPECT_LT(f.arapEnergy, 1e-3);
  std::printf("ARAP energy: conformal start %.3g (crossing), one-to-one start %.3g\n", conformal.arapEnergy, f.arapEnergy);
  o.start = Eigen::MatrixX2d::Zero(3, 2);
  EXPECT_THROW(flattenFree(slot, o), Error);
}

// The labeled map of a region read from its other side (its loop clockwise seen from its normal)
// runs the other way round against the region's triangles: as a start it is mirrored, and the
// restart keeps the boundary simple as from any one-to-one start (before, every triangle counted
// as a fold and the restart never began: bspline_uslot_clean_cw of the corpus).
TEST(FreeFlattening, AStartThatRunsTheOtherWayRoundIsMirrored) {
  Eigen::MatrixX2d truth;
  const TriangleMesh slot = testregions::gridRegion(
      50, 50, 1.0 / 50, [](double x, double y) { return !(x > 0.4 && x < 0.6 && y > 0.3); },
      [](double u, double v) { return Eigen::Vector3d(10 * u, 10 * v, 8 * ((u - .5) * (u - .5) - (v - .5) * (v - .5))); }, truth);
  FreeFlatteningOptions o;
  o.start = 10 * truth;
  const FreeFlattening g = flattenFree(slot, o);
  o.start.col(1) = -o.start.col(1);  // seen from the other side
  const FreeFlattening f = flattenFree(slot, o);
  EXPECT_EQ(f.flippedTriangles, 0);
  EXPECT_FALSE(f.boundaryCrosses);
  // The same map as from the start seen from this side, up to a rigid motion (every vertex as
  // far from vertex 0); started mirrored, ARAP wandered elsewhere (its rotations cannot undo a
  // reflection): up to 0.24 apart, the region being 10 wide.
  double apart = 0;
  for (Eigen::Index v = 1; v < f.uv.rows(); ++v)
    apart = std::max(apart, std::abs((f.uv.row(v) - f.uv.row(0)).norm() - (g.uv.row(v) - g.uv.row(0)).norm()));
  EXPECT_LT(apart, 1e-6);
  EXPECT_NEAR(f.arapEnergy, g.arapEnergy, 1e-9);
  std::printf("largest difference in distance to vertex 0 from the two starts: %.2e\n", apart);
}
