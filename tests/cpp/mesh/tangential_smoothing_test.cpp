#include "mesh/tangential_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_patches.h"

using namespace holefill;

TEST(TangentialSmoothing, AnOffCentreVertexMovesToItsRingsCentreInItsTangentPlane) {
  HolePatch p = testpatches::fan(0.0, [](double, double) { return 0.0; });
  p.points[6] = Eigen::Vector3d(0.3, -0.2, 0.0);
  const double before = worstQuality(p);
  const std::vector<Eigen::Vector3d> loop(p.points.begin(), p.points.begin() + 6);
  const TangentialSmoothingResult r = smoothTangentially(p);
  EXPECT_EQ(r.sweeps, TangentialSmoothingOptions{}.iterations);
  EXPECT_LT(p.points[6].head<2>().norm(), 1e-3);  // the hexagon's centre
  EXPECT_EQ(p.points[6].z(), 0.0);                // never off the plane
  EXPECT_GT(worstQuality(p), before);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(p.points[k], loop[k]) << k;
}

TEST(TangentialSmoothing, OnACurvedPatchOnlyTheTangentialPartMoves) {
  // The loop on the paraboloid z = x² + y² with the middle vertex at its apex but off to the side:
  // its normal there is tilted, and the move stays square to it.
  HolePatch p = testpatches::fan(0.0, [](double x, double y) { return 0.5 * (x * x + y * y); });
  p.points[6] = Eigen::Vector3d(0.2, 0.0, 0.0);
  double area2 = 0;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (const auto& t : p.triangles) n += patchTriangleNormal(p, t, &area2) * area2;  // area-weighted
  n.normalize();
  const Eigen::Vector3d start = p.points[6];
  TangentialSmoothingOptions once;
  once.iterations = 1;
  smoothTangentially(p, once);
  const Eigen::Vector3d move = p.points[6] - start;
  EXPECT_GT(move.norm(), 0.05);
  EXPECT_LT(std::abs(move.dot(n)), 1e-9 + 1e-6 * move.norm());
  EXPECT_LT(p.points[6].x(), start.x());  // towards the ring's centre
}
