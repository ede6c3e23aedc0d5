#include "learn/canonical_boundary.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/error.h"
#include "learn/uvtran_data.h"

using namespace holefill;
using namespace holefill::learn;

TEST(CanonicalBoundary, IndependentOfStartDirectionPlacementAndScale) {
  const UvtranSample x = makeUvtranSample(3);
  // Move the canonical loop anywhere, start it elsewhere, reverse it: the canonical points return.
  Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Eigen::Vector3d> moved, reversed;
  const int n = static_cast<int>(x.boundary.size());
  for (int k = 0; k < n; ++k) moved.push_back(12.5 * (R * x.boundary[(k + 37) % n]) + Eigen::Vector3d(4, -9, 2));
  for (int k = 0; k < n; ++k) reversed.push_back(moved[(n - k) % n]);
  const CanonicalBoundary a = canonicalizeBoundary(x.boundary), b = canonicalizeBoundary(moved),
                          c = canonicalizeBoundary(reversed);
  double worst = 0, worstMirror = 0;
  for (int k = 0; k < n; ++k) {
    worst = std::max(worst, (a.points[k] - b.points[k]).norm());
    // Running the other way turns the frame half a turn about x: the same loop, mirrored in y and z.
    const Eigen::Vector3d m = a.points[(n - k) % n];
    worstMirror = std::max(worstMirror, (Eigen::Vector3d(m.x(), 1 - m.y(), 1 - m.z()) - c.points[k]).norm());
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(worstMirror, 1e-9);
  // The data is already canonical: canonicalizing it again is (nearly) the identity. Nearly: the
  // frame is re-fitted to the resampled loop: under 2e-3 with g++, 2.1e-3 with clang.
  for (int k = 0; k < n; ++k) EXPECT_LT((a.points[k] - x.boundary[k]).norm(), 3e-3);
}

TEST(CanonicalBoundary, RejectsBadLoops) {
  std::vector<Eigen::Vector3d> few = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  EXPECT_THROW(canonicalizeBoundary(few), Error);
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 20; ++i) line.emplace_back(i, 2 * i, 0);
  EXPECT_THROW(canonicalizeBoundary(line), Error);
  std::vector<Eigen::Vector3d> nan;
  for (int i = 0; i < 20; ++i) nan.emplace_back(std::cos(i), std::sin(i), 0);
  nan[5].x() = std::nan("");
  EXPECT_THROW(canonicalizeBoundary(nan), Error);
}
