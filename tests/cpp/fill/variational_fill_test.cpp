#include "fill/variational_fill.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/error.h"

using namespace holefill;

namespace {

// A height field z = h(x, y) seen through the domain (x = u, y = v): boundary samples on an ellipse
// inside [0,a]x[0,b], counter-clockwise, with the field's normals and the inward cross direction.
struct Field {
  double cx, cy, cxx, cyy, cxy;
  double z(double x, double y) const { return cx * x + cy * y + cxx * x * x + cyy * y * y + cxy * x * y; }
  Eigen::Vector3d normal(double x, double y) const {
    return Eigen::Vector3d(-(cx + 2 * cxx * x + cxy * y), -(cy + 2 * cyy * y + cxy * x), 1.0).normalized();
  }
};

FillConstraints ellipse(const Field& f, double a, double b, int n, bool swapped) {
  FillConstraints c;
  for (int k = 0; k < n; ++k) {
    // Swapped: the mirror image (u,v) -> (v,u), walked backwards so that it stays counter-clockwise.
    const double t = 2 * M_PI * (swapped ? n - k : k) / n;
    const double x = 0.5 * a + 0.45 * a * std::cos(t), y = 0.5 * b + 0.45 * b * std::sin(t);
    const Eigen::Vector3d p(x, y, f.z(x, y)), nrm = f.normal(x, y);
    const Eigen::Vector3d inward = (Eigen::Vector3d(0.5 * a - x, 0.5 * b - y, 0) - nrm.dot(Eigen::Vector3d(0.5 * a - x, 0.5 * b - y, 0)) * nrm).normalized();
    auto swap = [&](const Eigen::Vector3d& v) { return swapped ? Eigen::Vector3d(v.y(), v.x(), v.z()) : v; };
    c.uv.push_back(swapped ? Eigen::Vector2d(y, x) : Eigen::Vector2d(x, y));
    c.point.push_back(swap(p));
    c.normal.push_back(swap(nrm));
    c.across.push_back(swap(inward));
    c.curvature.push_back(0.0);
    c.weight.push_back(1.0);
    c.normalValid.push_back(true);
    c.edge.push_back(0);
  }
  return c;
}

}  // namespace

TEST(VariationalFill, PlanarBoundaryGivesAPlane) {
  const FillConstraints c = ellipse(Field{0, 0, 0, 0, 0}, 2.0, 1.0, 120, false);
  const VariationalFillResult r = solveVariationalFill(c, 0, 2, 0, 1, {}, {});
  ASSERT_TRUE(r.toleranceMet);
  EXPECT_LT(r.surface.poles.col(2).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(VariationalFill, PassesThroughInteriorPoints) {
  // A flat G1 boundary with two points above and below it: the surface goes through both to the
  // G0 tolerance (a plane would miss them by 0.1), and still meets the boundary.
  FillConstraints c = ellipse(Field{0, 0, 0, 0, 0}, 2.0, 1.0, 120, false);
  c.passUV = {Eigen::Vector2d(1.0, 0.5), Eigen::Vector2d(0.6, 0.4)};
  c.passXYZ = {Eigen::Vector3d(1.0, 0.5, 0.1), Eigen::Vector3d(0.6, 0.4, -0.05)};
  const VariationalFillResult r = solveVariationalFill(c, 0, 2, 0, 1, {}, {});
  EXPECT_TRUE(r.toleranceMet);
  EXPECT_LE(r.passError, 1e-6);
  for (size_t p = 0; p < c.passUV.size(); ++p)
    EXPECT_LT((r.surface.point(c.passUV[p].x(), c.passUV[p].y()) - c.passXYZ[p]).norm(), 1e-6) << p;
  EXPECT_LE(r.g0, 1e-6);
  EXPECT_LE(r.g1, 1e-3);
  c.passXYZ.pop_back();
  EXPECT_THROW(solveVariationalFill(c, 0, 2, 0, 1, {}, {}), Error);
}

TEST(VariationalFill, MeetsG0AndG1OnACurvedBoundary) {
  const Field f{0.2, -0.1, 0.3, -0.2, 0.15};
  const FillConstraints c = ellipse(f, 1.0, 1.0, 200, false);
  const VariationalFillResult r = solveVariationalFill(c, 0, 1, 0, 1, {}, {});
  EXPECT_TRUE(r.toleranceMet);
  EXPECT_LE(r.g0, 1e-6);
  EXPECT_LE(r.g1, 1e-3);
  for (size_t k = 0; k < c.size(); k += 17) EXPECT_LT((r.surface.point(c.uv[k].x(), c.uv[k].y()) - c.point[k]).norm(), 1e-6);
  // Inside, the fairest surface through the quadric's boundary and normals is not the quadric (the
  // quadric bends), but it stays near it: 4.2e-3 at the centre, where the field rises 0.11.
  EXPECT_NEAR(r.surface.point(0.5, 0.5).z(), f.z(0.5, 0.5), 1e-2);
}

// The unknowns are eliminated in a band along the grid's shorter side, whichever it is: a long
// domain and its mirror image (u and v swapped, x and y swapped) give the same surface mirrored.
TEST(VariationalFill, SameFillWhicheverSideOfTheGridIsLonger) {
  const Field f{0.1, 0.05, 0.2, -0.3, 0.1};
  const FillConstraints c = ellipse(f, 3.0, 1.0, 240, false), m = ellipse(f, 3.0, 1.0, 240, true);
  const VariationalFillResult r = solveVariationalFill(c, 0, 3, 0, 1, {}, {});
  const VariationalFillResult s = solveVariationalFill(m, 0, 1, 0, 3, {}, {});
  ASSERT_EQ(r.surface.numU(), s.surface.numV());
  ASSERT_EQ(r.surface.numV(), s.surface.numU());
  ASSERT_NE(r.surface.numU(), r.surface.numV());
  EXPECT_TRUE(r.toleranceMet);
  EXPECT_TRUE(s.toleranceMet);
  double worst = 0;
  for (int i = 0; i < r.surface.numU(); ++i)
    for (int j = 0; j < r.surface.numV(); ++j) {
      const Eigen::Vector3d p = r.surface.poles.row(i * r.surface.numV() + j);
      const Eigen::Vector3d q = s.surface.poles.row(j * s.surface.numV() + i);
      worst = std::max(worst, (p - Eigen::Vector3d(q.y(), q.x(), q.z())).norm());
    }
  EXPECT_LT(worst, 1e-6);  // the solver's own G0 tolerance: its rounds stop within it
}

TEST(VariationalFill, RefusesNonFiniteSamples) {
  FillConstraints c = ellipse(Field{0, 0, 0, 0, 0}, 1.0, 1.0, 40, false);
  c.point[7].x() = std::nan("");
  EXPECT_THROW(solveVariationalFill(c, 0, 1, 0, 1, {}, {}), Error);
}
