#include "mesh/mesh_topology.h"

#include <gtest/gtest.h>

#include "geometry/error.h"

using namespace holefill;

namespace {

TriangleMesh mesh(const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3i>& t) {
  TriangleMesh m;
  m.vertices.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (size_t k = 0; k < v.size(); ++k) m.vertices.row(static_cast<Eigen::Index>(k)) = v[k].transpose();
  m.triangles.resize(static_cast<Eigen::Index>(t.size()), 3);
  for (size_t k = 0; k < t.size(); ++k) m.triangles.row(static_cast<Eigen::Index>(k)) = t[k].transpose();
  return m;
}

// A strip of 2n triangles over quads 0..n-1 (vertices 2k, 2k+1 across); `twist` joins its ends
// the Möbius way, otherwise it stays open. Every triangle is listed anticlockwise.
TriangleMesh strip(int n, bool twist) {
  std::vector<Eigen::Vector3d> v;
  for (int k = 0; k < n + (twist ? 0 : 1); ++k) {
    v.emplace_back(k, 0, 0);
    v.emplace_back(k, 1, 0);
  }
  std::vector<Eigen::Vector3i> t;
  const int count = static_cast<int>(v.size()) / 2;
  for (int k = 0; k < n; ++k) {
    const int a = 2 * k, b = 2 * k + 1;
    int c = 2 * ((k + 1) % count), d = c + 1;
    if (twist && k == n - 1) std::swap(c, d);  // the half turn
    t.emplace_back(a, c, d);
    t.emplace_back(a, d, b);
  }
  return mesh(v, t);
}

}  // namespace

TEST(MeshTopology, ATriangleListedTheOtherWayIsReadReversed) {
  TriangleMesh m = strip(3, false);
  m.triangles.row(2) = Eigen::RowVector3i(m.triangles(2, 0), m.triangles(2, 2), m.triangles(2, 1));
  const MeshTopology t(m);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.nonOrientableComponents, 0);
  EXPECT_EQ(t.inconsistentEdges, 2);  // both of its inner edges
  int flipped = 0;
  for (bool f : t.flipped) flipped += f;
  EXPECT_EQ(flipped, 1);  // the minority, not the five that agree
  EXPECT_TRUE(t.flipped[2]);
  // In the corrected orientation triangle 2 runs as the others do.
  const int a = m.triangles(2, 0), b = m.triangles(2, 2);
  EXPECT_EQ(t.nextVertex(2, a), b);
  EXPECT_EQ(t.nextVertex(0, m.triangles(0, 0)), m.triangles(0, 1));  // the others as listed
}

TEST(MeshTopology, AMobiusStripCannotBeOriented) {
  const MeshTopology t(strip(6, true));
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.nonOrientableComponents, 1);
  ASSERT_EQ(t.orientable.size(), 1u);
  EXPECT_FALSE(t.orientable[0]);
  const MeshTopology ring(strip(6, false));
  EXPECT_EQ(ring.nonOrientableComponents, 0);
}

TEST(MeshTopology, EdgesComponentsNonManifoldEdgesAndUnusedVertices) {
  // Three triangles on edge 0-1 (a fin), one separate triangle, and a vertex of none.
  const TriangleMesh m = mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {9, 9, 9}},
                              {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {5, 6, 7}});
  const MeshTopology t(m);
  EXPECT_EQ(t.nonManifoldEdges, 1);
  EXPECT_EQ(t.unusedVertices, 1);
  // Components grow across manifold edges only (orientation is carried across them): the fin's
  // three triangles are three components, the separate triangle a fourth.
  EXPECT_EQ(t.components, 4);
  ASSERT_TRUE(t.hasEdge(1, 0));
  const MeshTopology::Edge& e = t.edge(1, 0);
  EXPECT_EQ(e.a, 0);
  EXPECT_EQ(e.b, 1);
  EXPECT_EQ(e.count, 3);
  EXPECT_NE(t.component[3], t.component[0]);
  EXPECT_FALSE(t.hasEdge(2, 5));
  EXPECT_THROW(t.edge(2, 5), Error);
  EXPECT_EQ(t.edges().size(), 3u + 2u + 2u + 3u);  // fin: 0-1 and two per triangle; the separate one: 3
}
