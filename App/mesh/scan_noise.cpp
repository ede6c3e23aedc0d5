#include "mesh/scan_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/mesh_topology.h"

namespace holefill {

ScanNoise estimateScanNoise(const TriangleMesh& mesh) {
  ScanNoise out;
  const MeshTopology topo(mesh);
  const Eigen::Index nv = mesh.vertices.rows();
  // Normals from the consistently oriented triangles, so that they do not cancel.
  TriangleMesh oriented{mesh.vertices, mesh.triangles};
  for (Eigen::Index t = 0; t < oriented.triangles.rows(); ++t)
    if (topo.flipped[static_cast<size_t>(t)]) std::swap(oriented.triangles(t, 1), oriented.triangles(t, 2));
  const Eigen::MatrixX3d normal = vertexNormals(oriented);
  std::vector<std::vector<int>> ring(static_cast<size_t>(nv));
  std::vector<char> boundary(static_cast<size_t>(nv), 0);
  double edge = 0;
  for (const auto& e : topo.edges()) {
    ring[e.a].push_back(e.b), ring[e.b].push_back(e.a);
    if (e.count != 2) boundary[e.a] = boundary[e.b] = 1;
    edge += (mesh.vertices.row(e.a) - mesh.vertices.row(e.b)).norm();
  }
  out.meanEdge = edge / std::max<size_t>(1, topo.edges().size());
  std::vector<double> offset(static_cast<size_t>(nv), 0);
  for (Eigen::Index v = 0; v < nv; ++v) {
    if (ring[v].empty()) continue;
    Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
    for (int u : ring[v]) mean += mesh.vertices.row(u);
    offset[v] = (mean / static_cast<double>(ring[v].size()) - mesh.vertices.row(v)).dot(normal.row(v));
  }
  std::vector<double> rough;
  for (Eigen::Index v = 0; v < nv; ++v) {
    if (boundary[v] || ring[v].size() < 3) continue;
    bool inner = true;  // the neighbours' offsets must be whole umbrellas too
    double m = 0;
    for (int u : ring[v]) inner = inner && !boundary[u], m += offset[u];
    if (inner) rough.push_back(std::abs(offset[v] - m / static_cast<double>(ring[v].size())));
  }
  out.samples = static_cast<int>(rough.size());
  if (rough.size() < 8) return out;
  std::nth_element(rough.begin(), rough.begin() + static_cast<std::ptrdiff_t>(rough.size() / 2), rough.end());
  out.sigma = rough[rough.size() / 2] / (0.6745 * 1.359);
  return out;
}

}  // namespace holefill
