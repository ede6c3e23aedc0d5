#include "mesh/triangle_mesh.h"

#include "geometry/edge_key.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <cstdint>

#include "geometry/error.h"

namespace holefill {

void validateMesh(const TriangleMesh& mesh, const std::string& what) {
  const Eigen::Index n = mesh.vertices.rows();
  for (Eigen::Index i = 0; i < n; ++i)
    if (!mesh.vertices.row(i).allFinite())
      throw Error(what + ": vertex " + std::to_string(i) + " has a coordinate that is not finite (NaN or infinity); repair or remove it");
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::RowVector3i f = mesh.triangles.row(t);
    for (int k = 0; k < 3; ++k)
      if (f[k] < 0 || f[k] >= n)
        throw Error(what + ": triangle " + std::to_string(t) + " uses vertex " + std::to_string(f[k]) + ", out of range: the mesh has " +
                    std::to_string(n) + " vertices");
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
      throw Error(what + ": triangle " + std::to_string(t) + " repeats a vertex (" + std::to_string(f[0]) + ", " +
                  std::to_string(f[1]) + ", " + std::to_string(f[2]) + "); remove degenerate triangles first");
  }
}

double triangleQuality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double prod = la * lb * lc;
  if (!(prod > 0)) return 0;
  const double s = 0.5 * (la + lb + lc);
  return std::max(0.0, 8.0 * (s - la) * (s - lb) * (s - lc) / prod);
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

double maxInnerAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  auto angle = [](const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
    const Eigen::Vector3d u = q - p, v = r - p;
    if (!(u.norm() > 0 && v.norm() > 0)) return M_PI;
    return angleBetween(u, v);
  };
  return std::max({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

Eigen::MatrixX3d vertexNormals(const TriangleMesh& mesh) {
  Eigen::MatrixX3d n = Eigen::MatrixX3d::Zero(mesh.vertices.rows(), 3);
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::RowVector3i f = mesh.triangles.row(t);
    // The unnormalized cross product is twice the area times the unit normal: area weighting for free.
    const Eigen::RowVector3d w = (mesh.vertices.row(f[1]) - mesh.vertices.row(f[0]))
                                     .cross(mesh.vertices.row(f[2]) - mesh.vertices.row(f[0]));
    for (int k = 0; k < 3; ++k) n.row(f[k]) += w;
  }
  for (Eigen::Index i = 0; i < n.rows(); ++i) {
    const double len = n.row(i).norm();
    if (len > 0) n.row(i) /= len;
  }
  return n;
}

std::vector<int> weldMap(const Eigen::MatrixX3d& vertices, double tol, const std::vector<int>& candidates) {
  std::vector<int> site(vertices.rows());
  std::iota(site.begin(), site.end(), 0);
  // Union-find whose root is the smallest index: a chain of close pairs (a, b within tol, b, c
  // within tol) is one cluster even where a and c are farther apart.
  const auto root = [&](int v) {
    while (site[v] != v) v = site[v] = site[site[v]];
    return v;
  };
  std::vector<int> order = candidates;
  if (order.empty()) order = site;
  // Sweep along x: only pairs within tol in x need the full distance.
  std::sort(order.begin(), order.end(), [&](int a, int b) { return vertices(a, 0) < vertices(b, 0); });
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1; j < order.size() && vertices(order[j], 0) - vertices(order[i], 0) <= tol; ++j)
      if ((vertices.row(order[i]) - vertices.row(order[j])).norm() <= tol) {
        const int a = root(order[i]), b = root(order[j]);
        site[std::max(a, b)] = std::min(a, b);
      }
  for (size_t v = 0; v < site.size(); ++v) site[v] = root(static_cast<int>(v));
  return site;
}

int countBoundaryEdges(const TriangleMesh& mesh, const std::vector<int>& weld) {
  std::vector<std::uint64_t> keys;
  keys.reserve(static_cast<size_t>(mesh.triangles.rows()) * 3);
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      int u = mesh.triangles(t, k), v = mesh.triangles(t, (k + 1) % 3);
      if (!weld.empty()) { u = weld[u]; v = weld[v]; }
      if (u == v) continue;
      keys.push_back(undirectedEdgeKey(u, v));
    }
  std::sort(keys.begin(), keys.end());
  int boundary = 0;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    boundary += j - i == 1 ? 1 : 0;
    i = j;
  }
  return boundary;
}

double boundingDiagonal(const Eigen::MatrixX3d& vertices) {
  if (vertices.rows() == 0) return 0;
  return (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
}

}  // namespace holefill
