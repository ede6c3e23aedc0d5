#include <gtest/gtest.h>

#include "mesh/mesh_holes.h"
#include "mesh/triangle_mesh.h"
#include "mesh/sample_meshes.h"

using namespace holefill;

// The bundled meshes are what their names say: counts, closedness and holes.
TEST(SampleMeshes, GridIcosphereAndTubeHaveTheirCountsAndBoundaries) {
  const TriangleMesh grid = samples::gridPlane(4, 3, 0.5);
  EXPECT_EQ(grid.vertices.rows(), 5 * 4);
  EXPECT_EQ(grid.triangles.rows(), 2 * 4 * 3);
  EXPECT_EQ(countBoundaryEdges(grid), 2 * (4 + 3));
  EXPECT_NEAR(grid.vertices.col(0).maxCoeff(), 2.0, 1e-12);
  const TriangleMesh sphere = samples::icosphere(2, 3.0);
  EXPECT_EQ(countBoundaryEdges(sphere), 0);
  EXPECT_EQ(sphere.vertices.rows() - sphere.triangles.rows() / 2, 2);  // V − E + F = 2 with E = 3F/2
  EXPECT_NEAR(sphere.vertices.rowwise().norm().minCoeff(), 3.0, 1e-9);
  EXPECT_NEAR(sphere.vertices.rowwise().norm().maxCoeff(), 3.0, 1e-9);
  EXPECT_EQ(findMeshHoles(samples::tube(16, 5, 1.0, 2.0)).holes.size(), 2u);  // its two open ends
}

TEST(SampleMeshes, TheScanHasHolesAndACutHoleIsOne) {
  EXPECT_GE(findMeshHoles(samples::scanWithHoles()).holes.size(), 2u);
  const TriangleMesh grid = samples::gridPlane(10, 10, 1.0);
  const samples::CutResult cut = samples::cutHole(grid, [](const Eigen::Vector3d& p) { return (p - Eigen::Vector3d(5, 5, 0)).norm() < 2.5; });
  EXPECT_LT(cut.mesh.triangles.rows(), grid.triangles.rows());
  EXPECT_EQ(findMeshHoles(cut.mesh).holes.size(), 2u);  // the cut, and the grid's own border
}
