#include "mesh/self_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <iterator>
#include <unordered_map>

namespace holefill {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int, CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;

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
  std::vector<bool> local(nt, false);
  std::vector<Box> subjects, others;
  for (int t = 0; t < nt; ++t) (isSubject(t) ? subjects : others).push_back(boxOf(mesh, t));
  if (subjects.empty()) return r;
  for (const Box& b : subjects) local[b.info()] = true;
  if (!others.empty())
    CGAL::box_intersection_d(subjects.begin(), subjects.end(), others.begin(), others.end(),
                             [&](const Box&, const Box& o) { local[o.info()] = true; });
  // The local mesh, on the mesh's own vertex indices (shared edges and vertices stay shared), and
  // vertices at exactly one position taken as one: a seam's copies, or a fill's vertex against its
  // copy across a seam, touch there and do not cross.
  std::vector<int> localVertices;
  for (int t = 0; t < nt; ++t)
    if (local[t])
      for (int k = 0; k < 3; ++k) localVertices.push_back(mesh.triangles(t, k));
  std::sort(localVertices.begin(), localVertices.end());
  localVertices.erase(std::unique(localVertices.begin(), localVertices.end()), localVertices.end());
  const std::vector<int> site = weldMap(mesh.vertices, 0.0, localVertices);
  Mesh sm;
  std::unordered_map<int, Mesh::Vertex_index> vertexOf;
  std::vector<int> triangleOf;  // face index of sm -> triangle of mesh
  const auto vertex = [&](int v) {
    v = site[v];
    auto it = vertexOf.find(v);
    if (it != vertexOf.end()) return it->second;
    const Mesh::Vertex_index h = sm.add_vertex(K::Point_3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)));
    return vertexOf.emplace(v, h).first->second;
  };
  // Subjects first: where a subject and an old triangle cannot both join, the subject is kept.
  std::vector<int> order;
  for (int t = 0; t < nt; ++t)
    if (local[t] && isSubject(t)) order.push_back(t);
  for (int t = 0; t < nt; ++t)
    if (local[t] && !isSubject(t)) order.push_back(t);
  for (int t : order) {
    const Mesh::Vertex_index a = vertex(mesh.triangles(t, 0)), b = vertex(mesh.triangles(t, 1)), c = vertex(mesh.triangles(t, 2));
    const Mesh::Face_index f = a == b || b == c || a == c ? Mesh::null_face() : sm.add_face(a, b, c);
    if (f == Mesh::null_face()) {
      ++r.skippedTriangles;
      continue;
    }
    if (static_cast<size_t>(f.idx()) >= triangleOf.size()) triangleOf.resize(f.idx() + 1, -1);
    triangleOf[f.idx()] = t;
  }
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> found;
  CGAL::Polygon_mesh_processing::self_intersections(faces(sm), sm, std::back_inserter(found));
  for (const auto& [a, b] : found) {
    const int ta = triangleOf[a.idx()], tb = triangleOf[b.idx()];
    if (!isSubject(ta) && !isSubject(tb)) continue;  // the input's own, not the fill's
    r.pairs.emplace_back(std::min(ta, tb), std::max(ta, tb));
    if (r.pairs.size() >= limit) break;
  }
  std::sort(r.pairs.begin(), r.pairs.end());
  return r;
}

}  // namespace holefill
