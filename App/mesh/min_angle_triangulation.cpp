#include "mesh/min_angle_triangulation.h"

#include <cmath>
#include <limits>
#include <set>

#include "geometry/error.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

MinAngleResult triangulateMinAngle(const std::vector<Eigen::Vector3d>& loop,
                                   const std::vector<Eigen::Vector3d>& normalSums,
                                   const std::vector<Eigen::Vector3d>& outsideNormals,
                                   const std::function<bool(int, int)>& edgeExists,
                                   const MinAngleOptions& options) {
  const int n = static_cast<int>(loop.size());
  if (n < 3) throw Error("a hole needs at least 3 boundary vertices, this one has " + std::to_string(n));
  MinAngleResult result;

  std::vector<Eigen::Vector3d> normal(n);
  for (int i = 0; i < n; ++i) {
    const double len = normalSums[i].norm();
    normal[i] = len > 0 ? Eigen::Vector3d(normalSums[i] / len) : Eigen::Vector3d::Zero();
  }
  double spread = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (normal[i].squaredNorm() > 0 && normal[j].squaredNorm() > 0) spread = std::max(spread, angleBetween(normal[i], normal[j]));
  result.sigma = spread < options.lowNormalSpread ? options.smallSigma : options.sigmaShare * spread;

  // The live loop as a doubly linked list; across[i] is the unit normal of the triangle on
  // the other side of the edge i → next[i].
  std::vector<int> prev(n), next(n);
  for (int i = 0; i < n; ++i) { prev[i] = (i + n - 1) % n; next[i] = (i + 1) % n; }
  std::vector<Eigen::Vector3d> across = outsideNormals;
  std::vector<Eigen::Vector3d> sums = normalSums;
  std::set<std::pair<int, int>> newEdges;
  auto joined = [&](int a, int b) {
    return newEdges.count({std::min(a, b), std::max(a, b)}) > 0 || edgeExists(a, b);
  };
  auto earAngle = [&](int i) {
    const Eigen::Vector3d &a = loop[prev[i]], &v = loop[i], &b = loop[next[i]];
    const double theta = angleBetween(a - v, b - v);
    const Eigen::Vector3d nt = (v - a).cross(b - a);
    // Loops run with their triangles' edges (anticlockwise in the paper's terms): concave
    // exactly when the oriented triangle's normal agrees with the vertex normal.
    return nt.dot(sums[i]) > 0 ? 2 * M_PI - theta : theta;
  };
  auto earNormal = [&](int i) {
    // The new triangle (next, i, prev) runs against the loop.
    return Eigen::Vector3d((loop[i] - loop[next[i]]).cross(loop[prev[i]] - loop[next[i]]));
  };

  int alive = n, start = 0;
  while (alive > 3) {
    int best = -1;
    for (int pass = 0; pass < 3 && best < 0; ++pass) {
      double bestAngle = std::numeric_limits<double>::infinity();
      int i = start;
      for (int k = 0; k < alive; ++k, i = next[i]) {
        if (joined(prev[i], next[i])) continue;
        if (pass == 0) {
          const Eigen::Vector3d &na = sums[prev[i]], &nb = sums[next[i]];
          if (na.squaredNorm() > 0 && nb.squaredNorm() > 0 && angleBetween(na, nb) > result.sigma) continue;
        }
        if (pass <= 1) {
          const Eigen::Vector3d ne = earNormal(i);
          const double len = ne.norm();
          if (!(len > 0)) continue;
          const double cosFold = std::cos(options.maxFoldAngle);
          if (ne.dot(across[prev[i]]) < cosFold * len || ne.dot(across[i]) < cosFold * len) continue;
        }
        const double a = earAngle(i);
        if (a < bestAngle) { bestAngle = a; best = i; }
      }
      if (best >= 0 && pass == 1) ++result.earsWithoutSigma;
      if (best >= 0 && pass == 2) ++result.earsWithFold;
    }
    if (best < 0)
      throw Error("the hole cannot be triangulated without duplicating an existing edge (" + std::to_string(alive) +
                  " boundary vertices left); the mesh around it is folded onto itself");
    const int a = prev[best], b = next[best];
    result.triangles.push_back({b, best, a});
    const Eigen::Vector3d ne = earNormal(best);
    for (int v : {a, best, b}) sums[v] += ne;
    newEdges.insert({std::min(a, b), std::max(a, b)});
    across[a] = ne.normalized();
    next[a] = b;
    prev[b] = a;
    start = a;
    --alive;
  }
  const int a = prev[start], c = next[start];
  result.triangles.push_back({c, start, a});
  return result;
}

}  // namespace holefill
