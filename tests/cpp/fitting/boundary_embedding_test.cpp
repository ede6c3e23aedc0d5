#include "fitting/boundary_embedding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "test_regions.h"

using namespace holefill;

// A 5 × 5 grid with a hole in the middle cell: outer and inner loops. Laid out as the grid they
// are simple and apart; with the hole's corner (3, 3) pulled out through the outer loop's top
// side, the crossings name exactly the ends of the edges that cross.
TEST(BoundaryEmbedding, NamesTheEndsOfCrossingBoundaryEdges) {
  Eigen::MatrixX2d uv;
  const TriangleMesh region = testregions::gridRegion(
      5, 5, 1.0, [](double x, double y) { return !(x > 2 && x < 3 && y > 2 && y < 3); },
      [](double x, double y) { return Eigen::Vector3d(x, y, 0); }, uv);
  const MeshHoleReport holes = findMeshHoles(region);
  ASSERT_EQ(holes.holes.size(), 2u);
  EXPECT_TRUE(boundaryCrossingVertices(holes, uv).empty());
  EXPECT_FALSE(boundaryCrosses(holes, uv));
  auto vertexAt = [&](double x, double y) {
    for (Eigen::Index v = 0; v < uv.rows(); ++v)
      if ((uv.row(v) - Eigen::RowVector2d(x, y)).norm() < 1e-12) return static_cast<int>(v);
    return -1;
  };
  Eigen::MatrixX2d moved = uv;
  const int corner = vertexAt(3, 3);
  ASSERT_GE(corner, 0);
  moved.row(corner) << 3.2, 5.5;
  // The hole's edges (3, 2)-corner and corner-(2, 3) run through the top's (3, 5)-(4, 5) and
  // (2, 5)-(3, 5).
  std::vector<int> expected = {corner, vertexAt(3, 2), vertexAt(2, 3), vertexAt(2, 5), vertexAt(3, 5), vertexAt(4, 5)};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(boundaryCrossingVertices(holes, moved), expected);
  EXPECT_TRUE(boundaryCrosses(holes, moved));
  EXPECT_EQ(boundaryCrossingVertices(holes, moved, 1).size(), 4u);  // one crossing: two edges, four ends
}
