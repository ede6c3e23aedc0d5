#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fitting/thb_spline.h"
#include "geometry/error.h"

using namespace holefill;

namespace {

// Two levels of refinement of a 6 × 5 cubic space: a block at level 0, a block inside it at level 1.
ThbSpace refined() {
  ThbSpace s(3, 6, 5);
  std::vector<std::pair<int, int>> a, b;
  for (int i = 1; i <= 4; ++i)
    for (int j = 1; j <= 3; ++j) a.emplace_back(i, j);
  s.refine(0, a);
  for (int i = 3; i <= 6; ++i)
    for (int j = 3; j <= 5; ++j) b.emplace_back(i, j);
  s.refine(1, b);
  return s;
}

// Collocation matrix of the active functions (or their hierarchical versions) at random points.
Eigen::MatrixXd collocation(const ThbSpace& s, int points, bool hierarchical, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const int n = static_cast<int>(s.functions().size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(points, n);
  ThbSpace flat(s.degree(), s.cellsU(s.levels() - 1), s.cellsV(s.levels() - 1));  // the finest level's tensor basis
  std::vector<std::map<std::pair<int, int>, double>> hb;
  if (hierarchical)
    for (const auto& f : s.functions()) hb.push_back(s.hierarchical(f.level, f.i, f.j));
  for (int r = 0; r < points; ++r) {
    const double u = U(rng), v = U(rng);
    if (!hierarchical) {
      for (const auto& [k, x] : s.evaluate(u, v)) M(r, k) = x;
      continue;
    }
    std::map<std::pair<int, int>, double> fine;
    const auto& fb = flat.functions();
    for (const auto& [k, x] : flat.evaluate(u, v)) fine[{fb[k].i, fb[k].j}] = x;
    for (int k = 0; k < n; ++k) {
      for (const auto& [ij, c] : hb[k]) {
        const auto it = fine.find(ij);
        if (it != fine.end()) M(r, k) += c * it->second;
      }
    }
  }
  return M;
}

}  // namespace

TEST(ThbSpline, OneLevelIsTheTensorProductBasis) {
  const ThbSpace s(3, 6, 5);
  EXPECT_EQ(s.functions().size(), 9u * 8u);
  double worst = 0;
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
    for (double v : {0.0, 0.31, 0.64, 1.0}) {
      double sum = 0;
      for (const auto& [k, x] : s.evaluate(u, v)) sum += x;
      worst = std::max(worst, std::abs(sum - 1));
    }
  EXPECT_LT(worst, 1e-14);
}

TEST(ThbSpline, TruncatedBasisIsAPartitionOfUnityWithSmallerSupportsAndSpansTheHierarchicalSpace) {
  const ThbSpace s = refined();
  ASSERT_EQ(s.levels(), 3);
  const int n = static_cast<int>(s.functions().size());
  // Partition of unity and non-negativity.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0, lowest = 1;
  for (int r = 0; r < 2000; ++r) {
    double sum = 0;
    for (const auto& [k, x] : s.evaluate(U(rng), U(rng))) sum += x, lowest = std::min(lowest, x);
    worst = std::max(worst, std::abs(sum - 1));
  }
  // Truncation only drops (non-negative) finer contributions: in the finest basis each truncated
  // function's coefficients lie between 0 and its hierarchical function's, on a subset of its
  // support, and some supports shrink.
  int shrunk = 0;
  double above = 0;
  for (const auto& f : s.functions()) {
    const auto h = s.hierarchical(f.level, f.i, f.j);
    for (const auto& [ij, c] : f.finest) {
      const auto it = h.find(ij);
      above = std::max(above, it == h.end() ? 1.0 : std::max(c - it->second, -c));
    }
    shrunk += f.finest.size() < h.size();
  }
  // Linear independence, and the same span as the hierarchical (untruncated) functions.
  const Eigen::MatrixXd T = collocation(s, 3 * n, false, 7), H = collocation(s, 3 * n, true, 7);
  Eigen::MatrixXd both(T.rows(), 2 * n);
  both << T, H;
  const auto rank = [](const Eigen::MatrixXd& M) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(M);
    qr.setThreshold(1e-10);
    return static_cast<int>(qr.rank());
  };
  std::printf("THB: %d functions over 3 levels; partition of unity to %.1e, lowest value %.1e; %d of them truncated; ranks %d (THB), %d (HB), %d (both)\n",
              n, worst, lowest, shrunk, rank(T), rank(H), rank(both));
  EXPECT_LT(worst, 1e-12);
  EXPECT_GE(lowest, -1e-14);
  EXPECT_LT(above, 1e-12);
  EXPECT_GT(shrunk, 0);
  EXPECT_EQ(rank(T), n);
  EXPECT_EQ(rank(H), n);
  EXPECT_EQ(rank(both), n);
}

