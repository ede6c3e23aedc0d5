#include "geometry/bspline_surface.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/bspline_basis.h"

using namespace holefill;

namespace {
BSplineSurface randomSurface(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  BSplineSurface s;
  s.knotsU = {0, 0, 0, 0, 0.3, 0.5, 1, 1, 1, 1};
  s.knotsV = {0, 0, 0, 0, 0.6, 1, 1, 1, 1};
  s.poles.resize(s.numU() * s.numV(), 3);
  for (int i = 0; i < s.numU(); ++i)
    for (int j = 0; j < s.numV(); ++j) s.poles.row(s.index(i, j)) << i, j, d(rng);
  return s;
}
}  // namespace

TEST(BsplineSurface, KnotInsertionPreservesTheSurface) {
  const BSplineSurface s = randomSurface(1);
  BSplineSurface r = insertKnot(insertKnot(insertKnot(s, 0, 0.3), 1, 0.17), 0, 0.77);
  EXPECT_EQ(r.numU(), s.numU() + 2);
  EXPECT_EQ(r.numV(), s.numV() + 1);
  for (int a = 0; a <= 20; ++a)
    for (int b = 0; b <= 20; ++b) {
      const double u = a / 20.0, v = b / 20.0;
      EXPECT_LT((s.point(u, v) - r.point(u, v)).norm(), 1e-13);
      EXPECT_LT((s.derivatives(u, v, 2)[1][1] - r.derivatives(u, v, 2)[1][1]).norm(), 1e-10);
    }
}

TEST(BsplineSurface, DerivativesMatchFiniteDifferences) {
  const BSplineSurface s = randomSurface(2);
  const double h = 1e-6;
  for (double u : {0.1, 0.42, 0.8})
    for (double v : {0.2, 0.55, 0.9}) {
      const auto d = s.derivatives(u, v, 3);
      const auto du = s.derivatives(u + h, v, 3), dum = s.derivatives(u - h, v, 3);
      const auto dv = s.derivatives(u, v + h, 3), dvm = s.derivatives(u, v - h, 3);
      EXPECT_LT((d[1][0] - (du[0][0] - dum[0][0]) / (2 * h)).norm(), 1e-6);
      EXPECT_LT((d[0][1] - (dv[0][0] - dvm[0][0]) / (2 * h)).norm(), 1e-6);
      EXPECT_LT((d[2][0] - (du[1][0] - dum[1][0]) / (2 * h)).norm(), 1e-4);
      EXPECT_LT((d[1][1] - (dv[1][0] - dvm[1][0]) / (2 * h)).norm(), 1e-4);
      EXPECT_LT((d[2][1] - (dv[2][0] - dvm[2][0]) / (2 * h)).norm(), 1e-3);
    }
}

TEST(BsplineSurface, MatchesOcctEvaluation) {
  const BSplineSurface s = randomSurface(3);
  const Handle(Geom_BSplineSurface) g = toOcct(s);
  for (double u : {0.0, 0.33, 0.71, 1.0})
    for (double v : {0.0, 0.5, 0.93, 1.0}) {
      const gp_Pnt p = g->Value(u, v);
      EXPECT_LT((s.point(u, v) - Eigen::Vector3d(p.X(), p.Y(), p.Z())).norm(), 1e-13);
    }
  const BSplineSurface back = fromOcct(g);
  EXPECT_EQ(back.knotsU, s.knotsU);
  EXPECT_LT((back.poles - s.poles).norm(), 1e-15);
}
