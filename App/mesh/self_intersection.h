// Exact self-intersection of a filled mesh's new triangles (issue 26): a fill is valid only where
// its new triangles cross neither each other nor the surface around the hole. Candidate pairs are
// a subject triangle and any triangle whose bounding box overlaps its (CGAL's box_intersection_d),
// tested with exact predicates (so touching and crossing are told apart without a tolerance) as
// CGAL PMP's self_intersections tests faces: on the mesh's own indices (vertices at exactly one
// position taken as one: a seam's copies), triangles sharing an edge or a vertex count only where
// they meet beyond it. Only pairs with a subject are tested: PMP on the local mesh also tested
// the old triangles against each other, which was most of a fill's crossing check (measured on the
// mesh corpus: median whole fill 3.4 ms with the check, 2.1 ms without, before this).
#pragma once

#include <utility>
#include <vector>

#include "mesh/triangle_mesh.h"

namespace holefill {

struct SelfIntersections {
  std::vector<std::pair<int, int>> pairs;  // triangle indices of `mesh`, at least one of each a subject
  int skippedTriangles = 0;                // pairs of one triangle twice (the same three vertices): coincident, not tested
};

// `subject[t]`: triangle t is one whose intersections are asked for (a fill's new triangles);
// empty: every triangle. Stops after `limit` pairs.
SelfIntersections selfIntersections(const TriangleMesh& mesh, const std::vector<bool>& subject = {}, size_t limit = 1000);

}  // namespace holefill
