#include "fill/fairness_energy.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "geometry/bspline_basis.h"

using namespace holefill;

TEST(FairnessEnergy, SymmetricPositiveSemiDefinite) {
  const auto U = std::vector<double>{0, 0, 0, 0, 0.2, 0.5, 0.6, 1, 1, 1, 1};
  const auto V = clampedUniformKnots(3, 3, 0.0, 2.0);
  const Eigen::MatrixXd A = Eigen::MatrixXd(fairnessMatrix(3, U, 3, V, FairnessWeights{}));
  EXPECT_LT((A - A.transpose()).norm(), 1e-10 * A.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A);
  EXPECT_GT(es.eigenvalues().minCoeff(), -1e-9 * es.eigenvalues().maxCoeff());
  // Null space: the bilinear functions 1, u, v and uv have no bending energy (|S_uv|² counts, so uv does not).
  EXPECT_GE((es.eigenvalues().array() < 1e-9 * es.eigenvalues().maxCoeff()).count(), 3);
}

TEST(FairnessEnergy, ZeroOnPlanesPositiveOnCurvedSurfaces) {
  const auto U = clampedUniformKnots(3, 4, 0.0, 1.0), V = clampedUniformKnots(3, 5, 0.0, 1.0);
  const int nu = 7, nv = 8;
  const Eigen::SparseMatrix<double> A = fairnessMatrix(3, U, 3, V, FairnessWeights{});
  // Greville abscissae reproduce linear functions: a plane z = 2u - 3v + 1 has poles z_ij = 2g_i - 3g_j + 1.
  auto greville = [](const std::vector<double>& K, int i) { return (K[i + 1] + K[i + 2] + K[i + 3]) / 3.0; };
  // Blossom of u²: the B-spline coefficients that reproduce it exactly.
  auto square = [](const std::vector<double>& K, int i) {
    return (K[i + 1] * K[i + 2] + K[i + 2] * K[i + 3] + K[i + 1] * K[i + 3]) / 3.0;
  };
  Eigen::VectorXd plane(nu * nv), bowl(nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = greville(U, i), v = greville(V, j);
      plane(i * nv + j) = 2 * u - 3 * v + 1;
      bowl(i * nv + j) = square(U, i) + square(V, j);
    }
  EXPECT_NEAR(plane.dot(A * plane), 0.0, 1e-9);
  // For z = u² + v² the bending energy is 0.3 * (4 + 4) over the unit square; rate of bending is 0.
  EXPECT_NEAR(bowl.dot(A * bowl), 0.3 * 8.0, 1e-9);
}
