#include "mesh/vertex_weld.h"

#include <gtest/gtest.h>

#include "geometry/error.h"
#include "mesh/mesh_holes.h"
#include "mesh/mesh_hole_fill.h"

namespace holefill {
namespace {

// A 3 × 3 grid of unit squares cut along x = 1 into two sheets that share no vertex: the seam's
// four positions carry two vertices each, as an exporter writes a texture seam.
TriangleMesh seamedGrid() {
  std::vector<Eigen::RowVector3d> v;
  std::vector<Eigen::RowVector3i> t;
  auto sheet = [&](int x0, int x1) {
    const int base = static_cast<int>(v.size());
    const int w = x1 - x0 + 1;
    for (int j = 0; j <= 3; ++j)
      for (int i = x0; i <= x1; ++i) v.emplace_back(i, j, 0);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i + 1 < w; ++i) {
        const int a = base + j * w + i, b = a + 1, c = a + w, d = c + 1;
        t.emplace_back(a, b, d);
        t.emplace_back(a, d, c);
      }
  };
  sheet(0, 1);
  sheet(1, 3);
  TriangleMesh m;
  m.vertices.resize(v.size(), 3);
  m.triangles.resize(t.size(), 3);
  for (size_t k = 0; k < v.size(); ++k) m.vertices.row(k) = v[k];
  for (size_t k = 0; k < t.size(); ++k) m.triangles.row(k) = t[k];
  return m;
}

TEST(VertexWeld, MergesASeamIntoOneSheet) {
  const TriangleMesh m = seamedGrid();
  ASSERT_EQ(m.vertices.rows(), 8 + 12);
  EXPECT_EQ(countBoundaryEdges(m), 12 + 6);  // the sheet's rim and both sides of the seam
  const VertexWeld w = weldVertices(m, 1e-9);
  EXPECT_EQ(w.mergedVertices, 4);
  EXPECT_EQ(w.droppedTriangles, 0);
  EXPECT_EQ(w.mesh.vertices.rows(), 16);
  EXPECT_EQ(w.mesh.triangles.rows(), m.triangles.rows());
  EXPECT_EQ(countBoundaryEdges(w.mesh), 12);  // the rim only
  // Kept vertices keep their order and positions; a copy maps to its first vertex.
  for (Eigen::Index i = 0; i < m.vertices.rows(); ++i)
    EXPECT_TRUE(w.mesh.vertices.row(w.index[i]).isApprox(m.vertices.row(i))) << i;
  EXPECT_EQ(w.index[0], 0);
  EXPECT_LT(w.index[8], 8);  // the second sheet's (1, 0) is the first sheet's
}

TEST(VertexWeld, DropsCollapsedAndRepeatedTriangles) {
  TriangleMesh m;
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1e-12, 0, 0, 1, 1, 0;
  m.triangles.resize(4, 3);
  m.triangles << 0, 1, 2,   // kept
      3, 1, 2,              // the same as the first once 3 is 0
      0, 3, 4,              // collapsed: 0 and 3 are one vertex
      1, 4, 2;              // kept
  const VertexWeld w = weldVertices(m, 1e-9);
  EXPECT_EQ(w.mergedVertices, 1);
  EXPECT_EQ(w.droppedTriangles, 2);
  ASSERT_EQ(w.mesh.triangles.rows(), 2);
  EXPECT_EQ(w.mesh.triangles.row(1), Eigen::RowVector3i(1, 3, 2));  // vertex 4 is now 3
}

TEST(VertexWeld, JoinsChainsOfClosePairs) {
  Eigen::MatrixX3d v(3, 3);
  v << 0, 0, 0, 0.6, 0, 0, 1.2, 0, 0;  // 0–1 and 1–2 within 0.7, 0–2 not
  const std::vector<int> site = weldMap(v, 0.7);
  EXPECT_EQ(site, (std::vector<int>{0, 0, 0}));
}

TEST(VertexWeld, TheMeshFillClosesTheSeamWhenAsked) {
  TriangleMesh m = seamedGrid();
  MeshFillOptions o;
  const MeshFillResult asIs = fillMeshHoles(m, o);
  o.weld = 1e-9;
  const MeshFillResult welded = fillMeshHoles(m, o);
  EXPECT_EQ(welded.weldedVertices, 4);
  EXPECT_EQ(welded.detection.holes.size(), 1u);  // the rim: the seam is no hole
  // As it is, the seam is read as one too (its two sides paired), but the result stays open by
  // index along it: closed only once welded.
  EXPECT_EQ(asIs.detection.holes.size(), 1u);
  EXPECT_EQ(asIs.detection.seamEdges, 6);
  EXPECT_FALSE(asIs.closed);
  EXPECT_TRUE(asIs.closedWhenWelded);
  EXPECT_TRUE(welded.closed);
  EXPECT_EQ(countBoundaryEdges(welded.mesh), 0);
  // The welded input comes first, bit for bit.
  const VertexWeld w = weldVertices(m, 1e-9 * boundingDiagonal(m.vertices));
  EXPECT_TRUE(welded.mesh.vertices.topRows(w.mesh.vertices.rows()) == w.mesh.vertices);
  EXPECT_TRUE(welded.mesh.triangles.topRows(w.mesh.triangles.rows()) == w.mesh.triangles);
  o.weld = -1;
  EXPECT_THROW(fillMeshHoles(m, o), Error);
}

}  // namespace
}  // namespace holefill
