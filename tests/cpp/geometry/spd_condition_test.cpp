#include "geometry/spd_condition.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holefill {
namespace {

// A 1-D Laplacian plus a shift: eigenvalues 2 + s − 2 cos(kπ/(n+1)) are known in closed form.
Eigen::SparseMatrix<double> shiftedLaplacian(int n, double s) {
  Eigen::SparseMatrix<double> A(n, n);
  for (int i = 0; i < n; ++i) {
    A.insert(i, i) = 2 + s;
    if (i > 0) A.insert(i, i - 1) = -1;
    if (i + 1 < n) A.insert(i, i + 1) = -1;
  }
  return A;
}

double exactLog10(int n, double s) {
  const double lo = 2 + s - 2 * std::cos(M_PI / (n + 1)), hi = 2 + s - 2 * std::cos(n * M_PI / (n + 1));
  return std::log10(hi / lo);
}

TEST(SpdCondition, SmallMatrixIsExact) {
  EXPECT_NEAR(log10Condition(shiftedLaplacian(50, 0.01)), exactLog10(50, 0.01), 1e-9);
}

TEST(SpdCondition, LargeMatrixEstimateAgreesWithTheExactValue) {
  // 1,000 unknowns: estimated, within what log10 shows.
  const double e = log10Condition(shiftedLaplacian(1000, 0.01));
  EXPECT_NEAR(e, exactLog10(1000, 0.01), 0.02);
  // The same matrix forced through the dense path agrees.
  EXPECT_NEAR(log10Condition(shiftedLaplacian(1000, 0.01), 2000), e, 0.02);
}

TEST(SpdCondition, SingularMatrixIsInfinite) {
  // The Neumann Laplacian: constants are in its kernel. Estimated (600) and exact (100).
  for (int n : {600, 100}) {
    Eigen::SparseMatrix<double> A = shiftedLaplacian(n, 0);
    A.coeffRef(0, 0) = 1, A.coeffRef(n - 1, n - 1) = 1;
    EXPECT_TRUE(std::isinf(log10Condition(A))) << n;
  }
}

}  // namespace
}  // namespace holefill
