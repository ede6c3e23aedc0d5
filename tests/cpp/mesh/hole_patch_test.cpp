#include "mesh/hole_patch.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_patches.h"

using namespace holefill;

TEST(HolePatch, EdgesHoldOneTriangleOnTheLoopAndTwoInsideAndFollowEdits) {
  HolePatch p = testpatches::fan(0.0, [](double, double) { return 0.0; });
  PatchEdges edges(p);
  ASSERT_TRUE(edges.has(0, 1));
  EXPECT_EQ(edges.find(1, 0)->size(), 1u);  // a loop edge, either way round
  ASSERT_TRUE(edges.has(6, 3));
  EXPECT_EQ(edges.find(3, 6)->size(), 2u);  // a spoke: the two triangles beside it
  EXPECT_FALSE(edges.has(0, 3));
  edges.remove(p.triangles[2], 2);  // triangle (2, 3, 6) taken out, then put back
  EXPECT_EQ(edges.find(3, 6)->size(), 1u);
  EXPECT_FALSE(edges.has(2, 3));
  edges.add(p.triangles[2], 2);
  EXPECT_EQ(edges.find(3, 6)->size(), 2u);
  EXPECT_TRUE(p.isNew(6) && !p.isNew(5));
}

TEST(HolePatch, QualityAndNormalsOfARegularFan) {
  HolePatch p = testpatches::fan(0.0, [](double, double) { return 0.0; });
  // Six equilateral triangles: Field's quality 1 everywhere.
  EXPECT_NEAR(worstQuality(p), 1.0, 1e-12);
  EXPECT_NEAR(meanQuality(p), 1.0, 1e-12);
  double area2 = 0;
  const Eigen::Vector3d n = patchTriangleNormal(p, p.triangles[0], &area2);
  EXPECT_NEAR(n.z(), 1.0, 1e-12);  // anticlockwise seen from +z
  EXPECT_NEAR(area2, std::sqrt(3.0) / 2, 1e-12);  // twice the area of a unit equilateral triangle
  p.points[6] = p.points[0];  // collapsed onto a loop vertex: degenerate triangles
  EXPECT_NEAR(worstQuality(p), 0.0, 1e-12);
  EXPECT_EQ(patchTriangleNormal(p, p.triangles[0]), Eigen::Vector3d::Zero());
}
