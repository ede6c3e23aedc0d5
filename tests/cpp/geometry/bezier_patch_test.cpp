#include "geometry/bezier_patch.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/error.h"

using namespace holefill;

TEST(BezierPatch, ElevationAndSplittingKeepTheSurface) {
  Eigen::MatrixX3d p(16, 3);
  for (int i = 0; i < 16; ++i) p.row(i) << i / 4, i % 4, std::sin(1.3 * i);
  const BSplineSurface s = bezierPatch(3, 3, p);
  const BSplineSurface e = elevateBezier(s, 5, 5);
  const auto parts = splitBezier(e, 0.5, 0.5);
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
    for (double v : {0.0, 0.31, 0.5, 0.9, 1.0}) {
      EXPECT_LT((e.point(u, v) - s.point(u, v)).norm(), 1e-13);
      const int k = (v > 0.5 ? 2 : 0) + (u > 0.5 ? 1 : 0);
      const double su = u > 0.5 ? 2 * u - 1 : 2 * u, sv = v > 0.5 ? 2 * v - 1 : 2 * v;
      EXPECT_LT((parts[k].point(su, sv) - s.point(u, v)).norm(), 1e-13);
    }
  EXPECT_THROW(elevateBezier(s, 2, 3), Error);
}
