#include "geometry/spd_condition.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace holefill {

double log10Condition(const Eigen::SparseMatrix<double>& N, int exactUpTo) {
  const double infinite = std::numeric_limits<double>::infinity();
  const Eigen::Index n = N.rows();
  if (n == 0) return infinite;
  double lo = 0, hi = 0;
  if (n <= exactUpTo) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(N), Eigen::EigenvaluesOnly);
    lo = eig.eigenvalues().minCoeff(), hi = eig.eigenvalues().maxCoeff();
  } else {
    Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0).normalized();
    for (int it = 0; it < 60; ++it) {
      x = N * x;
      hi = x.norm();
      if (!(hi > 0)) return infinite;
      x /= hi;
    }
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(N);
    if (ldlt.info() != Eigen::Success) return infinite;
    Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(n, 2.0, 1.0).normalized();
    for (int it = 0; it < 60; ++it) {
      y = ldlt.solve(y);
      const double g = y.norm();
      if (!(g > 0 && std::isfinite(g))) return infinite;
      y /= g;
    }
    lo = y.dot(N * y);
  }
  return lo > 1e-15 * hi ? std::log10(hi / lo) : infinite;
}

}  // namespace holefill
