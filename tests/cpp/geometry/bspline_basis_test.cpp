#include "geometry/bspline_basis.h"

#include <gtest/gtest.h>

#include <random>

using namespace holefill;

TEST(BsplineBasis, PartitionOfUnityOnNonUniformKnots) {
  const std::vector<double> U = {0, 0, 0, 0, 0.1, 0.45, 0.5, 0.9, 1, 1, 1, 1};
  for (int k = 0; k <= 200; ++k) {
    const double u = k / 200.0;
    const int s = findSpan(U, 3, u);
    const Eigen::MatrixXd d = basisDerivatives(U, 3, s, u, 3);
    EXPECT_NEAR(d.row(0).sum(), 1.0, 1e-14) << "u=" << u;
    for (int j = 0; j < 4; ++j) EXPECT_GE(d(0, j), -1e-15);
    // Derivatives of a partition of unity sum to zero.
    for (int o = 1; o <= 3; ++o) EXPECT_NEAR(d.row(o).sum(), 0.0, 1e-9);
  }
}

TEST(BsplineBasis, DerivativesMatchFiniteDifferences) {
  const std::vector<double> U = {0, 0, 0, 0, 0.2, 0.3, 0.7, 1, 1, 1, 1};
  const double h = 1e-6;
  for (double u : {0.05, 0.25, 0.33, 0.5, 0.95}) {
    const int s = findSpan(U, 3, u);
    const Eigen::MatrixXd d = basisDerivatives(U, 3, s, u, 3);
    const Eigen::MatrixXd dp = basisDerivatives(U, 3, s, u + h, 3), dm = basisDerivatives(U, 3, s, u - h, 3);
    for (int o = 0; o < 3; ++o)
      for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(d(o + 1, j), (dp(o, j) - dm(o, j)) / (2 * h), 1e-4 * (1 + std::abs(d(o + 1, j)))) << "order " << o + 1;
  }
}

TEST(BsplineBasis, FindSpanAtEnds) {
  const auto U = clampedUniformKnots(3, 4, 0.0, 2.0);
  EXPECT_EQ(findSpan(U, 3, 0.0), 3);
  EXPECT_EQ(findSpan(U, 3, 2.0), 6);
  EXPECT_EQ(findSpan(U, 3, 0.5), 4);
  EXPECT_EQ(breakpoints(U).size(), 5u);
}

TEST(BsplineBasis, GaussLegendreIntegratesPolynomialsExactly) {
  std::vector<double> x, w;
  for (int n = 1; n <= 8; ++n) {
    gaussLegendre(n, x, w);
    for (int deg = 0; deg <= 2 * n - 1; ++deg) {
      double s = 0;
      for (int i = 0; i < n; ++i) s += w[i] * std::pow(x[i], deg);
      const double exact = deg % 2 ? 0.0 : 2.0 / (deg + 1);
      EXPECT_NEAR(s, exact, 1e-13) << "n=" << n << " deg=" << deg;
    }
  }
}
