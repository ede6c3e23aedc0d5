#include "gnurbs/stepwise_least_squares.h"

#include <Eigen/QR>
#include <algorithm>

#include "geometry/error.h"

namespace holefill {

namespace {

// Orthonormal basis of the vectors y with yᵀ A = 0 (the left null space of A), by a
// rank-revealing QR; the identity when A has no columns.
Eigen::MatrixXd leftNullSpace(const Eigen::MatrixXd& A, double tolerance) {
  if (A.cols() == 0) return Eigen::MatrixXd::Identity(A.rows(), A.rows());
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  qr.setThreshold(tolerance);
  const Eigen::Index r = qr.rank();
  const Eigen::MatrixXd Q = qr.householderQ();
  return Q.rightCols(A.rows() - r);
}

}  // namespace

StepwiseResult solveStepwise(const StepwiseProblem& p, const StepwiseOptions& o) {
  const Eigen::Index n = p.M.cols(), columns = p.c.cols();
  if (p.c.rows() != p.M.rows() || p.H.size() != p.steps.size() || p.g.size() != p.steps.size())
    throw Error("solveStepwise: constraint, step and objective sizes disagree");
  std::vector<int> stepOf(n, -1);
  for (size_t s = 0; s < p.steps.size(); ++s)
    for (int i : p.steps[s]) {
      if (i < 0 || i >= n || stepOf[i] >= 0) throw Error("solveStepwise: the steps are not a partition of the variables");
      stepOf[i] = static_cast<int>(s);
    }
  if (std::count(stepOf.begin(), stepOf.end(), -1) > 0) throw Error("solveStepwise: a variable belongs to no step");

  StepwiseResult out;
  out.x = Eigen::MatrixXd::Zero(n, columns);
  std::vector<int> known;
  for (size_t s = 0; s < p.steps.size(); ++s) {
    const std::vector<int>& J = p.steps[s];
    if (J.empty()) continue;
    std::vector<int> later;
    for (Eigen::Index i = 0; i < n; ++i)
      if (stepOf[i] > static_cast<int>(s)) later.push_back(static_cast<int>(i));
    // Constraints left to this step and the later ones, with the solved variables moved right.
    const Eigen::MatrixXd rhs = p.c - p.M * out.x;
    const Eigen::MatrixXd N = leftNullSpace(p.M(Eigen::all, later), o.rankTolerance);
    const Eigen::MatrixXd A = N.transpose() * p.M(Eigen::all, J);
    const Eigen::MatrixXd b = N.transpose() * rhs;

    const Eigen::Index nj = static_cast<Eigen::Index>(J.size());
    Eigen::MatrixXd x0 = Eigen::MatrixXd::Zero(nj, columns), Z = Eigen::MatrixXd::Identity(nj, nj);
    if (A.rows() > 0) {
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
      cod.setThreshold(o.rankTolerance);
      x0 = cod.solve(b);
      out.stepInfeasibility = std::max(out.stepInfeasibility, (A * x0 - b).cwiseAbs().maxCoeff());
      Z = leftNullSpace(A.transpose(), o.rankTolerance);
    }
    // Minimise over x = x0 + Z y: the objective on this step, the solved variables fixed.
    const Eigen::MatrixXd HJ = p.H[s](J, J);
    Eigen::MatrixXd gJ = p.g[s](J, Eigen::all);
    if (!known.empty()) gJ -= p.H[s](J, known) * out.x(known, Eigen::all);
    if (Z.cols() > 0) {
      Eigen::MatrixXd R = Z.transpose() * HJ * Z;
      const double scale = std::max(1.0, R.diagonal().cwiseAbs().maxCoeff());
      R.diagonal().array() += o.regularization * scale;
      const Eigen::MatrixXd y = R.ldlt().solve(Z.transpose() * (gJ - HJ * x0));
      x0 += Z * y;
    }
    out.x(J, Eigen::all) = x0;
    known.insert(known.end(), J.begin(), J.end());
  }
  if (p.M.rows() > 0) out.constraintResidual = (p.M * out.x - p.c).cwiseAbs().maxCoeff();
  return out;
}

}  // namespace holefill
