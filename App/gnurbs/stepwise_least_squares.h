// Equality-constrained least squares solved in steps (g2-gnurbs.md sec. 4.1): the unknowns are
// split into ordered groups; each group is fixed by its own quadratic objective, the earlier
// groups held at their solved values, under the constraints it must satisfy so that the later
// groups can still meet theirs. Those are the projections of M x = c onto the left null space
// of the later groups' columns, so the stepwise solution satisfies every constraint exactly
// whenever the whole system is consistent (the paper derives them by hand, eqs. (12)-(15) and
// (18)-(20), for its two spoke cases; here they follow from the system). Each step is solved
// by the null-space method on a rank-revealing QR, so redundant constraints are harmless.
// The right-hand sides have several columns (x, y, z) sharing the matrices.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace holefill {

struct StepwiseProblem {
  Eigen::MatrixXd M, c;                  // constraints M x = c (c: rows × columns of x)
  std::vector<std::vector<int>> steps;   // variable indices per step, in solving order; a partition
  // Per step, minimise ½ xᵀ H x − gᵀ x over that step's variables with the earlier ones fixed;
  // H (n×n) and g (n × columns) are over all n variables; entries on later steps are ignored.
  std::vector<Eigen::MatrixXd> H, g;
};

struct StepwiseOptions {
  double regularization = 1e-12;  // added (× the step's largest diagonal of H) for definiteness
  double rankTolerance = 1e-10;   // relative pivot threshold of the QR rank decisions
};

struct StepwiseResult {
  Eigen::MatrixXd x;                 // n × columns
  double constraintResidual = 0;     // max |M x − c|, absolute
  double stepInfeasibility = 0;      // largest residual a step could not remove (0 when consistent)
};

StepwiseResult solveStepwise(const StepwiseProblem& problem, const StepwiseOptions& options = {});

// The same solve split in two: the factorisations depend only on M, the steps and H, so a
// problem that recurs with other right-hand sides c and g (an EP configuration repeated over a
// cage, at other positions) is factored once. solve() gives what solveStepwise gives.
class StepwiseSolver {
public:
  StepwiseSolver(const StepwiseProblem& problem, const StepwiseOptions& options = {});
  StepwiseResult solve(const Eigen::MatrixXd& c, const std::vector<Eigen::MatrixXd>& g) const;
  // True when `problem` has this solver's M, steps and H (bit for bit).
  bool matches(const StepwiseProblem& problem) const;

private:
  struct Step {
    std::vector<int> J, known;
    Eigen::MatrixXd N, A, Z, HJ, HJknown;
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
    Eigen::LDLT<Eigen::MatrixXd> reduced;  // of Zᵀ H_J Z (regularised), when Z has columns
    bool constrained = false;
  };
  Eigen::MatrixXd M_;
  std::vector<std::vector<int>> steps_;
  std::vector<Eigen::MatrixXd> H_;
  std::vector<Step> factored_;
  Eigen::Index n_ = 0;
};

}  // namespace holefill
