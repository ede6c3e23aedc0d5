#include <gtest/gtest.h>

#include <cmath>

#include "geometry/bspline_basis.h"
#include "geometry/polygon2d.h"
#include "geometry/surface_projection.h"

using namespace holefill;

namespace {
// A curved bicubic patch over [0,1]^2 with poles on z = sin-like bumps.
BSplineSurface patch() {
  BSplineSurface s;
  s.knotsU = s.knotsV = clampedUniformKnots(3, 4, 0.0, 1.0);
  s.poles.resize(s.numU() * s.numV(), 3);
  for (int i = 0; i < s.numU(); ++i)
    for (int j = 0; j < s.numV(); ++j)
      s.poles.row(s.index(i, j)) << i / 6.0, j / 6.0, 0.3 * std::sin(1.3 * i) * std::cos(0.9 * j);
  return s;
}
}  // namespace

TEST(SurfaceProjection, RecoversTheParametersOfPointsOnTheSurface) {
  const BSplineSurface s = patch();
  std::vector<Eigen::Vector2d> truth;
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 200; ++k) {
    const double t = 2 * M_PI * k / 200;
    truth.emplace_back(0.5 + 0.35 * std::cos(t), 0.5 + 0.3 * std::sin(t) + 0.05 * std::sin(5 * t));
    pts.push_back(s.point(truth.back().x(), truth.back().y()));
  }
  const ProjectionResult r = projectSequence(s, pts);
  double worst = 0;
  for (size_t k = 0; k < pts.size(); ++k) worst = std::max(worst, (r.uv[k] - truth[k]).norm());
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(r.gridSearches, 1);  // continuation seeded every point after the first
}

TEST(SurfaceProjection, RepeatedCornerPointsGetIdenticalParametersSoThePcurveStaysSimple) {
  const BSplineSurface s = patch();
  std::vector<Eigen::Vector3d> pts;
  // A sharp triangle whose corners are sampled twice (end of one edge, start of the next), the
  // second copy a round-off away, and the loop closed on its start.
  const Eigen::Vector2d c[3] = {{0.2, 0.2}, {0.8, 0.25}, {0.5, 0.3}};
  for (int e = 0; e < 3; ++e)
    for (int k = 0; k <= 40; ++k) {
      const Eigen::Vector2d q = c[e] + (c[(e + 1) % 3] - c[e]) * (k / 40.0);
      pts.push_back(s.point(q.x(), q.y()) + Eigen::Vector3d::Constant(k == 0 ? 1e-13 : 0.0));
    }
  const ProjectionResult r = projectSequence(s, pts);
  for (size_t k = 1; k < pts.size(); ++k)
    if ((pts[k] - pts[k - 1]).norm() < 1e-9) EXPECT_EQ(r.uv[k], r.uv[k - 1]);
  EXPECT_EQ(r.uv.back(), r.uv.front());
  EXPECT_FALSE(selfIntersects(Polygon2(r.uv.begin(), r.uv.end())));
}

TEST(SurfaceProjection, ExtensionLetsPointsBeyondTheSurfaceKeepTheirOwnParameters) {
  const BSplineSurface s = patch();
  // Points of the end spans' polynomial continuation beyond u = 1.
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 10; ++k) pts.push_back(s.point(1.0, 0.5) + Eigen::Vector3d(0.01 * k, 0, 0));
  ProjectionOptions o;
  const ProjectionResult clamped = projectSequence(s, pts, o);
  o.extension = 0.25;
  const ProjectionResult extended = projectSequence(s, pts, o);
  EXPECT_NEAR(clamped.uv.back().x(), 1.0, 1e-12);
  EXPECT_GT(extended.uv.back().x(), 1.02);  // 0.09 beyond the edge, where |S_u| is about 2
}
