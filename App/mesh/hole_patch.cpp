#include "mesh/hole_patch.h"

#include <algorithm>

#include "geometry/error.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

PatchEdges::PatchEdges(const HolePatch& patch) {
  map_.reserve(patch.triangles.size() * 2);
  for (size_t t = 0; t < patch.triangles.size(); ++t) add(patch.triangles[t], static_cast<int>(t));
}

void PatchEdges::add(const std::array<int, 3>& tri, int t) {
  for (int k = 0; k < 3; ++k) {
    EdgeTriangles& e = map_[key(tri[k], tri[(k + 1) % 3])];
    HF_CHECK(e.n < 2, "a patch edge would get a third triangle");
    e.t[e.n++] = t;
  }
}

void PatchEdges::remove(const std::array<int, 3>& tri, int t) {
  for (int k = 0; k < 3; ++k) {
    auto it = map_.find(key(tri[k], tri[(k + 1) % 3]));
    if (it == map_.end()) continue;
    EdgeTriangles& e = it->second;
    if (e.n == 2 && e.t[0] == t) {
      e.t[0] = e.t[1];
      e.n = 1;
    } else if (e.n > 0 && e.t[e.n - 1] == t) {
      --e.n;
    }
    if (e.n == 0) map_.erase(it);
  }
}

const EdgeTriangles* PatchEdges::find(int u, int v) const {
  auto it = map_.find(key(u, v));
  return it == map_.end() ? nullptr : &it->second;
}

double worstQuality(const HolePatch& patch) {
  double q = 1;
  for (const auto& t : patch.triangles)
    q = std::min(q, triangleQuality(patch.points[t[0]], patch.points[t[1]], patch.points[t[2]]));
  return q;
}

double meanQuality(const HolePatch& patch) {
  double q = 0;
  for (const auto& t : patch.triangles) q += triangleQuality(patch.points[t[0]], patch.points[t[1]], patch.points[t[2]]);
  return patch.triangles.empty() ? 0 : q / static_cast<double>(patch.triangles.size());
}

Eigen::Vector3d patchTriangleNormal(const HolePatch& patch, const std::array<int, 3>& tri, double* area2) {
  const Eigen::Vector3d c = (patch.points[tri[1]] - patch.points[tri[0]]).cross(patch.points[tri[2]] - patch.points[tri[0]]);
  const double len = c.norm();
  if (area2) *area2 = len;
  return len > 0 ? Eigen::Vector3d(c / len) : Eigen::Vector3d::Zero();
}

}  // namespace holefill
