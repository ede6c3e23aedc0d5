// Exact self-intersection of a filled mesh's new triangles (issue 26): a fill is valid only where
// its new triangles cross neither each other nor the surface around the hole. Pairs are found by
// CGAL's Polygon Mesh Processing (self_intersections: exact predicates, so touching and crossing
// are told apart without a tolerance) on the part of the mesh that can meet the subject
// triangles: they and every other triangle whose bounding box overlaps one of theirs, connected
// by the mesh's own indices (vertices at exactly one position taken as one: a seam's copies), so
// that triangles sharing an edge or a vertex count only where they meet beyond it. Triangles that cannot join that local mesh as a manifold surface (a third
// triangle on an edge, a repeated triangle) are left out and counted.
#pragma once

#include <utility>
#include <vector>

#include "mesh/triangle_mesh.h"

namespace holefill {

struct SelfIntersections {
  std::vector<std::pair<int, int>> pairs;  // triangle indices of `mesh`, at least one of each a subject
  int skippedTriangles = 0;                // left out of the test: not manifold with the others
};

// `subject[t]`: triangle t is one whose intersections are asked for (a fill's new triangles);
// empty: every triangle. Stops after `limit` pairs.
SelfIntersections selfIntersections(const TriangleMesh& mesh, const std::vector<bool>& subject = {}, size_t limit = 1000);

}  // namespace holefill
