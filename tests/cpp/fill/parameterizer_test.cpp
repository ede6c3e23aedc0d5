#include "fill/parameterizer.h"

#include <gtest/gtest.h>

#include "geometry/error.h"
#include "geometry/polygon2d.h"

using namespace holefill;

namespace {
// Samples of a polygonal loop through the corners, 11 per side (ends included), a corner at each.
std::vector<BoundarySample> polygonLoop(Hole& hole, const std::vector<Eigen::Vector3d>& corners) {
  const int n = static_cast<int>(corners.size());
  std::vector<BoundarySample> s;
  hole.edges.resize(n);
  for (int e = 0; e < n; ++e) {
    hole.edges[e].cornerAtStart = true;
    for (int i = 0; i <= 10; ++i) {
      BoundarySample x;
      x.point = corners[e] + (corners[(e + 1) % n] - corners[e]) * (i / 10.0);
      x.weight = 0.1;
      x.edge = e;
      s.push_back(x);
    }
  }
  hole.corners = n;
  return s;
}

// A planar loop: a 3:1 rectangle tilted in space.
std::vector<BoundarySample> tiltedRectangle(Hole& hole) {
  const Eigen::Vector3d o(1, 2, 3), a = Eigen::Vector3d(1, 1, 0).normalized() * 3, b = Eigen::Vector3d(0, 0, 1);
  return polygonLoop(hole, {o, o + a, o + a + b, o + b});
}
}  // namespace

TEST(Parameterizer, NearestPlaneIsAnIsometryOnPlanarLoops) {
  Hole hole;
  const auto s = tiltedRectangle(hole);
  const Parameterization p = parameterize(hole, s, ParamMethod::NearestPlane);
  ASSERT_EQ(p.uv.size(), s.size());
  for (size_t i = 0; i < s.size(); ++i)
    for (size_t j = 0; j < s.size(); j += 7)
      EXPECT_NEAR((p.uv[i] - p.uv[j]).norm(), (s[i].point - s[j].point).norm(), 1e-12);
  EXPECT_GT(signedArea(Polygon2(p.uv.begin(), p.uv.end())), 0.0);  // counter-clockwise
  EXPECT_LE(p.u0, p.uv[0].x());
}

TEST(Parameterizer, MeanValueMapsAFourSidedLoopOntoTheRectangleOfItsSides) {
  Hole hole;
  const auto s = tiltedRectangle(hole);
  const Parameterization p = parameterize(hole, s, ParamMethod::MeanValue);
  ASSERT_EQ(p.cornerSamples.size(), 4u);
  // Axis-aligned (the sides are iso-lines of the fill), 3 x 1 as the loop's opposite sides are.
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d d = p.uv[p.cornerSamples[(c + 1) % 4]] - p.uv[p.cornerSamples[c]];
    EXPECT_NEAR(std::min(std::abs(d.x()), std::abs(d.y())), 0.0, 1e-12);
    EXPECT_NEAR(d.norm(), c % 2 == 0 ? 3.0 : 1.0, 1e-12);
  }
  // Chord length along a side: the midpoint sample of the first side is the side's midpoint.
  EXPECT_LT((p.uv[5] - 0.5 * (p.uv[0] + p.uv[10])).norm(), 1e-12);
  // Interior reference points interpolate the planar boundary: they lie in its plane, and they
  // cover the whole rectangle, not a band of it.
  ASSERT_GE(p.interiorXYZ.size(), 50u);
  const Eigen::Vector3d n = (s[10].point - s[0].point).cross(s[30].point - s[0].point).normalized();
  for (const auto& x : p.interiorXYZ) EXPECT_NEAR((x - s[0].point).dot(n), 0.0, 1e-9);
}

TEST(Parameterizer, MeanValueMapsOtherLoopsOntoARegularPolygonWithItsFirstSideAlongU) {
  // A planar pentagon with unequal sides: corners go to the regular pentagon of its perimeter.
  Hole hole;
  const auto s = polygonLoop(hole, {{0, 0, 0}, {4, 0, 0}, {5, 2, 0}, {2, 4, 0}, {-1, 2, 0}});
  const Parameterization p = parameterize(hole, s, ParamMethod::MeanValue);
  ASSERT_EQ(p.cornerSamples.size(), 5u);
  const double side = (p.uv[p.cornerSamples[0]] - p.uv[p.cornerSamples[1]]).norm();
  for (int c = 0; c < 5; ++c)
    EXPECT_NEAR((p.uv[p.cornerSamples[c]] - p.uv[p.cornerSamples[(c + 1) % 5]]).norm(), side, 1e-12);
  EXPECT_NEAR(p.uv[p.cornerSamples[0]].y(), p.uv[p.cornerSamples[1]].y(), 1e-12);  // first side along u
}

TEST(Parameterizer, DegenerateLoopIsAClearError) {
  Hole hole;
  hole.edges.resize(2);
  std::vector<BoundarySample> s;
  for (int e = 0; e < 2; ++e)
    for (int i = 0; i <= 10; ++i) {
      BoundarySample x;
      x.point = Eigen::Vector3d(e == 0 ? i : 10 - i, 0, 0);  // out along a segment and back
      x.weight = 1;
      x.edge = e;
      s.push_back(x);
    }
  EXPECT_THROW(parameterize(hole, s, ParamMethod::NearestPlane), Error);
}
