#include "mesh/bilateral_fairing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_patches.h"

using namespace holefill;

using testpatches::fan;

TEST(BilateralFairing, ASpikeSinksTowardsItsRingAndTheLoopStays) {
  HolePatch p = fan(0.3, [](double, double) { return 0.0; });
  const std::vector<Eigen::Vector3d> loop(p.points.begin(), p.points.begin() + 6);
  BilateralOptions once;
  once.iterations = 1;
  const BilateralResult r = bilateralFair(p, once);
  // Every neighbour is 0.3 below along its normal and as close: the weighted mean offset takes
  // it all the way down in one iteration (subtracted, as Fleishman has it, not added).
  EXPECT_NEAR(p.points[6].z(), 0.0, 1e-12);
  EXPECT_NEAR(r.maxMove, 0.3, 1e-12);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(p.points[k], loop[k]) << k;
  EXPECT_NEAR(p.points[6].x(), 0.0, 1e-12);  // along its normal only: no drift in the plane
  EXPECT_NEAR(p.points[6].y(), 0.0, 1e-12);
}

TEST(BilateralFairing, AFlatPatchStaysFlatAndNoIterationsMovesNothing) {
  HolePatch flat = fan(0.0, [](double, double) { return 0.0; });
  const BilateralResult r = bilateralFair(flat);
  EXPECT_NEAR(flat.points[6].z(), 0.0, 1e-15);
  EXPECT_NEAR(r.maxMove, 0.0, 1e-15);
  HolePatch spike = fan(0.3, [](double, double) { return 0.0; });
  BilateralOptions none;
  none.iterations = 0;
  bilateralFair(spike, none);
  EXPECT_EQ(spike.points[6].z(), 0.3);
}
