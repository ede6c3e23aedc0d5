#include "fitting/cloud_boundary.h"

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "geometry/error.h"

namespace holefill {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb0 = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Vb = CGAL::Alpha_shape_vertex_base_2<K, Vb0>;
using Fb = CGAL::Alpha_shape_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;
using AlphaShape = CGAL::Alpha_shape_2<Dt>;

int findRoot(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}
}  // namespace

CloudBoundary detectCloudBoundary(const Eigen::MatrixX3d& points, const CloudBoundaryOptions& o) {
  const int n = static_cast<int>(points.rows());
  if (n < 10) throw Error("the cloud has " + std::to_string(n) + " points; finding its boundary needs at least 10");
  if (!points.allFinite()) throw Error("the cloud has a non-finite coordinate");
  if (!(o.alphaSpacings > 0)) throw Error("the alpha radius must be positive");
  const Eigen::RowVector3d c = points.colwise().mean();
  const Eigen::MatrixX3d q = points.rowwise() - c;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(q.transpose() * q);
  const Eigen::Vector3d e1 = eig.eigenvectors().col(2), e2 = eig.eigenvectors().col(1);
  if (!(eig.eigenvalues()(1) > 1e-24 * std::max(1.0, eig.eigenvalues()(2)))) throw Error("the cloud spans no area: its points lie on a line");

  std::vector<std::pair<K::Point_2, int>> pts;
  for (int k = 0; k < n; ++k) pts.emplace_back(K::Point_2(q.row(k).dot(e1), q.row(k).dot(e2)), k);
  Dt dt(pts.begin(), pts.end());
  if (static_cast<int>(dt.number_of_vertices()) != n)
    throw Error("some points of the cloud coincide in its plane: remove duplicates first (" + std::to_string(n - int(dt.number_of_vertices())) + " of them)");
  std::vector<double> lengths;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) lengths.push_back(std::sqrt(dt.segment(*e).squared_length()));
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  CloudBoundary out;
  out.spacing = lengths[lengths.size() / 2];
  const double r = o.alphaSpacings * out.spacing;
  AlphaShape shape(pts.begin(), pts.end(), r * r, AlphaShape::REGULARIZED);

  // Boundary edges, grouped into connected components; the largest is the outer boundary.
  std::vector<std::pair<int, int>> edges;
  for (auto it = shape.alpha_shape_edges_begin(); it != shape.alpha_shape_edges_end(); ++it) {
    const auto f = it->first;
    const int i = it->second;
    edges.emplace_back(f->vertex(shape.cw(i))->info(), f->vertex(shape.ccw(i))->info());
  }
  if (edges.size() < 3) throw Error("the cloud's alpha shape has no boundary loop: is it a surface patch?");
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [a, b] : edges) parent[findRoot(parent, a)] = findRoot(parent, b);
  std::map<int, int> size;
  for (const auto& [a, b] : edges) ++size[findRoot(parent, a)];
  const int outer = std::max_element(size.begin(), size.end(), [](auto& x, auto& y) { return x.second < y.second; })->first;
  out.boundary.assign(n, false);
  for (const auto& [a, b] : edges)
    if (findRoot(parent, a) == outer) out.boundary[a] = out.boundary[b] = true;
  out.count = static_cast<int>(std::count(out.boundary.begin(), out.boundary.end(), true));
  return out;
}

}  // namespace holefill
