// Boundary points of clouds given without them.
#include <gtest/gtest.h>

#include <random>

#include "fitting/cloud_boundary.h"
#include "geometry/error.h"

using namespace holefill;

namespace {
// A jittered grid on a bent sheet over [0, 2] x [0, 1], minus an L-notch when `notch`.
Eigen::MatrixX3d sheet(bool notch, std::vector<bool>& truth) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> j(-0.15, 0.15);
  std::vector<Eigen::RowVector3d> p;
  truth.clear();
  const int nu = 61, nv = 31;
  for (int a = 0; a < nu; ++a)
    for (int b = 0; b < nv; ++b) {
      const bool cut = notch && a > 40 && b > 20;
      if (cut) continue;
      const bool edge = a == 0 || b == 0 || a == nu - 1 || b == nv - 1 || (notch && ((a == 40 && b > 20) || (b == 20 && a > 40)));
      const double du = edge ? 0 : j(rng), dv = edge ? 0 : j(rng);
      const double u = (a + du) * 2.0 / (nu - 1), v = (b + dv) / (nv - 1);
      p.emplace_back(u, v, 0.3 * std::sin(2 * u) + 0.2 * v * v);
      truth.push_back(edge);
    }
  Eigen::MatrixX3d m(p.size(), 3);
  for (size_t k = 0; k < p.size(); ++k) m.row(k) = p[k];
  return m;
}
}  // namespace

TEST(CloudBoundary, FindsTheRectanglesSidesAndNothingInside) {
  std::vector<bool> truth;
  const Eigen::MatrixX3d p = sheet(false, truth);
  const CloudBoundary b = detectCloudBoundary(p);
  int missed = 0, extra = 0;
  for (size_t k = 0; k < truth.size(); ++k) missed += truth[k] && !b.boundary[k], extra += !truth[k] && b.boundary[k];
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(extra, 0);
  EXPECT_NEAR(b.spacing, 1.0 / 30, 0.3 / 30);
}

TEST(CloudBoundary, FollowsAConcaveNotch) {
  std::vector<bool> truth;
  const Eigen::MatrixX3d p = sheet(true, truth);
  const CloudBoundary b = detectCloudBoundary(p);
  int missed = 0, extra = 0;
  for (size_t k = 0; k < truth.size(); ++k) missed += truth[k] && !b.boundary[k], extra += !truth[k] && b.boundary[k];
  // The alpha disc (3 spacings = 0.1) cannot enter the notch's 90° inner corner at (4/3, 2/3):
  // the points it cannot reach there are the only ones missed.
  for (size_t k = 0; k < truth.size(); ++k)
    if (truth[k] && !b.boundary[k]) EXPECT_LT((p.row(k).head<2>() - Eigen::RowVector2d(4.0 / 3, 2.0 / 3)).norm(), 0.1) << p.row(k);
  EXPECT_LE(missed, 4);
  EXPECT_EQ(extra, 0);
}

TEST(CloudBoundary, BadCloudsAreRefused) {
  EXPECT_THROW(detectCloudBoundary(Eigen::MatrixX3d::Random(5, 3)), Error);
  Eigen::MatrixX3d line(20, 3);
  for (int k = 0; k < 20; ++k) line.row(k) << k, 2 * k, 0;
  EXPECT_THROW(detectCloudBoundary(line), Error);
  Eigen::MatrixX3d nan = Eigen::MatrixX3d::Random(20, 3);
  nan(3, 1) = std::nan("");
  EXPECT_THROW(detectCloudBoundary(nan), Error);
}

