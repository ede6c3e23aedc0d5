#include "mesh/tangential_smoothing.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace holefill {

TangentialSmoothingResult smoothTangentially(HolePatch& patch, const TangentialSmoothingOptions& options,
                                             const RefinementOptions& relax) {
  TangentialSmoothingResult result;
  if (patch.points.size() <= static_cast<size_t>(patch.boundaryCount)) return result;
  PatchEdges edges(patch);
  const int n = static_cast<int>(patch.points.size());
  const double cosFold = std::cos(relax.maxFoldAngle);
  // Per-sweep vertex → triangle lists in flat arrays, and one buffer for the normals before a
  // move: the sweeps run after every refinement round, and allocation was a tenth of the fill's time.
  std::vector<int> first(n + 1), incident;
  std::vector<Eigen::Vector3d> before;
  for (; result.sweeps < options.iterations; ++result.sweeps) {
    std::fill(first.begin(), first.end(), 0);
    for (const auto& tri : patch.triangles)
      for (int v : tri) ++first[v + 1];
    for (int v = 0; v < n; ++v) first[v + 1] += first[v];
    incident.resize(3 * patch.triangles.size());
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (size_t t = 0; t < patch.triangles.size(); ++t)
      for (int v : patch.triangles[t]) incident[fill[v]++] = static_cast<int>(t);
    for (int v = patch.boundaryCount; v < n; ++v) {
      const int* ring = incident.data() + first[v];
      const int count = first[v + 1] - first[v];
      if (count == 0) continue;
      Eigen::Vector3d normal = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
      before.clear();
      for (int i = 0; i < count; ++i) {
        double a2;
        before.push_back(patchTriangleNormal(patch, patch.triangles[ring[i]], &a2));
        normal += before.back() * a2;
        // A new vertex is interior, so each 1-ring neighbour sits in exactly two of its
        // triangles: summing the triangles' other corners weighs every neighbour alike.
        for (int q : patch.triangles[ring[i]])
          if (q != v) centroid += patch.points[q];
      }
      centroid /= 2.0 * static_cast<double>(count);
      if (!(normal.norm() > 0)) continue;
      normal.normalize();
      Eigen::Vector3d move = options.step * (centroid - patch.points[v]);
      move -= normal * normal.dot(move);
      const Eigen::Vector3d old = patch.points[v];
      bool accepted = false;
      for (int halving = 0; halving < 4 && !accepted; ++halving, move *= 0.5) {
        patch.points[v] = old + move;
        accepted = true;
        for (int i = 0; i < count && accepted; ++i) {
          const Eigen::Vector3d after = patchTriangleNormal(patch, patch.triangles[ring[i]]);
          accepted = after.dot(before[i]) > 0.5 && after.dot(normal) > cosFold;
        }
      }
      if (!accepted) {
        patch.points[v] = old;
        ++result.rejectedMoves;
      }
    }
    result.swaps += relaxAllEdges(patch, edges, relax);
  }
  return result;
}

}  // namespace holefill
