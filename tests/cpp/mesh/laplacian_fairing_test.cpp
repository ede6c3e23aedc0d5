#include "mesh/laplacian_fairing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_patches.h"

using namespace holefill;

using testpatches::fan;

TEST(LaplacianFairing, AMembraneSitsAtTheMeanOfItsRing) {
  // The loop on the paraboloid z = x² + y² (height 1 all round): the membrane (Δx = 0) puts the
  // middle vertex at the loop's mean height, moving it along its normal (z) only.
  for (LaplacianWeights w : {LaplacianWeights::Uniform, LaplacianWeights::Cotangent}) {
    HolePatch p = fan(0.0, [](double x, double y) { return x * x + y * y; });
    LaplacianFairingOptions o;
    o.order = 1;
    o.weights = w;
    fairLaplacian(p, SurroundingRing{}, o);
    EXPECT_NEAR(p.points[6].z(), 1.0, 1e-9);
    EXPECT_NEAR(p.points[6].x(), 0.0, 1e-12);
    EXPECT_NEAR(p.points[6].y(), 0.0, 1e-12);
  }
}

TEST(LaplacianFairing, APlanarHoleStaysPlanarAndOrderZeroLeavesTheFlatPlacement) {
  HolePatch p = fan(0.0, [](double x, double y) { return 0.2 * x - 0.1 * y + 3; });  // a tilted plane
  p.points[6].z() = 3.0;  // on it
  LaplacianFairingOptions o;
  o.order = 1;
  fairLaplacian(p, SurroundingRing{}, o);
  EXPECT_NEAR(p.points[6].z() - (0.2 * p.points[6].x() - 0.1 * p.points[6].y() + 3), 0.0, 1e-9);
  HolePatch q = fan(0.0, [](double x, double y) { return x * x + y * y; });
  o.order = 0;
  fairLaplacian(q, SurroundingRing{}, o);
  EXPECT_EQ(q.points[6].z(), 0.0);
}

TEST(LaplacianFairing, AnOrderAboveTwoIsSolvedAtTwoFromTheLimitOn) {
  // On an uneven loop order 3 and order 2 place the new vertex differently; from a limit of
  // one new vertex on (the fan has one), order 3 is solved as order 2, exactly; 0: never.
  const auto paraboloid = [](double x, double y) { return x * x * x + 0.5 * y * y + 0.3 * x * y; };
  HolePatch two = fan(0.0, paraboloid), three = fan(0.0, paraboloid), limited = fan(0.0, paraboloid);
  LaplacianFairingOptions o;
  o.order = 2;
  fairLaplacian(two, SurroundingRing{}, o);
  o.order = 3;
  o.highOrderUpTo = 0;
  fairLaplacian(three, SurroundingRing{}, o);
  EXPECT_GT((three.points[6] - two.points[6]).norm(), 1e-6);
  o.highOrderUpTo = 1;
  fairLaplacian(limited, SurroundingRing{}, o);
  EXPECT_EQ(limited.points[6], two.points[6]);
}
