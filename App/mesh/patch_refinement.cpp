#include "mesh/patch_refinement.h"

#include <cmath>

#include "geometry/error.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

namespace {

// cot of the angle at r of triangle (p, q, r); +inf-like for a degenerate triangle.
double cotAt(const Eigen::Vector3d& r, const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const Eigen::Vector3d u = p - r, v = q - r;
  const double cross = u.cross(v).norm();
  return cross > 0 ? u.dot(v) / cross : (u.dot(v) >= 0 ? 1e300 : -1e300);
}

int opposite(const std::array<int, 3>& tri, int u, int v) {
  for (int x : tri)
    if (x != u && x != v) return x;
  return -1;
}

// Swaps edge (u, v) if the circumsphere test asks for it and the swap is valid.
bool relaxEdge(HolePatch& patch, PatchEdges& edges, int u, int v, const RefinementOptions& options) {
  const EdgeTriangles* on = edges.find(u, v);
  if (!on || on->size() != 2) return false;
  const int t0 = (*on)[0], t1 = (*on)[1];
  std::array<int, 3> A = patch.triangles[t0], B = patch.triangles[t1];
  const int r = opposite(A, u, v), s = opposite(B, u, v);
  if (r < 0 || s < 0 || r == s) return false;
  // Name the shared edge p→q as A runs it, so A = (p, q, r) and B = (q, p, s).
  int p = u, q = v;
  for (int k = 0; k < 3; ++k)
    if (A[k] == v && A[(k + 1) % 3] == u) { p = v; q = u; }
  const auto& P = patch.points;
  // s inside the circumsphere of (p, q, r) in the plane of the quad is the same as the two
  // angles facing the edge summing to more than π; unlike the two sphere tests, the angle sum
  // is symmetric in the triangles, so on a curved patch a swap is never undone by the next test.
  // For angles in (0, π), α + β > π exactly when cot α + cot β < 0 (no trigonometry needed).
  if (cotAt(P[r], P[p], P[q]) + cotAt(P[s], P[p], P[q]) >= -1e-9) return false;
  if (edges.has(r, s)) return false;
  if (!patch.isNew(r) && !patch.isNew(s) && patch.outsideEdge(r, s)) return false;
  const std::array<int, 3> C = {r, p, s}, D = {s, q, r};
  double areaA, areaB, areaC, areaD;
  const Eigen::Vector3d nA = patchTriangleNormal(patch, A, &areaA), nB = patchTriangleNormal(patch, B, &areaB);
  const Eigen::Vector3d nC = patchTriangleNormal(patch, C, &areaC), nD = patchTriangleNormal(patch, D, &areaD);
  if (!(areaC > 0) || !(areaD > 0)) return false;
  // The new pair must face the way the old pair did (no inverted triangle) and must not fold.
  const Eigen::Vector3d before = nA * areaA + nB * areaB;
  if (nC.dot(before) <= 0 || nD.dot(before) <= 0) return false;
  if (nC.dot(nD) < std::cos(options.maxFoldAngle)) return false;
  edges.remove(A, t0);
  edges.remove(B, t1);
  patch.triangles[t0] = C;
  patch.triangles[t1] = D;
  edges.add(C, t0);
  edges.add(D, t1);
  return true;
}

}  // namespace

int relaxEdges(HolePatch& patch, PatchEdges& edges, std::vector<std::pair<int, int>> work, const RefinementOptions& options,
               bool* capped) {
  // A swap can only break the test on the four outer edges of its quad, so those are all
  // that is rechecked: the same fixed point as sweeping every edge, at the cost of the changes.
  int swaps = 0;
  const long long budget = static_cast<long long>(options.maxRelaxPasses) * static_cast<long long>(patch.triangles.size() + 16);
  for (long long step = 0; !work.empty(); ++step) {
    if (step > budget) {
      if (capped) *capped = true;
      break;
    }
    const auto [u, v] = work.back();
    work.pop_back();
    const EdgeTriangles* on = edges.find(u, v);
    if (!on || on->size() != 2) continue;
    const int t0 = (*on)[0], t1 = (*on)[1];
    if (!relaxEdge(patch, edges, u, v, options)) continue;
    ++swaps;
    for (int t : {t0, t1}) {
      const auto& tri = patch.triangles[t];
      for (int k = 0; k < 3; ++k) work.emplace_back(tri[k], tri[(k + 1) % 3]);
    }
  }
  return swaps;
}

