#include "gnurbs/stepwise_least_squares.h"

#include <gtest/gtest.h>

using namespace holefill;

namespace {

// Two unknowns solved one after the other; each step pulls its own unknown to `target`.
StepwiseProblem twoSteps(const Eigen::MatrixXd& M, const Eigen::MatrixXd& c, double target0, double target1) {
  StepwiseProblem p;
  p.M = M;
  p.c = c;
  p.steps = {{0}, {1}};
  const Eigen::MatrixXd H = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd g(2, 1);
  g << target0, target1;
  p.H = {H, H};
  p.g = {g, g};
  return p;
}

}  // namespace

TEST(StepwiseLeastSquares, OneStepIsTheConstrainedMinimiser) {
  // min ½|x − a|² subject to x0 + x1 + x2 = 1: x = a + (1 − Σa)/3, in x, y and z at once (to the
  // regularisation's 1e-12 of H's diagonal).
  StepwiseProblem p;
  p.M = Eigen::MatrixXd::Ones(1, 3);
  p.c = Eigen::MatrixXd::Ones(1, 3);
  p.steps = {{0, 1, 2}};
  Eigen::MatrixXd a(3, 3);
  a << 1, 0, 2, 0.5, 0, -1, -2, 0, 4;
  p.H = {Eigen::MatrixXd::Identity(3, 3)};
  p.g = {a};
  const StepwiseResult r = solveStepwise(p);
  for (int col = 0; col < 3; ++col) {
    const double shift = (1 - a.col(col).sum()) / 3;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.x(i, col), a(i, col) + shift, 1e-10) << i << "," << col;
  }
  EXPECT_LT(r.constraintResidual, 1e-12);
  EXPECT_EQ(r.stepInfeasibility, 0.0);
}

TEST(StepwiseLeastSquares, AnEarlierStepLeavesWhatTheLaterOnesNeed) {
  // x0 + x1 = 1 and x1 = 0.3: the first step wants x0 = 5, but the later step can only meet both
  // rows if x0 = 0.7, so the first step is held to that (the rows' projection past x1's column).
  Eigen::MatrixXd M(2, 2), c(2, 1);
  M << 1, 1, 0, 1;
  c << 1, 0.3;
  const StepwiseResult r = solveStepwise(twoSteps(M, c, 5.0, 9.0));
  EXPECT_NEAR(r.x(0, 0), 0.7, 1e-12);
  EXPECT_NEAR(r.x(1, 0), 0.3, 1e-12);
  EXPECT_LT(r.constraintResidual, 1e-12);
  // Where the later unknown is free, the first keeps its own aim and the second completes the row.
  Eigen::MatrixXd M1(1, 2), c1(1, 1);
  M1 << 1, 1;
  c1 << 1;
  const StepwiseResult free = solveStepwise(twoSteps(M1, c1, 5.0, 9.0));
  EXPECT_NEAR(free.x(0, 0), 5.0, 1e-10);  // the regularisation (1e-12 of H's diagonal) shifts it that little
  EXPECT_NEAR(free.x(1, 0), -4.0, 1e-10);
}

TEST(StepwiseLeastSquares, RedundantRowsAreHarmlessAndContradictionsAreMeasured) {
  Eigen::MatrixXd M(3, 2), c(3, 1);
  M << 1, 1, 2, 2, 0, 1;  // the second row twice the first
  c << 1, 2, 0.3;
  const StepwiseResult r = solveStepwise(twoSteps(M, c, 5.0, 9.0));
  EXPECT_NEAR(r.x(0, 0), 0.7, 1e-10);
  EXPECT_NEAR(r.x(1, 0), 0.3, 1e-10);
  EXPECT_LT(r.stepInfeasibility, 1e-10);
  c(1, 0) = 3;  // now the two rows disagree: no x meets both
  const StepwiseResult bad = solveStepwise(twoSteps(M, c, 5.0, 9.0));
  EXPECT_GT(bad.constraintResidual, 0.1);
  EXPECT_GT(bad.stepInfeasibility, 0.1);
}

TEST(StepwiseLeastSquares, AFactoredSolverGivesTheSameForOtherRightHandSides) {
  Eigen::MatrixXd M(2, 2), c(2, 1);
  M << 1, 1, 0, 1;
  c << 1, 0.3;
  const StepwiseProblem p = twoSteps(M, c, 5.0, 9.0);
  const StepwiseSolver solver(p);
  EXPECT_TRUE(solver.matches(p));
  StepwiseProblem other = p;
  other.c << 2, -1;
  other.g[0](0, 0) = other.g[1](0, 0) = -3;
  const StepwiseResult direct = solveStepwise(other), factored = solver.solve(other.c, other.g);
  EXPECT_LT((direct.x - factored.x).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(factored.x(0, 0), 3.0, 1e-12);  // x1 = −1, x0 + x1 = 2
  other.M(0, 1) = 2;
  EXPECT_FALSE(solver.matches(other));
}
