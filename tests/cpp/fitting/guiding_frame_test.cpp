#include <gtest/gtest.h>

#include <random>

#include "fitting/guiding_frame.h"
#include "geometry/error.h"

using namespace holefill;

namespace {

// A cubic Bézier frame: four curves, each side's last control point the next side's first.
std::array<Eigen::MatrixX3d, 4> knownFrame() {
  const Eigen::Vector3d c[4] = {{0, 0, 0}, {4, 0.3, 0.5}, {4.4, 3.6, 0.2}, {-0.3, 3.2, 0.8}};
  std::array<Eigen::MatrixX3d, 4> P;
  const double bulge[4][2][3] = {{{1.3, -0.4, 0.6}, {2.8, -0.3, 0.9}},
                                 {{4.6, 1.1, 0.9}, {4.8, 2.4, 0.1}},
                                 {{3.1, 3.9, -0.2}, {1.2, 3.8, 0.5}},
                                 {{-0.6, 2.1, 0.4}, {-0.5, 0.9, -0.1}}};
  for (int i = 0; i < 4; ++i) {
    P[i].resize(4, 3);
    P[i].row(0) = c[i].transpose();
    P[i].row(1) << bulge[i][0][0], bulge[i][0][1], bulge[i][0][2];
    P[i].row(2) << bulge[i][1][0], bulge[i][1][1], bulge[i][1][2];
    P[i].row(3) = c[(i + 1) % 4].transpose();
  }
  return P;
}

Eigen::Vector3d cubic(const Eigen::MatrixX3d& P, double t) {
  const double s = 1 - t;
  return (s * s * s * P.row(0) + 3 * s * s * t * P.row(1) + 3 * s * t * t * P.row(2) + t * t * t * P.row(3)).transpose();
}

// Points at sorted random parameters in [lo, hi] on each chosen side.
LabeledSides sample(const std::array<Eigen::MatrixX3d, 4>& P, double lo, double hi, std::vector<int> which, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(lo, hi);
  LabeledSides s;
  for (int i : which) {
    std::vector<double> t(30);
    for (double& x : t) x = U(rng);
    std::sort(t.begin(), t.end());
    for (double x : t) s.points[i].push_back(cubic(P[i], x));
  }
  return s;
}

}  // namespace

TEST(GuidingFrame, RecoversAKnownCubicFrameFromItsPointsAndItsCornersFromPartsOfItsSides) {
  const auto P = knownFrame();
  {
    // Points over whole sides: the cubic frame itself (the shared corners converge linearly:
    // measured 1e-11 after about 1,500 rounds).
    GuidingFrameOptions o;
    o.tolerance = 1e-13;
    o.bending = 0;
    o.roundsPerDegree = 3000;
    o.maxDegree = 3;
    const GuidingFrame f = fitGuidingFrame(sample(P, 0.0, 1.0, {0, 1, 2, 3}, 7), o);
    ASSERT_EQ(f.degree, 3);
    double worst = 0;
    for (int i = 0; i < 4; ++i) worst = std::max(worst, (f.control[i] - P[i]).cwiseAbs().maxCoeff());
    std::printf("whole sides: degree %d, control points within %.1e, max deviation %.1e, %d rounds\n", f.degree, worst, f.maxDeviation, f.rounds);
    EXPECT_LT(worst, 1e-6);
    EXPECT_LT(f.maxDeviation, 1e-9);
    for (int i = 0; i < 4; ++i)  // the corners are shared: one side ends where the next begins
      EXPECT_EQ((f.point(static_cast<Side>(i), 1) - f.point(static_cast<Side>((i + 1) % 4), 0)).norm(), 0.0);
  }
  {
    // Points on the middle 70% of each side only, default options: the corners are inferred
    // (the frame's purpose) from each side's own continuation and held: measured 0.021 of a
    // frame about 5 across (0.146 when the shared least squares placed them).
    const double tolerance = GuidingFrameOptions().tolerance;
    GuidingFrameOptions o;
    const GuidingFrame f = fitGuidingFrame(sample(P, 0.15, 0.85, {0, 1, 2, 3}, 7), o);
    double corner = 0;
    for (int i = 0; i < 4; ++i) corner = std::max(corner, (f.point(static_cast<Side>(i), 0) - P[i].row(0).transpose()).norm());
    std::printf("middle 70%%, tolerance %.0e: degree %d, corners within %.1e (frame size about 5), max deviation %.1e, %d rounds\n",
                tolerance, f.degree, corner, f.maxDeviation, f.rounds);
    EXPECT_LE(f.maxDeviation, tolerance);
    EXPECT_EQ(f.degree, 3);
    EXPECT_LT(corner, 0.04);  // measured 0.021
  }
}

TEST(GuidingFrame, ThreeOrTwoLabeledSidesAndTheDefaultTolerance) {
  const auto P = knownFrame();
  for (const auto& which : std::vector<std::vector<int>>{{0, 1, 2}, {0, 1}, {0, 2}}) {
    SCOPED_TRACE(std::to_string(which.size()) + " sides, first " + std::to_string(which[0]) + ", last " + std::to_string(which.back()));
    const GuidingFrame f = fitGuidingFrame(sample(P, 0.0, 1.0, which, 3));
    EXPECT_LE(f.maxDeviation, 1e-3);  // the default tolerance, reached at some degree
    EXPECT_LE(f.degree, 3);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(f.labeled[i], std::find(which.begin(), which.end(), i) != which.end());
    if (which == std::vector<int>{0, 1}) EXPECT_EQ((f.point(Side::South, 1) - f.point(Side::East, 0)).norm(), 0.0);
  }
  // A straight labeled side stays linear: the degree rises only as far as the data asks.
  LabeledSides flat;
  for (int k = 0; k <= 10; ++k) {
    flat.points[0].emplace_back(k, 0, 0);
    flat.points[2].emplace_back(10 - k, 5, 0);
  }
  EXPECT_EQ(fitGuidingFrame(flat).degree, 1);
}

TEST(GuidingFrame, RefusesTooFewLabelsOrPointsAndNonFinitePoints) {
  LabeledSides s;
  s.points[0] = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_THROW(fitGuidingFrame(s), Error);  // one side only
  s.points[1] = {{1, 0, 0}};
  EXPECT_THROW(fitGuidingFrame(s), Error);  // a side with one point
  s.points[1] = {{1, 0, 0}, {1, std::nan(""), 0}};
  EXPECT_THROW(fitGuidingFrame(s), Error);
  s.points[1] = {{1, 0, 0}, {1, 1, 0}};
  EXPECT_NO_THROW(fitGuidingFrame(s));
  EXPECT_THROW(fitGuidingFrame(s).point(Side::West, 0.5), Error);
}
