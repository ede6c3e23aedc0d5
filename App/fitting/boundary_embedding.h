// Whether a region's boundary loops, laid out in a parameter domain, stay simple and apart: the
// condition for the map to be an embedding at the boundary, which keeping every triangle's
// orientation does not give (a boundary vertex's fan can sweep past a full turn and run over its
// neighbours' edges), and for the loops to trim a face (BRepCheck refuses a self-intersecting
// wire). mesh-extension.md sec. 3 assumes it of the labeled map; the parameterization checks it
// of its ARAP map and the tensor-product fit of its corrected parameters.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "mesh/mesh_holes.h"

namespace holefill {

// The vertices at both ends of every boundary edge that crosses another boundary edge (of its
// own loop or another) at `uv`, each once; up to `limit` crossings are looked for.
std::vector<int> boundaryCrossingVertices(const MeshHoleReport& boundary, const Eigen::MatrixX2d& uv, size_t limit = SIZE_MAX);

inline bool boundaryCrosses(const MeshHoleReport& boundary, const Eigen::MatrixX2d& uv) {
  return !boundaryCrossingVertices(boundary, uv, 1).empty();
}

}  // namespace holefill
