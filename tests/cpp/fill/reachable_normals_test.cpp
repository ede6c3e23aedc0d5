#include "fill/reachable_normals.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace holefill;
using Eigen::Vector3d;

namespace {

// A unit square in z = 0, run anticlockwise, 21 samples per edge from corner to corner. Edge 1's
// support normal is tilted by `tilt` about its own tangent: off the corners' normal +z by as much.
struct TiltedSquare {
  Hole hole;
  std::vector<BoundarySample> samples;
};

TiltedSquare square(double tilt, bool corners = true) {
  TiltedSquare s;
  const Vector3d c[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int e = 0; e < 4; ++e) {
    HoleEdge he;
    he.cornerAtStart = corners;
    s.hole.edges.push_back(he);
    const Vector3d p0 = c[e], p1 = c[(e + 1) % 4], t = (p1 - p0).normalized();
    Vector3d normal(0, 0, 1);
    if (e == 1) normal = Eigen::AngleAxisd(tilt, t) * normal;
    for (int k = 0; k <= 20; ++k) {
      BoundarySample x;
      x.point = p0 + (p1 - p0) * (k / 20.0);
      x.tangent = t;
      x.normal = normal;
      x.normalValid = true;
      x.edge = e;
      s.samples.push_back(x);
    }
  }
  return s;
}

double angle(const Vector3d& a, const Vector3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

}  // namespace

TEST(ReachableNormals, ATiltedCornerIsAimedAtTheCornerNormalAndEasedBackByMidEdge) {
  const double tilt = 2.2e-3;
  const TiltedSquare s = square(tilt);
  const std::vector<Vector3d> aim = reachableNormals(s.hole, s.samples, std::vector<bool>(4, true));
  ASSERT_EQ(aim.size(), s.samples.size());
  // Edge 1 runs from sample 21 (its corner with edge 0) to 41 (its corner with edge 2).
  EXPECT_LT(angle(aim[21], Vector3d::UnitZ()), 1e-12);
  EXPECT_LT(angle(aim[41], Vector3d::UnitZ()), 1e-12);
  EXPECT_LT(angle(aim[31], s.samples[31].normal), 1e-12);  // mid-edge: the support's own
  for (int k = 22; k <= 31; ++k) {  // eased monotonically, never past either end
    EXPECT_LE(angle(aim[k], s.samples[k].normal), angle(aim[k - 1], s.samples[k - 1].normal) + 1e-15);
    EXPECT_LE(angle(aim[k], s.samples[k].normal), tilt + 1e-12);
  }
  // Edges whose supports hold the corner normal keep it everywhere.
  for (int i : {0, 10, 20, 42, 62, 83}) EXPECT_LT(angle(aim[i], Vector3d::UnitZ()), 1e-12) << i;
  for (const auto& a : aim) EXPECT_NEAR(a.norm(), 1.0, 1e-12);
}

TEST(ReachableNormals, AnInexactEdgesNormalLosesItsTangentPart) {
  TiltedSquare s = square(0.0, false);
  s.samples[5].normal = Vector3d(0.1, 0, 1).normalized();  // edge 0 runs along +x
  const std::vector<Vector3d> aim = reachableNormals(s.hole, s.samples, std::vector<bool>(4, true));
  EXPECT_LT(angle(aim[5], Vector3d::UnitZ()), 1e-12);
}

TEST(ReachableNormals, WithoutTangentBreaksOrAG2RequestNothingIsEased) {
  const TiltedSquare s = square(2.2e-3, false);
  const std::vector<Vector3d> aim = reachableNormals(s.hole, s.samples, std::vector<bool>(4, true));
  for (size_t i = 0; i < aim.size(); ++i) EXPECT_LT(angle(aim[i], s.samples[i].normal), 1e-12) << i;
  // Edge 1 asked G1 only: its corners keep the support's tilt (the G1 tolerance is what counts).
  const TiltedSquare t = square(2.2e-3);
  const std::vector<Vector3d> g1 = reachableNormals(t.hole, t.samples, {true, false, true, true});
  for (int i = 21; i <= 41; ++i) EXPECT_LT(angle(g1[i], t.samples[i].normal), 1e-12) << i;
}
