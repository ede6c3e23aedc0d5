#include "mesh/hole_patch.h"

#include <algorithm>

namespace holefill {

PatchEdges::PatchEdges(const HolePatch& patch) {
  map_.reserve(patch.triangles.size() * 2);
  for (size_t t = 0; t < patch.triangles.size(); ++t) add(patch.triangles[t], static_cast<int>(t));
}

void PatchEdges::add(const std::array<int, 3>& tri, int t) {
  for (int k = 0; k < 3; ++k) map_[key(tri[k], tri[(k + 1) % 3])].push_back(t);
}

void PatchEdges::remove(const std::array<int, 3>& tri, int t) {
  for (int k = 0; k < 3; ++k) {
    auto it = map_.find(key(tri[k], tri[(k + 1) % 3]));
    if (it == map_.end()) continue;
    auto& list = it->second;
    list.erase(std::remove(list.begin(), list.end(), t), list.end());
    if (list.empty()) map_.erase(it);
  }
}

const std::vector<int>* PatchEdges::find(int u, int v) const {
  auto it = map_.find(key(u, v));
  return it == map_.end() ? nullptr : &it->second;
}

Eigen::Vector3d patchTriangleNormal(const HolePatch& patch, const std::array<int, 3>& tri, double* area2) {
  const Eigen::Vector3d c = (patch.points[tri[1]] - patch.points[tri[0]]).cross(patch.points[tri[2]] - patch.points[tri[0]]);
  const double len = c.norm();
  if (area2) *area2 = len;
  return len > 0 ? Eigen::Vector3d(c / len) : Eigen::Vector3d::Zero();
}

}  // namespace holefill
