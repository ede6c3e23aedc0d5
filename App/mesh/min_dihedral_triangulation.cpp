#include "mesh/min_dihedral_triangulation.h"

#include <limits>

#include "geometry/error.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

namespace {

struct Weight {
  double angle = 0, area = 0;  // compared in this order
  bool operator<(const Weight& o) const { return angle < o.angle || (angle == o.angle && area < o.area); }
  Weight operator+(const Weight& o) const { return {std::max(angle, o.angle), area + o.area}; }
};

const Weight kInfinite{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};

}  // namespace

std::vector<std::array<int, 3>> triangulateMinDihedral(const std::vector<Eigen::Vector3d>& loop,
                                                       const std::vector<Eigen::Vector3d>& outsideNormals,
                                                       const std::function<bool(int, int)>& edgeExists) {
  const int n = static_cast<int>(loop.size());
  if (n < 3) throw Error("a hole needs at least 3 boundary vertices, this one has " + std::to_string(n));
  // The new triangle over i < m < k runs (k, m, i), against the loop.
  auto normal = [&](int i, int m, int k) {
    const Eigen::Vector3d c = (loop[m] - loop[k]).cross(loop[i] - loop[k]);
    const double len = c.norm();
    return len > 0 ? Eigen::Vector3d(c / len) : Eigen::Vector3d::Zero();
  };
  std::vector<Weight> W(static_cast<size_t>(n) * n, Weight{});
  std::vector<int> O(static_cast<size_t>(n) * n, -1);
  auto at = [n](int i, int k) { return static_cast<size_t>(i) * n + k; };
  // The triangle on the other side of chord (i, j): the sub-solution's top triangle, or the
  // surrounding triangle when (i, j) is a loop edge.
  auto neighbourNormal = [&](int i, int j) {
    if (j == i + 1) return Eigen::Vector3d(outsideNormals[i]);
    return normal(i, O[at(i, j)], j);
  };
  for (int len = 2; len < n; ++len)
    for (int i = 0; i + len < n; ++i) {
      const int k = i + len;
      // Chord (i, k) must not repeat an edge the mesh has (unless it is the loop's closing edge).
      if (!(i == 0 && k == n - 1) && edgeExists(i, k)) {
        W[at(i, k)] = kInfinite;
        continue;
      }
      Weight best = kInfinite;
      int arg = -1;
      for (int m = i + 1; m < k; ++m) {
        const Weight& a = W[at(i, m)];
        const Weight& b = W[at(m, k)];
        if (!(a.angle < kInfinite.angle) || !(b.angle < kInfinite.angle)) continue;
        const Eigen::Vector3d nt = normal(i, m, k);
        const double area = 0.5 * (loop[m] - loop[k]).cross(loop[i] - loop[k]).norm();
        // A degenerate triangle (three collinear loop vertices, as on a straight run of the
        // boundary) has no normal: it weighs as the worst fold, taken only if nothing else fits.
        double dihedral = nt.squaredNorm() > 0 ? std::max(angleBetween(nt, neighbourNormal(i, m)), angleBetween(nt, neighbourNormal(m, k)))
                                               : M_PI;
        if (i == 0 && k == n - 1) dihedral = std::max(dihedral, angleBetween(nt, outsideNormals[n - 1]));
        const Weight w = a + b + Weight{dihedral, area};
        if (w < best) { best = w; arg = m; }
      }
      W[at(i, k)] = best;
      O[at(i, k)] = arg;
    }
  if (O[at(0, n - 1)] < 0) throw Error("the hole cannot be triangulated without repeating an existing edge");
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::pair<int, int>> stack = {{0, n - 1}};
  while (!stack.empty()) {
    const auto [i, k] = stack.back();
    stack.pop_back();
    if (k - i < 2) continue;
    const int m = O[at(i, k)];
    triangles.push_back({k, m, i});
    stack.emplace_back(i, m);
    stack.emplace_back(m, k);
  }
  return triangles;
}

}  // namespace holefill
