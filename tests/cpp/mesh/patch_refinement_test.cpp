#include <gtest/gtest.h>

#include "mesh/patch_refinement.h"
#include "test_patches.h"

using namespace holefill;
using namespace holefill::testpatches;

// Pfeifle–Seidel density refinement on a flat disk triangulated as a fan of thin ears: new
// vertices come in until the patch matches the loop's spacing, in the plane, as an oriented disk,
// and the relaxation leaves no edge whose two opposite angles sum to more than π (Delaunay).
TEST(PatchRefinement, AFanOfThinEarsBecomesADenseDelaunayDiskInItsPlane) {
  HolePatch p = flatFanDisk(24, 4.0);
  const double before = longestEdge(p), spacing = p.scale[0];
  const RefinementResult r = refinePatch(p);
  EXPECT_GT(r.splits, 10);
  EXPECT_GT(r.swaps, 0);
  EXPECT_FALSE(r.capped);
  expectFlatOrientedDisk(p);
  EXPECT_LT(longestEdge(p), 0.5 * before);
  EXPECT_LT(longestEdge(p), 3 * spacing);
  PatchEdges edges(p);
  for (size_t t = 0; t < p.triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const int u = p.triangles[t][e], v = p.triangles[t][(e + 1) % 3];
      const EdgeTriangles* on = edges.find(u, v);
      ASSERT_NE(on, nullptr);
      if (on->size() != 2 || u > v) continue;
      double opposite = 0;
      for (int k : *on) {
        const auto& tri = p.triangles[k];
        for (int c = 0; c < 3; ++c)
          if (tri[c] != u && tri[c] != v) {
            const Eigen::Vector3d a = p.points[u] - p.points[tri[c]], b = p.points[v] - p.points[tri[c]];
            opposite += std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
          }
      }
      EXPECT_LE(opposite, M_PI + 1e-9) << "edge " << u << "-" << v;
    }
}

// A hole already as dense as its loop is relaxed, not split: the triangle (3 loop vertices) stays.
TEST(PatchRefinement, ATriangleHoleIsLeftAsItIs) {
  HolePatch p = flatFanDisk(3, 1.0);
  const RefinementResult r = refinePatch(p);
  EXPECT_EQ(r.splits, 0);
  EXPECT_EQ(p.triangles.size(), 1u);
  EXPECT_EQ(p.points.size(), 3u);
}

// A larger α asks for more vertices: a triangle is split while α times the distance from its
// centroid to a corner exceeds the spacing σ, so the triangles end about σ/α across.
TEST(PatchRefinement, DensityFactorSetsHowManyVerticesComeIn) {
  HolePatch matched = flatFanDisk(24, 4.0), denser = matched;
  RefinementOptions o;
  refinePatch(matched, o);
  o.densityFactor = 3.0;
  refinePatch(denser, o);
  EXPECT_GT(denser.points.size(), 2 * matched.points.size());
  EXPECT_LT(longestEdge(denser), longestEdge(matched));
  expectFlatOrientedDisk(denser);
}
