#include "mesh/fill_metrics.h"

#include <gtest/gtest.h>

#include "mesh/mesh_hole_fill.h"
#include "mesh/sample_meshes.h"

using namespace holefill;

TEST(FillMetrics, DistanceToATriangleInEveryRegion) {
  TriangleMesh t;
  t.vertices.resize(3, 3);
  t.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  t.triangles.resize(1, 3);
  t.triangles << 0, 1, 2;
  Eigen::MatrixX3d p(5, 3);
  p << 0.2, 0.2, 0.5,   // above the face
      -1, -1, 0,        // beyond vertex 0
      0.5, -2, 0,       // beyond edge 01
      1, 1, 0,          // beyond edge 12
      0, 0, 0;          // on it
  const Eigen::VectorXd d = distancesToMesh(p, t);
  EXPECT_NEAR(d[0], 0.5, 1e-15);
  EXPECT_NEAR(d[1], std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(d[2], 2.0, 1e-15);
  EXPECT_NEAR(d[3], std::sqrt(0.5), 1e-15);
  EXPECT_EQ(d[4], 0.0);
}

TEST(FillMetrics, MeasuresAFillByPositionAgainstTheCutSurface) {
  const auto cut = samples::cutHole(samples::icosphere(4), [](const Eigen::Vector3d& c) { return c.normalized().x() > 0.9; });
  const MeshFillResult r = fillMeshHoles(cut.mesh);
  const FillMetrics m = measureFill(cut.mesh, r.mesh, cut.removed);
  EXPECT_EQ(m.newVertices, r.fills[0].newVertices);
  EXPECT_EQ(m.newTriangles, r.fills[0].newTriangles);
  EXPECT_NEAR(m.meanQuality, r.fills[0].meanQuality, 1e-12);
  EXPECT_GT(m.boundaryEdgesBefore, 10);
  EXPECT_EQ(m.boundaryEdgesAfter, 0);
  EXPECT_EQ(m.nonManifoldEdgesAdded, 0);
  EXPECT_EQ(m.misorientedEdgesAdded, 0);
  EXPECT_TRUE(m.keptInput);
  // A cap of 0.9 in x: its fill lies within the cap's height (0.1 of radius, /diagonal 2√3).
  EXPECT_GT(m.maxDistance, 0);
  EXPECT_LT(m.maxDistance, 0.1 / (2 * std::sqrt(3.0)));
  // Filling the input "with itself" adds nothing and keeps everything.
  const FillMetrics none = measureFill(cut.mesh, cut.mesh, cut.removed);
  EXPECT_EQ(none.newTriangles, 0);
  EXPECT_EQ(none.boundaryEdgesAfter, none.boundaryEdgesBefore);
}
