#include "mesh/quality_improvement.h"

#include <algorithm>

#include "mesh/triangle_mesh.h"

namespace holefill {

namespace {

double quality(const HolePatch& p, const std::array<int, 3>& t) {
  return triangleQuality(p.points[t[0]], p.points[t[1]], p.points[t[2]]);
}

// Splits edge (u, v), shared by two patch triangles, at its midpoint.
void splitEdge(HolePatch& patch, PatchEdges& edges, int u, int v) {
  const EdgeTriangles on = *edges.find(u, v);
  const int m = static_cast<int>(patch.points.size());
  patch.points.push_back(0.5 * (patch.points[u] + patch.points[v]));
  patch.scale.push_back(0.5 * (patch.scale[u] + patch.scale[v]));
  for (int t : on) {
    const std::array<int, 3> tri = patch.triangles[t];
    // Rotate so the split edge is tri[0] → tri[1] (in the triangle's own direction).
    int k = 0;
    while (!((tri[k] == u && tri[(k + 1) % 3] == v) || (tri[k] == v && tri[(k + 1) % 3] == u))) ++k;
    const int a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
    const std::array<int, 3> first = {a, m, c}, second = {m, b, c};
    edges.remove(tri, t);
    patch.triangles[t] = first;
    edges.add(first, t);
    patch.triangles.push_back(second);
    edges.add(second, static_cast<int>(patch.triangles.size()) - 1);
  }
}

}  // namespace

QualityResult improvePatchQuality(HolePatch& patch, const QualityOptions& options, const RefinementOptions& relax) {
  QualityResult result;
  // Smoothing always runs: it raises the mean a lot (0.83 -> 0.90 on a UV-sphere cap) even
  // where it costs the boundary-pinned worst triangle a few hundredths. A split round is kept
  // only when it raises the worst triangle, or raises the mean while losing at most 0.02 on
  // the worst one: where the hole's loop folds strongly, smoothing cannot place the new
  // midpoints and a round makes things worse; it is undone and the rounds stop.
  result.swaps += smoothTangentially(patch, options.smoothing, relax).swaps;
  double bestMin = worstQuality(patch), bestMean = meanQuality(patch);
  auto better = [&](double lo, double avg) { return lo > bestMin || (avg > bestMean && lo >= bestMin - 0.02); };
  for (; result.rounds < options.rounds; ++result.rounds) {
    const std::vector<Eigen::Vector3d> keptPoints = patch.points;
    const std::vector<std::array<int, 3>> keptTriangles = patch.triangles;
    const std::vector<double> keptScale = patch.scale;
    PatchEdges edges(patch);
    std::vector<std::pair<double, int>> bad;
    for (size_t t = 0; t < patch.triangles.size(); ++t) {
      const double q = quality(patch, patch.triangles[t]);
      if (q < options.target) bad.emplace_back(q, static_cast<int>(t));
    }
    if (bad.empty()) break;
    std::sort(bad.begin(), bad.end());
    std::vector<bool> touched(patch.triangles.size() + 4 * bad.size(), false);
    int splits = 0;
    for (const auto& [q, t] : bad) {
      if (touched[t]) continue;  // an earlier split in this round already changed it
      const std::array<int, 3> tri = patch.triangles[t];
      int bu = -1, bv = -1;
      double longest = 0;
      for (int k = 0; k < 3; ++k) {
        const int u = tri[k], v = tri[(k + 1) % 3];
        const EdgeTriangles* on = edges.find(u, v);
        const double len = (patch.points[u] - patch.points[v]).norm();
        if (on && on->size() == 2 && len > longest && !touched[(*on)[0]] && !touched[(*on)[1]]) {
          longest = len;
          bu = u;
          bv = v;
        }
      }
      if (bu < 0) continue;
      for (int s : *edges.find(bu, bv)) touched[s] = true;
      const size_t before = patch.triangles.size();
      splitEdge(patch, edges, bu, bv);
      for (size_t n = before; n < patch.triangles.size(); ++n) touched[n] = true;
      ++splits;
    }
    if (splits == 0) break;
    // After a few splits only their neighbourhoods need settling: a short smoothing suffices.
    TangentialSmoothingOptions settle = options.smoothing;
    settle.iterations = std::min(settle.iterations, options.roundSweeps);
    const int swaps = relaxAllEdges(patch, edges, relax) + smoothTangentially(patch, settle, relax).swaps;
    const double lo = worstQuality(patch), avg = meanQuality(patch);
    if (!better(lo, avg)) {
      patch.points = keptPoints;
      patch.triangles = keptTriangles;
      patch.scale = keptScale;
      break;
    }
    bestMin = lo;
    bestMean = avg;
    result.splits += splits;
    result.swaps += swaps;
  }
  result.minQuality = worstQuality(patch);
  return result;
}

}  // namespace holefill
