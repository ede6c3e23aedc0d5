#include "mesh/self_intersection.h"

#include <gtest/gtest.h>

namespace holefill {
namespace {

TriangleMesh meshOf(std::initializer_list<Eigen::RowVector3d> v, std::initializer_list<Eigen::RowVector3i> t) {
  TriangleMesh m;
  m.vertices.resize(static_cast<Eigen::Index>(v.size()), 3);
  m.triangles.resize(static_cast<Eigen::Index>(t.size()), 3);
  Eigen::Index i = 0;
  for (const auto& p : v) m.vertices.row(i++) = p;
  i = 0;
  for (const auto& f : t) m.triangles.row(i++) = f;
  return m;
}

// An octahedron: closed, every triangle shares edges and vertices with others, none crosses.
TriangleMesh octahedron() {
  return meshOf({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

TEST(SelfIntersection, NeighboursSharingEdgesAndVerticesDoNotCount) {
  const SelfIntersections r = selfIntersections(octahedron());
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_EQ(r.skippedTriangles, 0);
}

TEST(SelfIntersection, ACrossingTriangleIsFoundWithWhatItCrosses) {
  TriangleMesh m = octahedron();
  // A triangle piercing the octahedron's +x,+y,+z face from outside to inside.
  const Eigen::Index n = m.vertices.rows();
  m.vertices.conservativeResize(n + 3, 3);
  m.vertices.row(n) << 0.3, 0.3, 0.3;
  m.vertices.row(n + 1) << 0.6, 0.6, -0.2;
  m.vertices.row(n + 2) << 0.2, 0.2, 1.2;
  m.triangles.conservativeResize(m.triangles.rows() + 1, 3);
  m.triangles.row(m.triangles.rows() - 1) << n, n + 1, n + 2;
  std::vector<bool> subject(m.triangles.rows(), false);
  subject.back() = true;
  const SelfIntersections r = selfIntersections(m, subject);
  ASSERT_FALSE(r.pairs.empty());
  for (const auto& [a, b] : r.pairs) EXPECT_EQ(b, m.triangles.rows() - 1);
  EXPECT_TRUE(std::any_of(r.pairs.begin(), r.pairs.end(), [](const auto& p) { return p.first == 0; }));  // the +x+y+z face
  // Asked about a face the new triangle does not reach: nothing (the crossing is not its).
  std::vector<bool> none(m.triangles.rows(), false);
  none[1] = true;  // a face the new triangle does not reach
  EXPECT_TRUE(selfIntersections(m, none).pairs.empty());
}

TEST(SelfIntersection, AFoldedNeighbourLyingOnItsFaceIsFound) {
  // Two triangles sharing edge 0-1, the second folded back onto the first (coplanar overlap): a
  // fill that flips over its boundary looks like this.
  const TriangleMesh m = meshOf({{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0.5, 0}}, {{0, 1, 2}, {1, 0, 3}});
  EXPECT_EQ(selfIntersections(m).pairs.size(), 1u);
  // Unfolded (the fourth vertex across the shared edge) they only share it.
  TriangleMesh flat = m;
  flat.vertices.row(3) << 1, -0.5, 0;
  EXPECT_TRUE(selfIntersections(flat).pairs.empty());
}

TEST(SelfIntersection, ANonManifoldTriangleIsTestedAndARepeatedOneCounted) {
  // Three triangles on edge 0-1: the third, upright, touches the others only along the edge.
  TriangleMesh m = meshOf({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  SelfIntersections r = selfIntersections(m);
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_EQ(r.skippedTriangles, 0);
  // Laid down onto the first, on its side of the edge: it overlaps it.
  m.vertices.row(4) << 0.5, 0.5, 0;
  r = selfIntersections(m);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0], std::make_pair(0, 2));
  // The first triangle twice: coincident, counted, not a crossing.
  m.vertices.row(4) << 0.5, 0, 1;
  m.triangles.conservativeResize(4, 3);
  m.triangles.row(3) << 1, 2, 0;
  r = selfIntersections(m);
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_EQ(r.skippedTriangles, 1);
}

// A subject with no area (three collinear corners) is reported as crossing itself, as CGAL's
// self_intersections does; a triangle crossing an old one that shares a vertex with it is found,
// and only the pairs with a subject are.
TEST(SelfIntersection, ADegenerateSubjectAndACrossingAtASharedVertexAreFound) {
  TriangleMesh m = meshOf({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}}, {{0, 1, 2}, {0, 3, 1}, {0, 4, 5}});
  std::vector<bool> subject = {false, true, false};
  SelfIntersections r = selfIntersections(m, subject);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0], std::make_pair(1, 1));
  subject = {false, false, true};  // through triangle 0's inside, sharing its corner 0
  r = selfIntersections(m, subject);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0], std::make_pair(0, 2));
  subject = {true, false, false};
  EXPECT_EQ(selfIntersections(m, subject).pairs, (std::vector<std::pair<int, int>>{{0, 2}}));
}

}  // namespace
}  // namespace holefill
