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

StepwiseSolver::StepwiseSolver(const StepwiseProblem& p, const StepwiseOptions& o) : M_(p.M), steps_(p.steps), H_(p.H), n_(p.M.cols()) {
  const Eigen::Index n = n_;
  if (p.H.size() != p.steps.size()) throw Error("solveStepwise: step and objective counts disagree");
  std::vector<int> stepOf(n, -1);
  for (size_t s = 0; s < p.steps.size(); ++s)
    for (int i : p.steps[s]) {
      if (i < 0 || i >= n || stepOf[i] >= 0) throw Error("solveStepwise: the steps are not a partition of the variables");
      stepOf[i] = static_cast<int>(s);
    }
  if (std::count(stepOf.begin(), stepOf.end(), -1) > 0) throw Error("solveStepwise: a variable belongs to no step");
  std::vector<int> known;
  for (size_t s = 0; s < p.steps.size(); ++s) {
    Step f;
    f.J = p.steps[s];
    f.known = known;
    if (!f.J.empty()) {
      std::vector<int> later;
      for (Eigen::Index i = 0; i < n; ++i)
        if (stepOf[i] > static_cast<int>(s)) later.push_back(static_cast<int>(i));
      // Constraints left to this step and the later ones: M x = c projected where the later
      // steps' columns cannot reach.
      f.N = leftNullSpace(p.M(Eigen::all, later), o.rankTolerance);
      f.A = f.N.transpose() * p.M(Eigen::all, f.J);
      const Eigen::Index nj = static_cast<Eigen::Index>(f.J.size());
      f.Z = Eigen::MatrixXd::Identity(nj, nj);
      if (f.A.rows() > 0) {
        f.constrained = true;
        f.cod.setThreshold(o.rankTolerance);
        f.cod.compute(f.A);
        f.Z = leftNullSpace(f.A.transpose(), o.rankTolerance);
      }
      f.HJ = p.H[s](f.J, f.J);
      if (!known.empty()) f.HJknown = p.H[s](f.J, known);
      if (f.Z.cols() > 0) {
        Eigen::MatrixXd R = f.Z.transpose() * f.HJ * f.Z;
        const double scale = std::max(1.0, R.diagonal().cwiseAbs().maxCoeff());
        R.diagonal().array() += o.regularization * scale;
        f.reduced.compute(R);
      }
      known.insert(known.end(), f.J.begin(), f.J.end());
    }
    factored_.push_back(std::move(f));
  }
}

bool StepwiseSolver::matches(const StepwiseProblem& p) const {
  if (p.steps != steps_ || p.M.rows() != M_.rows() || p.M.cols() != M_.cols() || p.H.size() != H_.size()) return false;
  if (!(p.M.array() == M_.array()).all()) return false;
  for (size_t s = 0; s < H_.size(); ++s)
    if (p.H[s].rows() != H_[s].rows() || p.H[s].cols() != H_[s].cols() || !(p.H[s].array() == H_[s].array()).all()) return false;
  return true;
}

StepwiseResult StepwiseSolver::solve(const Eigen::MatrixXd& c, const std::vector<Eigen::MatrixXd>& g) const {
  const Eigen::Index columns = c.cols();
  if (c.rows() != M_.rows() || g.size() != factored_.size()) throw Error("solveStepwise: constraint, step and objective sizes disagree");
  StepwiseResult out;
  out.x = Eigen::MatrixXd::Zero(n_, columns);
  for (size_t s = 0; s < factored_.size(); ++s) {
    const Step& f = factored_[s];
    if (f.J.empty()) continue;
    const Eigen::Index nj = static_cast<Eigen::Index>(f.J.size());
    Eigen::MatrixXd x0 = Eigen::MatrixXd::Zero(nj, columns);
    if (f.constrained) {
      const Eigen::MatrixXd b = f.N.transpose() * (c - M_ * out.x);
      x0 = f.cod.solve(b);
      out.stepInfeasibility = std::max(out.stepInfeasibility, (f.A * x0 - b).cwiseAbs().maxCoeff());
    }
    // Minimise over x = x0 + Z y: the objective on this step, the solved variables fixed.
    Eigen::MatrixXd gJ = g[s](f.J, Eigen::all);
    if (!f.known.empty()) gJ -= f.HJknown * out.x(f.known, Eigen::all);
    if (f.Z.cols() > 0) x0 += f.Z * f.reduced.solve(f.Z.transpose() * (gJ - f.HJ * x0));
    out.x(f.J, Eigen::all) = x0;
  }
  if (M_.rows() > 0) out.constraintResidual = (M_ * out.x - c).cwiseAbs().maxCoeff();
  return out;
}

StepwiseResult solveStepwise(const StepwiseProblem& p, const StepwiseOptions& o) {
  if (p.c.rows() != p.M.rows() || p.H.size() != p.steps.size() || p.g.size() != p.steps.size())
    throw Error("solveStepwise: constraint, step and objective sizes disagree");
  return StepwiseSolver(p, o).solve(p.c, p.g);
}

}  // namespace holefill
