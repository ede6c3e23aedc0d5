#include "mesh/tangential_smoothing.h"

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
  for (; result.sweeps < options.iterations; ++result.sweeps) {
    std::vector<std::vector<int>> incident(n);
    for (size_t t = 0; t < patch.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) incident[patch.triangles[t][k]].push_back(static_cast<int>(t));
    for (int v = patch.boundaryCount; v < n; ++v) {
      if (incident[v].empty()) continue;
      Eigen::Vector3d normal = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
      for (int t : incident[v]) {
        double a2;
        normal += patchTriangleNormal(patch, patch.triangles[t], &a2) * a2;
        // A new vertex is interior, so each 1-ring neighbour sits in exactly two of its
        // triangles: summing the triangles' other corners weighs every neighbour alike.
        for (int q : patch.triangles[t])
          if (q != v) centroid += patch.points[q];
      }
      centroid /= 2.0 * static_cast<double>(incident[v].size());
      if (!(normal.norm() > 0)) continue;
      normal.normalize();
      Eigen::Vector3d move = options.step * (centroid - patch.points[v]);
      move -= normal * normal.dot(move);
      const Eigen::Vector3d old = patch.points[v];
      std::vector<Eigen::Vector3d> before;
      for (int t : incident[v]) before.push_back(patchTriangleNormal(patch, patch.triangles[t]));
      bool accepted = false;
      for (int halving = 0; halving < 4 && !accepted; ++halving, move *= 0.5) {
        patch.points[v] = old + move;
        accepted = true;
        for (size_t i = 0; i < incident[v].size() && accepted; ++i) {
          const Eigen::Vector3d after = patchTriangleNormal(patch, patch.triangles[incident[v][i]]);
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
