#include "mesh/min_dihedral_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "geometry/error.h"

using namespace holefill;

namespace {

// A hole in a +z-facing plane: its loop runs clockwise seen from +z (along the surrounding
// triangles' own edges), each loop edge's outside triangle facing +z.
std::vector<Eigen::Vector3d> clockwiseHexagon() {
  std::vector<Eigen::Vector3d> loop;
  for (int k = 0; k < 6; ++k) loop.emplace_back(std::cos(-M_PI / 3 * k), std::sin(-M_PI / 3 * k), 0.0);
  return loop;
}

const auto kNoEdges = [](int, int) { return false; };

}  // namespace

TEST(MinDihedralTriangulation, APlanarLoopIsCoveredOnceFacingLikeItsSurroundings) {
  const std::vector<Eigen::Vector3d> loop = clockwiseHexagon();
  const std::vector<Eigen::Vector3d> up(6, Eigen::Vector3d::UnitZ());
  const auto tris = triangulateMinDihedral(loop, up, kNoEdges);
  ASSERT_EQ(tris.size(), 4u);  // n − 2
  double area = 0;
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : tris) {
    const Eigen::Vector3d n = (loop[t[1]] - loop[t[0]]).cross(loop[t[2]] - loop[t[0]]);
    EXPECT_GT(n.z(), 0) << "a triangle faces away from its surroundings";
    area += 0.5 * n.norm();
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  EXPECT_NEAR(area, 1.5 * std::sqrt(3.0), 1e-12);  // the hexagon's area: no overlap, no gap
  for (int k = 0; k < 6; ++k) {  // each loop edge once, run against the loop
    EXPECT_EQ(directed[std::make_pair((k + 1) % 6, k)], 1) << k;
    EXPECT_EQ(directed[std::make_pair(k, (k + 1) % 6)], 0) << k;
  }
}

TEST(MinDihedralTriangulation, AnExistingEdgeIsNeverRepeatedAndNoWayOutIsAnError) {
  // A square with one corner raised: either diagonal closes it; the one the surrounding mesh
  // already has (1-3) must not be used.
  const std::vector<Eigen::Vector3d> loop = {{0, 0, 0}, {0, 1, 0}, {1, 1, 1}, {1, 0, 0}};  // clockwise from +z
  const std::vector<Eigen::Vector3d> up(4, Eigen::Vector3d::UnitZ());
  const auto has13 = [](int a, int b) { return (a == 1 && b == 3) || (a == 3 && b == 1); };
  const auto tris = triangulateMinDihedral(loop, up, has13);
  ASSERT_EQ(tris.size(), 2u);
  for (const auto& t : tris) {
    int ends = 0;
    for (int c : t) ends += c == 1 || c == 3;
    EXPECT_LT(ends, 2) << "the existing edge 1-3 was added again";
  }
  const auto both = [](int a, int b) { return (a + b) % 2 == 0; };  // 0-2 and 1-3 both exist
  EXPECT_THROW(triangulateMinDihedral(loop, up, both), Error);
}
