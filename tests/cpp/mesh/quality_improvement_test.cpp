#include <gtest/gtest.h>

#include "mesh/quality_improvement.h"
#include "test_patches.h"

using namespace holefill;
using namespace holefill::testpatches;

// After density refinement a fan leaves flat ears at the loop; the quality pass (splits of the
// long interior edges, tangential smoothing, relaxation) raises the worst triangle, never lowers
// it, and keeps the patch a flat oriented disk with its loop where it was.
TEST(QualityImprovement, RaisesTheWorstTriangleOfARefinedFanAndKeepsTheLoop) {
  HolePatch p = flatFanDisk(24, 4.0);
  refinePatch(p);
  const std::vector<Eigen::Vector3d> loop(p.points.begin(), p.points.begin() + p.boundaryCount);
  const double worstBefore = worstQuality(p);
  const QualityResult r = improvePatchQuality(p);
  EXPECT_GE(r.minQuality, worstBefore);
  EXPECT_NEAR(r.minQuality, worstQuality(p), 1e-12);
  EXPECT_GT(r.minQuality, 0.4);
  expectFlatOrientedDisk(p);
  for (int k = 0; k < p.boundaryCount; ++k) EXPECT_EQ(p.points[k], loop[k]) << "loop vertex " << k << " moved";
}

// Switched off (no rounds, no smoothing), it changes nothing.
TEST(QualityImprovement, NoRoundsAndNoSmoothingLeaveThePatch) {
  HolePatch p = flatFanDisk(12, 2.0);
  refinePatch(p);
  const HolePatch before = p;
  QualityOptions o;
  o.rounds = 0;
  o.smoothing.iterations = 0;
  const QualityResult r = improvePatchQuality(p, o);
  EXPECT_EQ(r.splits, 0);
  EXPECT_EQ(p.points, before.points);
  EXPECT_EQ(p.triangles.size(), before.triangles.size());
}
