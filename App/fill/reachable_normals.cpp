#include "fill/reachable_normals.h"

#include <cmath>

#include "geometry/tolerances.h"

namespace holefill {

std::vector<Eigen::Vector3d> reachableNormals(const Hole& hole, const std::vector<BoundarySample>& samples,
                                              const std::vector<bool>& easeCorners) {
  const size_t n = samples.size();
  std::vector<Eigen::Vector3d> aim(n);
  for (size_t i = 0; i < n; ++i) {
    const BoundarySample& x = samples[i];
    const Eigen::Vector3d r = x.normal - x.normal.dot(x.tangent) * x.tangent;
    aim[i] = r.norm() > 0.5 ? r.normalized() : x.normal;
  }
  const size_t m = hole.edges.size();
  if (n == 0 || m < 2 || easeCorners.size() != m) return aim;
  // Each edge's run of samples [first, last] and its arc length from the run's start.
  std::vector<long> first(m, -1), last(m, -1);
  std::vector<double> along(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const int e = samples[i].edge;
    if (e < 0 || static_cast<size_t>(e) >= m) return aim;
    if (first[e] < 0) first[e] = static_cast<long>(i);
    else if (last[e] != static_cast<long>(i) - 1) return aim;  // not one run per edge: leave the aims as they are
    else along[i] = along[i - 1] + (samples[i].point - samples[i - 1].point).norm();
    last[e] = static_cast<long>(i);
  }
  std::vector<Eigen::Vector3d> shift(n, Eigen::Vector3d::Zero());
  for (size_t b = 0; b < m; ++b) {
    const size_t a = (b + m - 1) % m;
    if (!hole.edges[b].cornerAtStart || first[a] < 0 || first[b] < 0) continue;
    const size_t endA = static_cast<size_t>(last[a]), startB = static_cast<size_t>(first[b]);
    const Eigen::Vector3d nc = samples[endA].tangent.cross(samples[startB].tangent);
    if (nc.norm() < std::sin(tol::kCornerAngleDeg * M_PI / 180.0)) continue;  // a cusp: n_c undetermined
    // Both edges' runs, each eased from its corner sample to its middle.
    for (const auto& [edge, corner, atEnd] : {std::tuple{a, endA, true}, std::tuple{b, startB, false}}) {
      if (!easeCorners[edge] || !samples[corner].normalValid) continue;
      const Eigen::Vector3d target = nc.dot(aim[corner]) >= 0 ? nc.normalized() : Eigen::Vector3d(-nc.normalized());
      const Eigen::Vector3d c = target - aim[corner];
      const double half = 0.5 * along[last[edge]];
      if (half <= 0) continue;
      for (long i = first[edge]; i <= last[edge]; ++i) {
        const double d = atEnd ? along[last[edge]] - along[i] : along[i];
        if (d >= half || !samples[i].normalValid) continue;
        const double u = d / half;
        shift[i] += (1 - u) * (1 - u) * (1 + 2 * u) * c;  // 1 at the corner, 0 with zero slope at mid-edge
      }
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (shift[i].squaredNorm() > 0) aim[i] = (aim[i] + shift[i]).normalized();
  return aim;
}

}  // namespace holefill
