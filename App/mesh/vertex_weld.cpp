#include "mesh/vertex_weld.h"

#include <algorithm>
#include <array>
#include <set>

namespace holefill {

VertexWeld weldVertices(const TriangleMesh& mesh, double tol) {
  VertexWeld w;
  const std::vector<int> site = weldMap(mesh.vertices, std::max(tol, 0.0));
  const Eigen::Index n = mesh.vertices.rows();
  w.index.assign(n, -1);
  int kept = 0;
  for (Eigen::Index v = 0; v < n; ++v)
    if (site[v] == v) w.index[v] = kept++;
  for (Eigen::Index v = 0; v < n; ++v) w.index[v] = w.index[site[v]];
  w.mergedVertices = static_cast<int>(n) - kept;
  w.mesh.vertices.resize(kept, 3);
  for (Eigen::Index v = 0; v < n; ++v)
    if (site[v] == v) w.mesh.vertices.row(w.index[v]) = mesh.vertices.row(v);
  std::vector<Eigen::RowVector3i> rows;
  rows.reserve(mesh.triangles.rows());
  // A triangle is the same as an earlier one when it has the same corners in the same cyclic
  // order (the same orientation): key by its rotation that starts at the smallest index.
  std::set<std::array<int, 3>> seen;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    std::array<int, 3> f{w.index[mesh.triangles(t, 0)], w.index[mesh.triangles(t, 1)], w.index[mesh.triangles(t, 2)]};
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) { ++w.droppedTriangles; continue; }
    std::array<int, 3> key = f;
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    if (!seen.insert(key).second) { ++w.droppedTriangles; continue; }
    rows.emplace_back(f[0], f[1], f[2]);
  }
  w.mesh.triangles.resize(static_cast<Eigen::Index>(rows.size()), 3);
  for (size_t t = 0; t < rows.size(); ++t) w.mesh.triangles.row(static_cast<Eigen::Index>(t)) = rows[t];
  return w;
}

}  // namespace holefill