TEST(ThbSpline, ReproducesCubicsAndRefusesBadInput) {
  const ThbSpace s = refined();
  const int n = static_cast<int>(s.functions().size());
  const Eigen::MatrixXd M = collocation(s, 3 * n, false, 11);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  Eigen::VectorXd f(M.rows());
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    const double u = U(rng), v = U(rng);
    f[r] = u * u * u * v - 2 * u * v * v + v * v * v + 0.5;
  }
  const Eigen::VectorXd c = M.colPivHouseholderQr().solve(f);
  EXPECT_LT((M * c - f).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_THROW(ThbSpace(0, 4, 4), Error);
  EXPECT_THROW(ThbSpace(3, 2, 4), Error);
  ThbSpace t(2, 4, 4);
  t.refine(0, {{0, 0}});
  EXPECT_THROW(t.refine(1, {{5, 5}}), Error);  // not in Ω^1
}

// The map to the finest level writes each active function in the finest B-splines: coefficients
// put through it give the finest B-spline surface whose values are the THB sum at every point;
// the space built from a list of cells is the space refined by hand.
TEST(ThbSpline, TheFinestMapWritesEachFunctionInTheFinestBasis) {
  const ThbSpace s = refined();
  const ThbSpace listed = refinedThbSpace(3, 6, 5, {{1, 3, 3}, {0, 1, 1}, {0, 2, 1}, {0, 3, 1}, {0, 4, 1}, {0, 1, 2}, {0, 2, 2}, {0, 3, 2},
                                                    {0, 4, 2}, {0, 1, 3}, {0, 2, 3}, {0, 3, 3}, {0, 4, 3}, {1, 4, 3}, {1, 5, 3}, {1, 6, 3},
                                                    {1, 3, 4}, {1, 4, 4}, {1, 5, 4}, {1, 6, 4}, {1, 3, 5}, {1, 4, 5}, {1, 5, 5}, {1, 6, 5}});
  ASSERT_EQ(listed.functions().size(), s.functions().size());
  const Eigen::SparseMatrix<double> T = s.finestMap();
  const int L = s.levels() - 1, nv = s.cellsV(L) + 3;
  ASSERT_EQ(T.rows(), (s.cellsU(L) + 3) * nv);
  ASSERT_EQ(T.cols(), static_cast<Eigen::Index>(s.functions().size()));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0, 1);
  Eigen::VectorXd c(T.cols());
  for (Eigen::Index k = 0; k < c.size(); ++k) c(k) = U(rng) - 0.5;
  const Eigen::VectorXd fine = T * c;
  const ThbSpace flat(3, s.cellsU(L), s.cellsV(L));
  double worst = 0;
  for (int r = 0; r < 200; ++r) {
    const double u = U(rng), v = U(rng);
    double thb = 0, bspline = 0;
    for (const auto& [k, x] : s.evaluate(u, v)) thb += c(k) * x;
    for (const auto& [k, x] : flat.evaluate(u, v)) bspline += fine(flat.functions()[k].i * nv + flat.functions()[k].j) * x;
    worst = std::max(worst, std::abs(thb - bspline));
  }
  EXPECT_LT(worst, 1e-13);
  EXPECT_THROW(refinedThbSpace(3, 6, 5, {{1, 0, 0}}), Error);  // a level-1 cell outside the refined ones
}
