#include "mesh/mesh_holes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "geometry/error.h"
#include "geometry/json_reader.h"

using namespace holefill;

namespace {

// An n x n grid of unit cells in z = 0, two triangles per cell, anticlockwise seen from +z;
// the cells for which `drop` says so are left out.
TriangleMesh grid(int n, const std::function<bool(int, int)>& drop) {
  TriangleMesh m;
  m.vertices.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.row(j * (n + 1) + i) << i, j, 0;
  std::vector<Eigen::Vector3i> t;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (drop(i, j)) continue;
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      t.emplace_back(a, b, c);
      t.emplace_back(a, c, d);
    }
  m.triangles.resize(static_cast<Eigen::Index>(t.size()), 3);
  for (size_t k = 0; k < t.size(); ++k) m.triangles.row(static_cast<Eigen::Index>(k)) = t[k].transpose();
  return m;
}

double signedArea(const TriangleMesh& m, const std::vector<int>& loop) {
  double a = 0;
  for (size_t k = 0; k < loop.size(); ++k) {
    const Eigen::RowVector3d p = m.vertices.row(loop[k]), q = m.vertices.row(loop[(k + 1) % loop.size()]);
    a += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  return a;
}

}  // namespace

TEST(MeshHoles, LoopsRunAlongTheTrianglesOwnEdgesLongestFirst) {
  // A 4 x 4 grid without its cell (1, 1) and the 2 x 1 cells (2..3, 3): an inner hole of length 4;
  // the corner bite joins the rim, whose loop turns in around it (its length stays 16).
  const TriangleMesh m = grid(4, [](int i, int j) { return (i == 1 && j == 1) || (j == 3 && i >= 2); });
  const MeshHoleReport r = findMeshHoles(m);
  ASSERT_EQ(r.holes.size(), 2u);
  EXPECT_NEAR(r.holes[0].length, 16.0, 1e-12);
  EXPECT_EQ(r.holes[0].loop.size(), 16u);
  EXPECT_NEAR(signedArea(m, r.holes[0].loop), 16.0 - 2.0, 1e-12);  // the grid less the bite
  EXPECT_NEAR(r.holes[1].length, 4.0, 1e-12);
  EXPECT_GT(signedArea(m, r.holes[0].loop), 0);  // the rim: anticlockwise, as the triangles run
  EXPECT_LT(signedArea(m, r.holes[1].loop), 0);  // the hole inside: the other way round seen from +z
  EXPECT_NEAR(std::abs(signedArea(m, r.holes[1].loop)), 1.0, 1e-12);
  for (const MeshHole& h : r.holes) {
    EXPECT_TRUE(h.fillable) << h.message;
    ASSERT_EQ(h.edgeTriangles.size(), h.loop.size());
    for (size_t k = 0; k < h.loop.size(); ++k) {  // each loop edge is an edge of its triangle
      const Eigen::RowVector3i t = m.triangles.row(h.edgeTriangles[k]);
      int found = 0;
      for (int c = 0; c < 3; ++c) found += t(c) == h.loop[k] || t(c) == h.loop[(k + 1) % h.loop.size()];
      EXPECT_EQ(found, 2) << k;
    }
  }
  EXPECT_EQ(r.boundaryEdges, 16 + 4);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.nonManifoldEdges, 0);
  // The report as JSON carries the same holes.
  const JsonValue j = parseJson(toJson(r), "report");
  ASSERT_NE(j.find("holes"), nullptr);
  EXPECT_EQ(j.find("holes")->array.size(), 2u);
}

TEST(MeshHoles, AVertexSharedByTwoHolesGivesTwoSimpleLoops) {
  // Cells (1, 1) and (2, 2) of a 4 x 4 grid meet at vertex (2, 2) only.
  const TriangleMesh m = grid(4, [](int i, int j) { return (i == 1 && j == 1) || (i == 2 && j == 2); });
  const MeshHoleReport r = findMeshHoles(m);
  ASSERT_EQ(r.holes.size(), 3u);  // the rim and two squares
  EXPECT_GE(r.singularVertices, 1);
  for (size_t k = 1; k < 3; ++k) {
    EXPECT_EQ(r.holes[k].loop.size(), 4u);
    EXPECT_NEAR(r.holes[k].length, 4.0, 1e-12);
    std::vector<int> sorted = r.holes[k].loop;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());  // simple: no vertex twice
  }
}

TEST(MeshHoles, AClosedMeshHasNoneAndABrokenOneIsRefusedByName) {
  // Two triangles glued back to back: every edge has two triangles.
  TriangleMesh closed;
  closed.vertices.resize(3, 3);
  closed.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  closed.triangles.resize(2, 3);
  closed.triangles << 0, 1, 2, 0, 2, 1;
  const MeshHoleReport r = findMeshHoles(closed);
  EXPECT_TRUE(r.holes.empty());
  EXPECT_EQ(r.boundaryEdges, 0);
  TriangleMesh bad = closed;
  bad.triangles(1, 2) = 7;
  EXPECT_THROW(findMeshHoles(bad), Error);
}
