#include "fitting/domain_extension.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Sparse>
#include <cmath>
#include <map>

#include "geometry/error.h"
#include "mesh/mesh_holes.h"
#include "mesh/mesh_topology.h"

namespace holefill {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Winding number of the region's boundary loops around q: nonzero inside the region's footprint.
int winding(const std::vector<std::vector<Eigen::Vector2d>>& loops, const Eigen::Vector2d& q) {
  int w = 0;
  for (const auto& loop : loops)
    for (size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
      const double cross = (b.x() - a.x()) * (q.y() - a.y()) - (q.x() - a.x()) * (b.y() - a.y());
      if (a.y() <= q.y() && b.y() > q.y() && cross > 0) ++w;
      if (a.y() > q.y() && b.y() <= q.y() && cross < 0) --w;
    }
  return w;
}

double segmentDistance(const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * d - q).norm();
}

}  // namespace

DomainExtension extendToRectangle(const TriangleMesh& region, const Eigen::MatrixX2d& uv, double width, double height,
                                  const DomainExtensionOptions& o) {
  validateMesh(region, "region");
  const int nv = static_cast<int>(region.vertices.rows()), nt = static_cast<int>(region.triangles.rows());
  if (uv.rows() != nv) throw Error("the parameterization has " + std::to_string(uv.rows()) + " points for " + std::to_string(nv) + " vertices");
  if (!uv.allFinite()) throw Error("the parameterization has a non-finite point");
  if (o.order != 2 && o.order != 3) throw Error("the extension order must be 2 (G1) or 3 (G2)");
  if (!(width > 0 && height > 0)) throw Error("the domain rectangle has no area");
  const MeshTopology topo(region);
  const MeshHoleReport holes = findMeshHoles(region, topo);

  // The region's boundary loops in uv, and its mean edge length there.
  std::vector<std::vector<Eigen::Vector2d>> loops;
  for (const auto& h : holes.holes) {
    loops.emplace_back();
    for (int v : h.loop) loops.back().push_back(uv.row(v).transpose());
  }
  double mean = 0;
  for (const auto& e : topo.edges()) mean += (uv.row(e.a) - uv.row(e.b)).norm();
  mean /= std::max<size_t>(1, topo.edges().size());
  const double h = o.spacing > 0 ? o.spacing : mean;

  DomainExtension out;
  out.regionVertices = nv;
  out.regionTriangles = nt;
  const double m = o.marginLayers * h;
  out.u0 = std::min(-m, uv.col(0).minCoeff());
  out.v0 = std::min(-m, uv.col(1).minCoeff());
  out.u1 = std::max(width + m, uv.col(0).maxCoeff());
  out.v1 = std::max(height + m, uv.col(1).maxCoeff());

  // Grid samples outside the footprint, kept half a spacing from its boundary (no slivers).
  std::vector<Eigen::Vector2d> fresh;
  std::map<std::pair<int, int>, int> freshAt;  // grid (i, j) → index into fresh
  const int cu = std::max(1, static_cast<int>(std::ceil((out.u1 - out.u0) / h))), cv = std::max(1, static_cast<int>(std::ceil((out.v1 - out.v0) / h)));
  for (int i = 0; i <= cu; ++i)
    for (int j = 0; j <= cv; ++j) {
      const Eigen::Vector2d q(out.u0 + (out.u1 - out.u0) * i / cu, out.v0 + (out.v1 - out.v0) * j / cv);
      if (winding(loops, q) != 0) continue;
      bool near = false;
      for (const auto& loop : loops)
        for (size_t k = 0; k < loop.size() && !near; ++k) near = segmentDistance(q, loop[k], loop[(k + 1) % loop.size()]) < 0.5 * h;
      if (!near) {
        freshAt[{i, j}] = static_cast<int>(fresh.size());
        fresh.push_back(q);
      }
    }

  // Constrained Delaunay triangulation of the boundary loops and the samples.
  CDT cdt;
  std::vector<CDT::Vertex_handle> handle(nv);
  for (const auto& hole : holes.holes)
    for (int v : hole.loop) {
      handle[v] = cdt.insert(CDT::Point(uv(v, 0), uv(v, 1)));
      handle[v]->info() = v;
    }
  for (size_t k = 0; k < fresh.size(); ++k) {
    auto vh = cdt.insert(CDT::Point(fresh[k].x(), fresh[k].y()));
    vh->info() = nv + static_cast<int>(k);
  }
  for (const auto& hole : holes.holes)
    for (size_t k = 0; k < hole.loop.size(); ++k) cdt.insert_constraint(handle[hole.loop[k]], handle[hole.loop[(k + 1) % hole.loop.size()]]);

  out.mesh.vertices.resize(nv + static_cast<Eigen::Index>(fresh.size()), 3);
  out.mesh.vertices.topRows(nv) = region.vertices;
  out.uv.resize(out.mesh.vertices.rows(), 2);
  out.uv.topRows(nv) = uv;
  for (size_t k = 0; k < fresh.size(); ++k) out.uv.row(nv + static_cast<Eigen::Index>(k)) = fresh[k].transpose();
  std::vector<Eigen::Vector3i> added;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    int id[3];
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) {
      id[k] = f->vertex(k)->info();
      if (id[k] < 0) throw Error("the extension met a point twice: the region's parameterization overlaps itself");
      c += out.uv.row(id[k]).transpose() / 3;
    }
    if (winding(loops, c) != 0) continue;  // the region's own triangles cover this
    // Flat faces (collinear points along the rectangle's rim and the region's boundary, which
    // CGAL may close with a zero-area face) carry no surface and would make the cotangent
    // weights infinite.
    const Eigen::Vector2d e1 = out.uv.row(id[1]) - out.uv.row(id[0]), e2 = out.uv.row(id[2]) - out.uv.row(id[0]);
    if (std::abs(e1.x() * e2.y() - e1.y() * e2.x()) <= 1e-9 * h * h) continue;
    added.emplace_back(id[0], id[1], id[2]);  // CGAL's faces are anticlockwise
  }
  out.mesh.triangles.resize(nt + static_cast<Eigen::Index>(added.size()), 3);
  out.mesh.triangles.topRows(nt) = region.triangles;
  for (size_t k = 0; k < added.size(); ++k) out.mesh.triangles.row(nt + static_cast<Eigen::Index>(k)) = added[k].transpose();

  // 3D: min |Lᵏ x|² over the new vertices, L the uv cotangent Laplacian of the extended mesh.
  const int N = static_cast<int>(out.mesh.vertices.rows()), nNew = N - nv;
  if (nNew == 0) return out;
  std::vector<Eigen::Triplet<double>> T;
  std::vector<double> diag(N, 0.0);
  for (Eigen::Index t = 0; t < out.mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = out.mesh.triangles(t, k), b = out.mesh.triangles(t, (k + 1) % 3), c = out.mesh.triangles(t, (k + 2) % 3);
      const Eigen::Vector2d u = out.uv.row(a) - out.uv.row(c), w = out.uv.row(b) - out.uv.row(c);
      const double cot = u.dot(w) / std::max(std::abs(u.x() * w.y() - u.y() * w.x()), 1e-300);
      const double wgt = 0.5 * cot;  // the weight of edge a-b from the corner at c
      T.emplace_back(a, b, wgt);
      T.emplace_back(b, a, wgt);
      diag[a] -= wgt;
      diag[b] -= wgt;
    }
  for (int v = 0; v < N; ++v) T.emplace_back(v, v, diag[v]);
  Eigen::SparseMatrix<double> L(N, N);
  L.setFromTriplets(T.begin(), T.end());
  // Δ = M⁻¹L (M the barycentric vertex areas), so Δ of a quadratic is constant; rows of vertices on
  // the extended mesh's outer boundary are dropped at every power (their one-sided Laplacian is
  // not zero even for a plane), so Δᵏ vanishes on linear data for k ≥ 1 and on quadratics for k ≥ 2.
  std::vector<double> area(N, 0.0);
  for (Eigen::Index t = 0; t < out.mesh.triangles.rows(); ++t) {
    const Eigen::Vector2d a = out.uv.row(out.mesh.triangles(t, 1)) - out.uv.row(out.mesh.triangles(t, 0));
    const Eigen::Vector2d b = out.uv.row(out.mesh.triangles(t, 2)) - out.uv.row(out.mesh.triangles(t, 0));
    const double third = std::abs(a.x() * b.y() - a.y() * b.x()) / 6;
    for (int k = 0; k < 3; ++k) area[out.mesh.triangles(t, k)] += third;
  }
  std::vector<int> rimCount(N, 0);
  const MeshTopology extended(out.mesh);
  for (const auto& e : extended.edges())
    if (e.count == 1) ++rimCount[e.a], ++rimCount[e.b];
  std::vector<Eigen::Triplet<double>> Dt;
  for (int v = 0; v < N; ++v)
    if (rimCount[v] == 0) Dt.emplace_back(v, v, 1.0 / std::max(area[v], 1e-300));
  Eigen::SparseMatrix<double> D(N, N);
  D.setFromTriplets(Dt.begin(), Dt.end());
  const Eigen::SparseMatrix<double> Delta = (D * L).pruned();
  Eigen::SparseMatrix<double> P = Delta;
  for (int k = 1; k < o.order; ++k) P = (Delta * P).pruned();
  // Columns of the new vertices (unknowns) and of the region's (known).
  const Eigen::SparseMatrix<double> Pn = P.rightCols(nNew);
  const Eigen::MatrixX3d known = P.leftCols(nv) * region.vertices;
  // Without the rim rows the new vertices along the rectangle's edges are under-determined:
  // k-th differences along the grid lines through the new vertices (zero on polynomials of
  // degree < k, so planes, and for k = 3 quadrics, are continued exactly) settle them; the
  // paper's isocurve fairness along the extension boundaries, here over all new grid lines.
  std::vector<Eigen::Triplet<double>> Ft;
  int frow = 0;
  // Differences of order k along each grid line; where a line of new vertices is too short for
  // them (a small cut corner), one order less, down to second differences.
  static const std::vector<std::vector<double>> diff = {{}, {}, {1, -2, 1}, {1, -3, 3, -1}};
  for (const auto& [ij, k0] : freshAt)
    for (int dir = 0; dir < 2; ++dir) {
      std::vector<int> run;
      for (int q = 0; q <= o.order; ++q) {
        const auto it = freshAt.find({ij.first + (dir == 0 ? q : 0), ij.second + (dir == 1 ? q : 0)});
        if (it == freshAt.end()) break;
        run.push_back(it->second);
      }
      int order = o.order;
      while (order >= 2 && static_cast<int>(run.size()) < order + 1) --order;
      if (order < 2) continue;
      if (order < o.order) {  // only where the longer stencil does not fit along this line at all
        const auto before = freshAt.find({ij.first - (dir == 0 ? 1 : 0), ij.second - (dir == 1 ? 1 : 0)});
        if (before != freshAt.end()) continue;  // this run's start is inside a line already covered
      }
      for (int q = 0; q <= order; ++q) Ft.emplace_back(frow, run[q], diff[order][q]);
      ++frow;
    }
  Eigen::SparseMatrix<double> F(frow, nNew);
  F.setFromTriplets(Ft.begin(), Ft.end());
  Eigen::SparseMatrix<double> A = Pn.transpose() * Pn;
  const double scale = std::max(1e-300, A.diagonal().cwiseAbs().maxCoeff());
  const Eigen::SparseMatrix<double> FtF = F.transpose() * F;
  const double fair = o.fairness * scale / std::max(1e-300, FtF.diagonal().cwiseAbs().maxCoeff());
  A += fair * FtF;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw Error("the polyharmonic extension's system is singular");
  const Eigen::MatrixX3d x = solver.solve(-(Pn.transpose() * known));
  if (!x.allFinite()) throw Error("the polyharmonic extension failed");
  out.mesh.vertices.bottomRows(nNew) = x;
  return out;
}

}  // namespace holefill
