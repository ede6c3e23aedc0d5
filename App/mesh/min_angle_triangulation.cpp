#include "mesh/min_angle_triangulation.h"

#include <cmath>
#include <limits>
#include <set>
#include <tuple>

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
  // The largest angle between two boundary normals: the pair of least dot product, then its angle
  // measured as everywhere else (a quadratic scan of dot products, not of angles: atan2 was 12%
  // of a 5,000-vertex hole's fill when every pair got one).
  double spread = 0, leastDot = std::numeric_limits<double>::infinity();
  int pi = -1, pj = -1;
  for (int i = 0; i < n; ++i) {
    if (normal[i].squaredNorm() == 0) continue;
    for (int j = i + 1; j < n; ++j) {
      const double d = normal[i].dot(normal[j]);
      if (normal[j].squaredNorm() > 0 && d < leastDot) { leastDot = d; pi = i; pj = j; }
    }
  }
  if (pi >= 0) spread = angleBetween(normal[pi], normal[pj]);
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
  // An ear's pass: 0 when it passes every test, 1 without σ, 2 without σ and the fold test, 3 when
  // its new edge exists. The ear cut is the one of least (pass, angle), which is the paper's rule
  // with the relaxations of the header. A cut changes the tests of the four ears around it only, so
  // the ears are kept ordered and those four re-keyed: linear-logarithmic in the hole's size
  // instead of a quadratic rescan (a 5,000-vertex hole took 6 s).
  const double cosFold = std::cos(options.maxFoldAngle);
  auto pass = [&](int i) {
    if (joined(prev[i], next[i])) return 3;
    const Eigen::Vector3d ne = earNormal(i);
    const double len = ne.norm();
    const bool folds = !(len > 0) || ne.dot(across[prev[i]]) < cosFold * len || ne.dot(across[i]) < cosFold * len;
    if (folds) return 2;
    const Eigen::Vector3d &na = sums[prev[i]], &nb = sums[next[i]];
    return na.squaredNorm() > 0 && nb.squaredNorm() > 0 && angleBetween(na, nb) > result.sigma ? 1 : 0;
  };
  using Key = std::tuple<int, double, int>;  // pass, angle, vertex
  std::set<Key> ears;
  std::vector<Key> keyOf(n);
  auto key = [&](int i) {
    const double angle = earAngle(i);  // NaN (coincident points) would break the set's order
    return Key(pass(i), std::isnan(angle) ? std::numeric_limits<double>::infinity() : angle, i);
  };
  auto rekey = [&](int i) {
    ears.erase(keyOf[i]);
    keyOf[i] = key(i);
    ears.insert(keyOf[i]);
  };
  for (int i = 0; i < n; ++i) ears.insert(keyOf[i] = key(i));

  int alive = n, last = 0;
  while (alive > 3) {
    const auto least = ears.begin();
    const int p = std::get<0>(*least);
    int best = std::get<2>(*least);
    const auto tied = [&](const Key& k) { return std::get<0>(k) == p && std::get<1>(k) == std::get<1>(*least); };
    if (std::next(least) != ears.end() && tied(*std::next(least))) {
      // Equal angles (a hole in a regular grid has many): the first tied ear met walking the loop
      // from the last cut, so the cuts advance as one front, as the paper's scan does.
      int i = last;
      for (int k = 0; k < alive; ++k, i = next[i])
        if (tied(keyOf[i])) { best = i; break; }
    }
    if (p == 3)
      throw Error("the hole cannot be triangulated without duplicating an existing edge (" + std::to_string(alive) +
                  " boundary vertices left); the mesh around it is folded onto itself");
    if (p == 1) ++result.earsWithoutSigma;
    if (p == 2) ++result.earsWithFold;
    const int a = prev[best], b = next[best];
    result.triangles.push_back({b, best, a});
    const Eigen::Vector3d ne = earNormal(best);
    for (int v : {a, best, b}) sums[v] += ne;
    newEdges.insert({std::min(a, b), std::max(a, b)});
    across[a] = ne.normalized();
    next[a] = b;
    prev[b] = a;
    ears.erase(keyOf[best]);
    for (int v : {prev[a], a, b, next[b]}) rekey(v);
    last = a;
    --alive;
  }
  const int start = last;
  const int a = prev[start], c = next[start];
  result.triangles.push_back({c, start, a});
  return result;
}

}  // namespace holefill
