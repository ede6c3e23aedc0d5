// Merging a mesh's coincident vertices before its holes are filled. Scans and exports
// duplicate vertices along seams (CGAL's elephant-with-holes: texture seams), so a seam reads as
// two boundary loops running side by side, and holes that touch it run into each other there
// (mesh_holes.h splits such loops; the seam itself stays open). Welding the copies first makes
// the seam an ordinary edge and leaves only the holes the surface really has. This is a repair
// before the paper's pipeline (Hu et al., section II takes a manifold mesh as given), offered in
// every door as an option, never done silently: it renumbers the input's vertices.
#pragma once

#include <vector>

#include "mesh/triangle_mesh.h"

namespace holefill {

struct VertexWeld {
  TriangleMesh mesh;               // the kept vertices in their input order, the triangles remapped
  std::vector<int> index;          // input vertex → vertex of `mesh`
  int mergedVertices = 0;          // input vertices merged into an earlier copy
  int droppedTriangles = 0;        // triangles left with two corners on one vertex, or repeating an earlier one
};

// Vertices within `tol` (model units; chains of such pairs count as one cluster) become the
// first of them. Triangles collapsed by the merge, and second copies of a triangle on the same
// three vertices with the same orientation, are dropped; everything else keeps its order.
// tol <= 0 welds only exactly equal positions.
VertexWeld weldVertices(const TriangleMesh& mesh, double tol);

}  // namespace holefill