int relaxAllEdges(HolePatch& patch, PatchEdges& edges, const RefinementOptions& options, bool* capped) {
  std::vector<std::pair<int, int>> work;
  work.reserve(patch.triangles.size() * 3);
  for (const auto& tri : patch.triangles)
    for (int k = 0; k < 3; ++k)
      if (tri[k] < tri[(k + 1) % 3]) work.emplace_back(tri[k], tri[(k + 1) % 3]);
  return relaxEdges(patch, edges, std::move(work), options, capped);
}

RefinementResult refinePatch(HolePatch& patch, const RefinementOptions& options) {
  RefinementResult result;
  HF_CHECK(patch.scale.size() == patch.points.size(), "every patch vertex needs a scale");
  PatchEdges edges(patch);
  const double alpha = options.densityFactor;
  // Relaxing the bare triangulation first gives small holes, which never split, the same
  // Delaunay-like shape as large ones.
  result.swaps += relaxAllEdges(patch, edges, options, &result.capped);
  for (; result.rounds < options.maxRounds; ++result.rounds) {
    int created = 0;
    std::vector<std::pair<int, int>> touched;  // edges a split made: the only ones the full relaxation can swap first
    const size_t count = patch.triangles.size();
    for (size_t t = 0; t < count; ++t) {
      const std::array<int, 3> tri = patch.triangles[t];
      const auto &a = patch.points[tri[0]], &b = patch.points[tri[1]], &c = patch.points[tri[2]];
      const Eigen::Vector3d centre = (a + b + c) / 3;
      const double sc = (patch.scale[tri[0]] + patch.scale[tri[1]] + patch.scale[tri[2]]) / 3;
      bool split = maxInnerAngle(a, b, c) < options.maxSplitAngle;
      for (int k = 0; k < 3 && split; ++k) {
        const double d = alpha * (centre - patch.points[tri[k]]).norm();
        split = d > sc && d > patch.scale[tri[k]];
      }
      if (!split) continue;
      if (static_cast<int>(patch.points.size()) - patch.boundaryCount >= options.maxVertices)
        throw Error("the hole needs more than " + std::to_string(options.maxVertices) +
                    " new vertices at the surrounding density; is the mesh scale sane?");
      const int m = static_cast<int>(patch.points.size());
      patch.points.push_back(centre);
      patch.scale.push_back(sc);
      const std::array<int, 3> t0 = {m, tri[1], tri[2]}, t1 = {tri[0], m, tri[2]}, t2 = {tri[0], tri[1], m};
      edges.remove(tri, static_cast<int>(t));
      patch.triangles[t] = t0;
      edges.add(t0, static_cast<int>(t));
      patch.triangles.push_back(t1);
      edges.add(t1, static_cast<int>(patch.triangles.size() - 1));
      patch.triangles.push_back(t2);
      edges.add(t2, static_cast<int>(patch.triangles.size() - 1));
      std::vector<std::pair<int, int>> old;
      for (int k = 0; k < 3; ++k) old.emplace_back(tri[k], tri[(k + 1) % 3]);
      result.swaps += relaxEdges(patch, edges, std::move(old), options, &result.capped);
      ++result.splits;
      ++created;
    }
    if (created == 0) break;
    // Step 4 of the paper relaxes all interior edges; edges no split touched already passed
    // the test, and relaxEdges follows every swap to its neighbours, so this is the same.
    for (const auto& tri : patch.triangles)
      if (tri[0] >= static_cast<int>(patch.points.size()) - created || tri[1] >= static_cast<int>(patch.points.size()) - created ||
          tri[2] >= static_cast<int>(patch.points.size()) - created)
        for (int k = 0; k < 3; ++k) touched.emplace_back(tri[k], tri[(k + 1) % 3]);
    result.swaps += relaxEdges(patch, edges, std::move(touched), options, &result.capped);
  }
  if (result.rounds >= options.maxRounds) result.capped = true;
  return result;
}

}  // namespace holefill
