#include "mesh/min_angle_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "geometry/error.h"

namespace holefill {
namespace {

// A planar hole of n vertices on the unit circle, run clockwise seen from +z: the direction of
// the edges of a surrounding mesh whose normals point up.
struct PlanarHole {
  std::vector<Eigen::Vector3d> loop, sums, across;
  explicit PlanarHole(int n) {
    for (int k = 0; k < n; ++k) {
      const double a = -2 * M_PI * k / n;
      loop.emplace_back(std::cos(a), std::sin(a), 0);
      sums.emplace_back(0, 0, 1);
      across.emplace_back(0, 0, 1);
    }
  }
};

// A long hole: the ear cutting is linear-logarithmic now (issue 22: a 20,000-vertex hole spent a
// minute here), and must still tile the polygon exactly, facing the mesh's side.
TEST(MinAngleTriangulation, LongPlanarLoopIsTiledOnce) {
  const int n = 3000;
  const PlanarHole h(n);
  const MinAngleResult r = triangulateMinAngle(h.loop, h.sums, h.across, [](int, int) { return false; });
  ASSERT_EQ(static_cast<int>(r.triangles.size()), n - 2);
  EXPECT_EQ(r.earsWithFold, 0);
  EXPECT_NEAR(r.sigma, MinAngleOptions{}.smallSigma, 1e-15);
  double area = 0;
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : r.triangles) {
    const Eigen::Vector3d nt = (h.loop[t[1]] - h.loop[t[0]]).cross(h.loop[t[2]] - h.loop[t[0]]);
    EXPECT_GT(nt.z(), 0) << "a triangle faces away from the surrounding mesh";
    area += 0.5 * nt.z();
    for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  }
  // Positive triangles whose areas add up to the polygon's cannot overlap.
  EXPECT_NEAR(area, 0.5 * n * std::sin(2 * M_PI / n), 1e-9);
  for (int k = 0; k < n; ++k) EXPECT_EQ((uses[{std::min(k, (k + 1) % n), std::max(k, (k + 1) % n)}]), 1);
  for (const auto& [e, count] : uses) {
    const bool onLoop = e.second - e.first == 1 || (e.first == 0 && e.second == n - 1);
    if (!onLoop) EXPECT_EQ(count, 2) << "an inner edge not shared by two triangles";
  }
}

// An ear whose new edge the mesh already has is never cut: here every chord from vertex 0.
TEST(MinAngleTriangulation, ExistingEdgesAreNotDuplicated) {
  const int n = 12;
  const PlanarHole h(n);
  const auto fromZero = [&](int i, int j) { return (i == 0 || j == 0) && std::abs(i - j) > 1 && std::abs(i - j) < n - 1; };
  const MinAngleResult r = triangulateMinAngle(h.loop, h.sums, h.across, fromZero);
  ASSERT_EQ(static_cast<int>(r.triangles.size()), n - 2);
  for (const auto& t : r.triangles)
    for (int k = 0; k < 3; ++k) EXPECT_FALSE(fromZero(t[k], t[(k + 1) % 3])) << t[k] << "-" << t[(k + 1) % 3];
}

// When every ear would duplicate an edge, the hole is refused with a message, not looped on.
TEST(MinAngleTriangulation, NoEarLeftIsAClearError) {
  const PlanarHole h(6);
  EXPECT_THROW(triangulateMinAngle(h.loop, h.sums, h.across, [](int i, int j) { return std::abs(i - j) != 1 && std::abs(i - j) != 5; }),
               Error);
}

}  // namespace
}  // namespace holefill
