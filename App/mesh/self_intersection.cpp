#include "mesh/self_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>

namespace holefill {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int, CGAL::Box_intersection_d::ID_EXPLICIT>;

Box boxOf(const TriangleMesh& mesh, int t) {
  double lo[3], hi[3];
  for (int d = 0; d < 3; ++d) {
    lo[d] = hi[d] = mesh.vertices(mesh.triangles(t, 0), d);
    for (int k = 1; k < 3; ++k) {
      lo[d] = std::min(lo[d], mesh.vertices(mesh.triangles(t, k), d));
      hi[d] = std::max(hi[d], mesh.vertices(mesh.triangles(t, k), d));
    }
  }
  return Box(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), t);
}

}  // namespace

SelfIntersections selfIntersections(const TriangleMesh& mesh, const std::vector<bool>& subject, size_t limit) {
  SelfIntersections r;
  const int nt = static_cast<int>(mesh.triangles.rows());
  const auto isSubject = [&](int t) { return subject.empty() || subject[t]; };
  // The triangles that can meet a subject: the subjects and those whose boxes overlap theirs.
  std::vector<Box> subjects, others;
  for (int t = 0; t < nt; ++t) (isSubject(t) ? subjects : others).push_back(boxOf(mesh, t));
  if (subjects.empty()) return r;
  std::vector<std::pair<int, int>> candidates;
  const auto collect = [&](const Box& a, const Box& b) { candidates.emplace_back(a.info(), b.info()); };
  CGAL::box_self_intersection_d(subjects.begin(), subjects.end(), collect);  // each pair once
  if (!others.empty()) CGAL::box_intersection_d(subjects.begin(), subjects.end(), others.begin(), others.end(), collect);
  // Vertices at exactly one position are one: a seam's copies, or a fill's vertex against its
  // copy across a seam, touch there and do not cross.
  std::vector<char> used(static_cast<size_t>(nt), 0);
  for (const Box& b : subjects) used[b.info()] = 1;
  for (const auto& [a, b] : candidates) used[b] = 1;
  std::vector<int> involved;
  for (int t = 0; t < nt; ++t)
    if (used[t])
      for (int k = 0; k < 3; ++k) involved.push_back(mesh.triangles(t, k));
  std::sort(involved.begin(), involved.end());
  involved.erase(std::unique(involved.begin(), involved.end()), involved.end());
  const std::vector<int> site = weldMap(mesh.vertices, 0.0, involved);
  const auto point = [&](int v) { return Point(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)); };
  const auto corners = [&](int t) { return std::array<int, 3>{site[mesh.triangles(t, 0)], site[mesh.triangles(t, 1)], site[mesh.triangles(t, 2)]}; };
  std::vector<std::pair<int, int>> found;
  // A subject with no area crosses itself (a fill that collapses a triangle), as CGAL's
  // self_intersections reports it.
  for (const Box& b : subjects) {
    const auto c = corners(b.info());
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;  // repeated corners: no triangle to test
    if (CGAL::collinear(point(c[0]), point(c[1]), point(c[2]))) found.emplace_back(b.info(), b.info());
  }
  // Each pair with a subject once, tested
  // exactly as CGAL PMP's self_intersections tests faces: triangles sharing an edge cross only
  // where they fold onto each other (coplanar, on one side of it); sharing a vertex, where either's
  // opposite side meets the other; otherwise where they meet at all.
  for (auto& [a, b] : candidates) {
    if (a == b) continue;
    const auto p = corners(a), q = corners(b);
    if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2] || q[0] == q[1] || q[1] == q[2] || q[0] == q[2]) continue;
    int sharedP[3], sharedQ[3], shared = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (p[i] == q[j]) sharedP[shared] = i, sharedQ[shared] = j, ++shared;
    bool crossing = false;
    if (shared == 3) {
      ++r.skippedTriangles;  // the same triangle twice: coincident, not crossing
      continue;
    } else if (shared == 2) {
      const int pa = p[sharedP[0]], pb = p[sharedP[1]], pc = p[3 - sharedP[0] - sharedP[1]], qc = q[3 - sharedQ[0] - sharedQ[1]];
      crossing = CGAL::coplanar(point(pa), point(pb), point(pc), point(qc)) &&
                 CGAL::coplanar_orientation(point(pa), point(pb), point(pc), point(qc)) == CGAL::POSITIVE;
    } else if (shared == 1) {
      const int i = sharedP[0], j = sharedQ[0];
      const K::Triangle_3 tp(point(p[0]), point(p[1]), point(p[2])), tq(point(q[0]), point(q[1]), point(q[2]));
      crossing = CGAL::do_intersect(tp, K::Segment_3(point(q[(j + 1) % 3]), point(q[(j + 2) % 3]))) ||
                 CGAL::do_intersect(tq, K::Segment_3(point(p[(i + 1) % 3]), point(p[(i + 2) % 3])));
    } else {
      crossing = CGAL::do_intersect(K::Triangle_3(point(p[0]), point(p[1]), point(p[2])), K::Triangle_3(point(q[0]), point(q[1]), point(q[2])));
    }
    if (crossing) found.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  if (found.size() > limit) found.resize(limit);
  r.pairs = std::move(found);
  return r;
}

}  // namespace holefill
