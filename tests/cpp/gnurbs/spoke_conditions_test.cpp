#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "gnurbs/spoke_conditions.h"

using namespace holefill;

// b = 2 cos(2π/N) from the eigen-polyhedron: −1 at valence 3, 0 at 4 (the C² case).
TEST(SpokeConditions, EigenPolyhedronBIsTwiceTheCosineOfTheSectorAngle) {
  for (int n = 3; n <= 12; ++n) EXPECT_NEAR(eigenPolyhedronB(n), 2 * std::cos(2 * M_PI / n), 1e-14) << n;
  EXPECT_NEAR(eigenPolyhedronB(3), -1, 1e-14);
  EXPECT_NEAR(eigenPolyhedronB(4), 0, 1e-14);
  // A valence-3 EP with a regular far end: ρ(0) = −2 β'(0) = 6b, so r = −6 at b = −1.
  EXPECT_DOUBLE_EQ(valence3Rho(isolatedBetaSlope(eigenPolyhedronB(3))), -6);
}

// ρ's scale stays inside the window, measured per valence, where the planar polar cage's surface
// keeps its regular star's smallest angle (spoke_conditions.h).
TEST(SpokeConditions, ConnectionRhoLiesInsideEachValencesMeasuredWindow) {
  const struct { int n; double lo, hi; } windows[] = {{5, 0, 1},         {6, -6.5, -4.75}, {7, -6.5, -4},  {8, -6.5, -4.25},
                                                      {9, -6.5, -4.5},   {10, -6.25, -4.75}, {12, -5.55, -5}, {16, -5.7, -5.45},
                                                      {20, -1e9, -5.65}};
  for (const auto& w : windows) {
    EXPECT_GE(connectionRho(w.n), w.lo) << w.n;
    EXPECT_LE(connectionRho(w.n), w.hi) << w.n;
  }
}

// The rows are conditions on differences of coefficients (every term a derivative): a translated
// net satisfies them as the net does, so each row's coefficients sum to zero; and with β = ρ = 0
// (b = 0, r = 0: valence 4, C²) a flat net continued straight across the spoke satisfies all of them.
TEST(SpokeConditions, RowsAreTranslationFreeAndAStraightNetMeetsTheC2Case) {
  const auto a = [](int m, int n) { return n == 0 ? m : 11 + 2 * m + (n - 1); };
  const auto b = [](int m, int n) { return n == 0 ? m : 33 + 2 * m + (n - 1); };
  Eigen::MatrixX3d p(55, 3);
  for (int m = 0; m <= 10; ++m) {
    p.row(m) << m, 0, 0;
    for (int n = 1; n <= 2; ++n) {
      p.row(a(m, n)) << m, n, 0;
      p.row(b(m, n)) << m, -n, 0;
    }
  }
  SpokeConnection c;
  c.b0 = 0;
  c.r = 0;
  std::vector<GridCondition> rows;
  appendSpokeConditions(c, a, b, rows);
  ASSERT_GT(rows.size(), 10u);
  for (const GridCondition& row : rows) {
    double sum = 0;
    Eigen::RowVector3d residual = Eigen::RowVector3d::Zero();
    for (const auto& [id, coefficient] : row.terms) {
      sum += coefficient;
      residual += coefficient * p.row(id);
    }
    EXPECT_NEAR(sum, 0, 1e-9);
    EXPECT_LT(residual.norm(), 1e-9);
  }
  // Face B folded up out of the plane breaks G1 along the spoke: some row sees it.
  for (int m = 0; m <= 10; ++m)
    for (int n = 1; n <= 2; ++n) p(b(m, n), 2) = 0.5 * n;
  double worst = 0;
  for (const GridCondition& row : rows) {
    Eigen::RowVector3d residual = Eigen::RowVector3d::Zero();
    for (const auto& [id, coefficient] : row.terms) residual += coefficient * p.row(id);
    worst = std::max(worst, residual.norm());
  }
  EXPECT_GT(worst, 1e-2);
}
