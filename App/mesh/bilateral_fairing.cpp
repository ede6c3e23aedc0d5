#include "mesh/bilateral_fairing.h"

#include <cmath>
#include <set>

namespace holefill {

BilateralResult bilateralFair(HolePatch& patch, const BilateralOptions& options) {
  BilateralResult result;
  const int n = static_cast<int>(patch.points.size());
  std::vector<std::set<int>> ring(n);
  std::vector<std::vector<int>> incident(n);
  for (size_t t = 0; t < patch.triangles.size(); ++t) {
    const auto& tri = patch.triangles[t];
    for (int k = 0; k < 3; ++k) {
      incident[tri[k]].push_back(static_cast<int>(t));
      ring[tri[k]].insert(tri[(k + 1) % 3]);
      ring[tri[k]].insert(tri[(k + 2) % 3]);
    }
  }
  for (int it = 0; it < options.iterations; ++it) {
    // Jacobi update: every vertex reads the positions of the previous iteration.
    std::vector<Eigen::Vector3d> moved = patch.points;
    result.maxMove = 0;
    for (int v = patch.boundaryCount; v < n; ++v) {
      if (ring[v].empty()) continue;
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      for (int t : incident[v]) {
        const auto& tri = patch.triangles[t];
        normal += (patch.points[tri[1]] - patch.points[tri[0]]).cross(patch.points[tri[2]] - patch.points[tri[0]]);
      }
      if (!(normal.norm() > 0)) continue;
      normal.normalize();
      const Eigen::Vector3d& p = patch.points[v];
      double density = 0;
      for (int q : ring[v]) density += (p - patch.points[q]).norm();
      density /= static_cast<double>(ring[v].size());
      const double sc = options.closenessScale * density, ss = options.featureScale * density;
      if (!(sc > 0) || !(ss > 0)) continue;
      double sum = 0, normalizer = 0;
      for (int q : ring[v]) {
        const Eigen::Vector3d d = p - patch.points[q];
        const double t = d.norm(), h = normal.dot(d);
        const double w = std::exp(-t * t / (2 * sc * sc)) * std::exp(-h * h / (2 * ss * ss));
        sum += w * h;
        normalizer += w;
      }
      if (!(normalizer > 0)) continue;
      moved[v] = p - normal * (sum / normalizer);
      result.maxMove = std::max(result.maxMove, (moved[v] - p).norm());
    }
    patch.points.swap(moved);
  }
  return result;
}

}  // namespace holefill
