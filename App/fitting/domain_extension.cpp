#include "fitting/domain_extension.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Sparse>
#include <cmath>
#include <map>
#include <set>

#include "geometry/error.h"
#include "geometry/polygon2d.h"
#include "mesh/mesh_holes.h"
#include "mesh/mesh_topology.h"

namespace holefill {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexId {
  int id = -1;  // the padded mesh's vertex; -1: not placed by us
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Constraints that cross would need constructed intersection points, which an inexact kernel
// places where CGAL's own predicates then contradict (a SIGSEGV in find_intersected_faces on
// regions whose map folded at the boundary): crossing constraints throw instead.
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;

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

}  // namespace

DomainExtension extendToRectangle(const TriangleMesh& region, const Eigen::MatrixX2d& uv, double width, double height,
                                  const DomainExtensionOptions& o) {
  validateMesh(region, "region");
  const int nv = static_cast<int>(region.vertices.rows()), nt = static_cast<int>(region.triangles.rows());
  if (uv.rows() != nv) throw Error("the parameterization has " + std::to_string(uv.rows()) + " points for " + std::to_string(nv) + " vertices");
  if (!uv.allFinite()) throw Error("the parameterization has a non-finite point");
  if (o.order != 2 && o.order != 3) throw Error("the extension order must be 2 (G1) or 3 (G2)");
  if (!(o.spacing >= 0 && o.clearance >= 0 && std::isfinite(o.spacing) && std::isfinite(o.clearance)))
    throw Error("the extension's grid spacing and clearance must be zero (automatic) or positive");
  if (!(o.marginWidth >= 0 && std::isfinite(o.marginWidth)) || o.marginLayers < 0)
    throw Error("the extension's margin must be zero or positive");
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
  double h = o.spacing > 0 ? o.spacing : mean;

  DomainExtension out;
  out.regionVertices = nv;
  out.regionTriangles = nt;
  const double m = std::max(o.marginLayers * h, o.marginWidth);
  out.u0 = std::min(-m, uv.col(0).minCoeff());
  out.v0 = std::min(-m, uv.col(1).minCoeff());
  out.u1 = std::max(width + m, uv.col(0).maxCoeff());
  out.v1 = std::max(height + m, uv.col(1).maxCoeff());

  // Grid samples outside the footprint, kept `clearance` from its boundary (no slivers), over
  // the rectangle and `pad` layers beyond it. The extension is solved on the padded grid and then
  // cropped to the rectangle: the region's labeled sides lie on the rectangle's rim, and solved
  // there, the new vertices next to them would have no whole stencil (a one-sided Laplacian is
  // not zero even on a plane) and were left under-determined (measured: 1.2 off on a cylinder
  // whose region was mapped exactly). Beyond the rectangle they continue the region instead.
  // At most 16 grid nodes per region vertex, and 10,000 more: the extension only supplies data
  // where the region has none, for a fit whose control net is far coarser. A map stretched far
  // past its region's own edges (found by fuzzing: a region of 1,140 vertices) otherwise asked for
  // a grid whose factorization took 321 s and 1.6 GB (19 s with the bound).
  if (const double nodes = (out.u1 - out.u0) * (out.v1 - out.v0) / (h * h), most = 16.0 * nv + 10000; nodes > most)
    h *= std::sqrt(nodes / most);
  const int pad = o.order + 1;
  const double clearance = o.clearance > 0 ? o.clearance : 0.5 * h;
  const int cu = std::max(1, static_cast<int>(std::ceil((out.u1 - out.u0) / h))), cv = std::max(1, static_cast<int>(std::ceil((out.v1 - out.v0) / h)));
  const double hu = (out.u1 - out.u0) / cu, hv = (out.v1 - out.v0) / cv;
  out.spacing = std::max(hu, hv);
  std::vector<Eigen::Vector2d> fresh;
  std::map<std::pair<int, int>, int> freshAt;  // grid (i, j) → index into fresh
  for (int i = -pad; i <= cu + pad; ++i)
    for (int j = -pad; j <= cv + pad; ++j) {
      const Eigen::Vector2d q(out.u0 + hu * i, out.v0 + hv * j);
      if (winding(loops, q) != 0) continue;
      bool near = false;
      for (const auto& loop : loops)
        for (size_t k = 0; k < loop.size() && !near; ++k) near = segmentDistance(q, loop[k], loop[(k + 1) % loop.size()]) < clearance;
      if (!near) {
        freshAt[{i, j}] = static_cast<int>(fresh.size());
        fresh.push_back(q);
      }
    }

  // Constrained Delaunay triangulation of the boundary loops and the samples. The loops must be
  // simple and apart in the domain: a map that folds at the boundary has them cross, and no
  // triangulation of the outside exists.
  for (size_t a = 0; a < loops.size(); ++a) {
    if (selfIntersects(loops[a]))
      throw Error("the region's map into the domain folds at its boundary (a boundary loop crosses itself): the extension "
                  "cannot be built; fit without extension or label the region differently");
    for (size_t b = a + 1; b < loops.size(); ++b)
      if (loopsCross(loops[a], loops[b]))
        throw Error("the region's map into the domain folds at its boundary (two boundary loops cross): the extension "
                    "cannot be built; fit without extension or label the region differently");
  }
  CDT cdt;
  std::vector<CDT::Vertex_handle> handle(nv);
  std::vector<CDT::Vertex_handle> freshHandle(fresh.size());
  try {
    for (const auto& hole : holes.holes)
      for (int v : hole.loop) {
        handle[v] = cdt.insert(CDT::Point(uv(v, 0), uv(v, 1)));
        if (handle[v]->info().id >= 0 && handle[v]->info().id != v)
          throw Error("the region's map into the domain sends two boundary vertices to one point, so the extension cannot be built: "
                      "a labeled side squeezed to nothing does that (move its corner labels apart), or fit without the extension");
        handle[v]->info().id = v;
      }
    for (size_t k = 0; k < fresh.size(); ++k) {
      freshHandle[k] = cdt.insert(CDT::Point(fresh[k].x(), fresh[k].y()));
      if (freshHandle[k]->info().id >= 0)
        throw Error("the region's map overlaps itself, so the extension cannot be built around it: labels whose corners sit where "
                    "the boundary doubles back fold the map there (move those corners), or fit without the extension");
      freshHandle[k]->info().id = nv + static_cast<int>(k);
    }
    for (const auto& hole : holes.holes)
      for (size_t k = 0; k < hole.loop.size(); ++k)
        cdt.insert_constraint(handle[hole.loop[k]], handle[hole.loop[(k + 1) % hole.loop.size()]]);
  } catch (const CDT::Intersection_of_constraints_exception&) {
    throw Error("the region's map into the domain folds at its boundary (boundary edges cross): the extension cannot be "
                "built; fit without extension or label the region differently");
  }
  // Every vertex is one of ours, at its own place (no constraint was split at a new point).
  for (auto it = cdt.finite_vertices_begin(); it != cdt.finite_vertices_end(); ++it) {
    const CDT::Vertex_handle v = it;
    const int i = v->info().id;
    const bool ours = i >= 0 && ((i < nv && handle[i] == v) || (i >= nv && i - nv < static_cast<int>(fresh.size()) &&
                                                                  freshHandle[i - nv] == v));
    if (!ours) throw Error("the extension's triangulation met a point it did not place: the region's parameterization overlaps itself");
  }

  TriangleMesh padded;
  padded.vertices.resize(nv + static_cast<Eigen::Index>(fresh.size()), 3);
  padded.vertices.topRows(nv) = region.vertices;
  padded.vertices.bottomRows(static_cast<Eigen::Index>(fresh.size())).rowwise() = region.vertices.colwise().mean();  // until placed
  Eigen::MatrixX2d puv(padded.vertices.rows(), 2);
  puv.topRows(nv) = uv;
  for (size_t k = 0; k < fresh.size(); ++k) puv.row(nv + static_cast<Eigen::Index>(k)) = fresh[k].transpose();
  std::vector<Eigen::Vector3i> added;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    int id[3];
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) {
      id[k] = f->vertex(k)->info().id;
      if (id[k] < 0)
        throw Error("the region's map overlaps itself, so the extension cannot be built around it: labels whose corners sit where "
                    "the boundary doubles back fold the map there (move those corners), or fit without the extension");
      c += puv.row(id[k]).transpose() / 3;
    }
    if (winding(loops, c) != 0) continue;  // the region's own triangles cover this
    // Flat faces (collinear points along the grid's rim and the region's boundary, which CGAL may
    // close with a zero-area face) carry no surface and would make the cotangent weights infinite.
    const Eigen::Vector2d e1 = puv.row(id[1]) - puv.row(id[0]), e2 = puv.row(id[2]) - puv.row(id[0]);
    if (std::abs(e1.x() * e2.y() - e1.y() * e2.x()) <= 1e-9 * h * h) continue;
    added.emplace_back(id[0], id[1], id[2]);  // CGAL's faces are anticlockwise
  }
  padded.triangles.resize(nt + static_cast<Eigen::Index>(added.size()), 3);
  padded.triangles.topRows(nt) = region.triangles;
  for (size_t k = 0; k < added.size(); ++k) padded.triangles.row(nt + static_cast<Eigen::Index>(k)) = added[k].transpose();

  // 3D: min |Δᵏ x|² over the new vertices. Δ is the uv cotangent Laplacian over mixed Voronoi
  // areas (Meyer et al.: circumcentric cells, halved at obtuse triangles), taken as the
  // five-point stencil at grid nodes whose four grid neighbours exist (what the cotangent
  // Laplacian is there, whichever diagonals the triangulation chose), so that it is exact on
  // bicubics on the grid.
  const int N = static_cast<int>(padded.vertices.rows()), nNew = N - nv;
  if (nNew > 0 && o.continueSurface) {
    // Triangles the map flattened (three boundary vertices on one side of the rectangle; a
    // sliver the flattening squeezed to nothing) have no cotangents and no area: left out of the
    // Laplacian, whose weights they made infinite (27 of the corpus's 63 regions stopped on a
    // "singular" system whose entries were inf).
    // Twice each triangle's uv area, once: the cotangents' denominator and the Voronoi areas'.
    std::vector<double> twice(padded.triangles.rows());
    std::vector<char> flat(padded.triangles.rows(), 0);
    for (Eigen::Index t = 0; t < padded.triangles.rows(); ++t) {
      const Eigen::Vector2d e1 = puv.row(padded.triangles(t, 1)) - puv.row(padded.triangles(t, 0));
      const Eigen::Vector2d e2 = puv.row(padded.triangles(t, 2)) - puv.row(padded.triangles(t, 0));
      twice[t] = std::abs(e1.x() * e2.y() - e1.y() * e2.x());
      flat[t] = twice[t] <= 1e-10 * h * h;
    }
    std::vector<Eigen::Triplet<double>> T;
    std::vector<double> diag(N, 0.0);
    for (Eigen::Index t = 0; t < padded.triangles.rows(); ++t)
      for (int k = 0; k < 3 && !flat[t]; ++k) {
        const int a = padded.triangles(t, k), b = padded.triangles(t, (k + 1) % 3), c = padded.triangles(t, (k + 2) % 3);
        const Eigen::Vector2d u = puv.row(a) - puv.row(c), w = puv.row(b) - puv.row(c);
        const double cot = u.dot(w) / twice[t];
        const double wgt = 0.5 * cot;  // the weight of edge a-b from the corner at c
        T.emplace_back(a, b, wgt);
        T.emplace_back(b, a, wgt);
        diag[a] -= wgt;
        diag[b] -= wgt;
      }
    for (int v = 0; v < N; ++v) T.emplace_back(v, v, diag[v]);
    Eigen::SparseMatrix<double, Eigen::RowMajor> L(N, N);
    L.setFromTriplets(T.begin(), T.end());
    std::vector<double> area(N, 0.0);
    for (Eigen::Index t = 0; t < padded.triangles.rows(); ++t) {
      if (flat[t]) continue;
      Eigen::Vector2d p[3];
      for (int k = 0; k < 3; ++k) p[k] = puv.row(padded.triangles(t, k)).transpose();
      int obtuse = -1;
      for (int k = 0; k < 3; ++k)
        if ((p[(k + 1) % 3] - p[k]).dot(p[(k + 2) % 3] - p[k]) < 0) obtuse = k;
      for (int k = 0; k < 3; ++k) {
        const int v = padded.triangles(t, k);
        if (obtuse >= 0) {
          area[v] += twice[t] / (obtuse == k ? 4 : 8);
          continue;
        }
        for (int side : {1, 2}) {  // the circumcentric cell: |e|² cot(opposite angle) / 8 for both edges at k
          const Eigen::Vector2d b = p[(k + side) % 3], c = p[(k + 3 - side) % 3];
          area[v] += (b - p[k]).squaredNorm() * (p[k] - c).dot(b - c) / twice[t] / 8;
        }
      }
    }
    std::vector<int> rimCount(N, 0);
    const MeshTopology paddedTopology(padded);
    for (const auto& e : paddedTopology.edges())
      if (e.count == 1) ++rimCount[e.a], ++rimCount[e.b];

    // Rows of Δ: the five-point stencil where the four grid neighbours exist, the triangulation's
    // at other vertices off its rim, none elsewhere.
    std::vector<char> hasRow(N, 0), gridRow(N, 0);
    std::vector<Eigen::Triplet<double>> Dt;
    for (const auto& node : freshAt) {  // not a structured binding: C++17 lambdas cannot capture one (clang)
      const auto& ij = node.first;
      const int v = nv + node.second;
      const auto at = [&](int di, int dj) {
        const auto it = freshAt.find({ij.first + di, ij.second + dj});
        return it == freshAt.end() ? -1 : nv + it->second;
      };
      const int w = at(-1, 0), e = at(1, 0), s = at(0, -1), n = at(0, 1);
      if (w < 0 || e < 0 || s < 0 || n < 0) continue;
      Dt.emplace_back(v, w, 1 / (hu * hu));
      Dt.emplace_back(v, e, 1 / (hu * hu));
      Dt.emplace_back(v, s, 1 / (hv * hv));
      Dt.emplace_back(v, n, 1 / (hv * hv));
      Dt.emplace_back(v, v, -2 / (hu * hu) - 2 / (hv * hv));
      hasRow[v] = gridRow[v] = 1;
    }
    for (int v = 0; v < N; ++v) {
      if (gridRow[v] || rimCount[v] != 0) continue;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(L, v); it; ++it)
        Dt.emplace_back(v, static_cast<int>(it.col()), it.value() / std::max(area[v], 1e-300));
      hasRow[v] = 1;
    }
    Eigen::SparseMatrix<double, Eigen::RowMajor> Delta(N, N);
    Delta.setFromTriplets(Dt.begin(), Dt.end());
    Eigen::SparseMatrix<double, Eigen::RowMajor> Pk = Delta;
    for (int k = 1; k < o.order; ++k) Pk = (Delta * Pk).pruned();
    // A row of Δᵏ is whole where every Δ it is made of has a row: within the padded grid's rim
    // layers it is not, and it is left out there (reading the missing rows as Δ = 0 would pull
    // the padding flat).
    std::vector<char> whole = hasRow;
    for (int k = 1; k < o.order; ++k) {
      std::vector<char> next(N, 0);
      for (int v = 0; v < N; ++v) {
        bool all = hasRow[v];
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Delta, v); it && all; ++it) all = whole[it.col()];
        next[v] = all;
      }
      whole.swap(next);
    }
    std::vector<Eigen::Triplet<double>> keep;
    for (int v = 0; v < N; ++v)
      if (whole[v]) keep.emplace_back(v, v, 1.0);
    Eigen::SparseMatrix<double> K(N, N);
    K.setFromTriplets(keep.begin(), keep.end());
    const Eigen::SparseMatrix<double> P = (K * Pk).pruned();
    // The region's vertices within k rings of its boundary join the unknowns, held to their
    // places by a fidelity term rather than exactly (boundaryFidelity): Δᵏ of noisy data is the
    // noise amplified, and with that ring fixed, scan noise of 2e-4 of the diagonal swung the
    // extension by 0.48 of it. Data that Δᵏ continues exactly (a bicubic) stay exact.
    std::vector<int> ringIndex(nv, -1);
    int nRing = 0;
    if (o.boundaryFidelity > 0) {
      std::vector<int> depth(nv, -1), frontier;
      for (const auto& hole : holes.holes)
        for (int v : hole.loop)
          if (depth[v] < 0) depth[v] = 0, frontier.push_back(v);
      std::vector<std::vector<int>> nbr(nv);
      for (const auto& e : topo.edges()) nbr[e.a].push_back(e.b), nbr[e.b].push_back(e.a);
      for (int d = 1; d < o.order; ++d) {
        std::vector<int> next;
        for (int v : frontier)
          for (int w : nbr[v])
            if (depth[w] < 0) depth[w] = d, next.push_back(w);
        frontier.swap(next);
      }
      for (int v = 0; v < nv; ++v)
        if (depth[v] >= 0) ringIndex[v] = nRing++;
    }
    const int nU = nNew + nRing;  // unknowns: the new vertices, then the ring
    std::vector<Eigen::Triplet<double>> St;
    Eigen::MatrixX3d known = Eigen::MatrixX3d::Zero(N, 3);
    for (int v = 0; v < N; ++v) {
      if (v >= nv) St.emplace_back(v, v - nv, 1.0);
      else if (ringIndex[v] >= 0) St.emplace_back(v, nNew + ringIndex[v], 1.0);
      else known.row(v) = region.vertices.row(v);
    }
    Eigen::SparseMatrix<double> select(N, nU);
    select.setFromTriplets(St.begin(), St.end());
    const Eigen::SparseMatrix<double> Pn = P * select;
    // Differences of order k + 1 along the grid lines (zero on polynomials of degree ≤ k, so k = 3
    // continues a bicubic exactly on the grid, k = 2 a biquadratic): they settle the padding, and
    // are the paper's isocurve fairness along the extension's boundaries, here over all new grid
    // lines. Lines of new vertices too short for them are left to Δᵏ's rows; only when that
    // leaves the system singular do they get third differences (zero on quadratics only), and
    // then second differences (which pull every curved surface flat).
    static const std::vector<std::vector<double>> diff = {{}, {}, {1, -2, 1}, {1, -3, 3, -1}, {1, -4, 6, -4, 1}};
    // The paper's isocurves: grid columns (fixed i) and rows (fixed j) on the domain's boundary
    // and nearest the rectangle's sides u = 0, width and v = 0, height.
    std::set<int> isoU = {0, cu, static_cast<int>(std::lround((0 - out.u0) / hu)), static_cast<int>(std::lround((width - out.u0) / hu))};
    std::set<int> isoV = {0, cv, static_cast<int>(std::lround((0 - out.v0) / hv)), static_cast<int>(std::lround((height - out.v0) / hv))};
    const auto gridLineDifferences = [&](int lowest) {
      std::vector<Eigen::Triplet<double>> Ft;
      int frow = 0;
      for (const auto& [ij, first] : freshAt)
        for (int dir = 0; dir < 2; ++dir) {
          std::vector<int> run;
          for (int q = 0; q <= o.order + 1; ++q) {
            const auto it = freshAt.find({ij.first + (dir == 0 ? q : 0), ij.second + (dir == 1 ? q : 0)});
            if (it == freshAt.end()) break;
            run.push_back(it->second);
          }
          int top = o.order + 1;
          if (o.paperIsocurves) {
            // Runs off the paper's isocurves are kept only where they reach into the padding.
            bool padding = false;
            for (int q = 0; q < static_cast<int>(run.size()); ++q) {
              const int i = ij.first + (dir == 0 ? q : 0), j = ij.second + (dir == 1 ? q : 0);
              padding = padding || i < 0 || i > cu || j < 0 || j > cv;
            }
            const int line = dir == 0 ? ij.second : ij.first;
            const bool isocurve = dir == 0 ? isoV.count(line) > 0 : isoU.count(line) > 0;
            if (!padding && !isocurve) continue;
            if (!padding) top = o.order;
          }
          int order = top;
          while (order >= lowest && static_cast<int>(run.size()) < order + 1) --order;
          if (order < lowest) continue;
          if (order < top) {  // only where the longer stencil does not fit along this line at all
            const auto before = freshAt.find({ij.first - (dir == 0 ? 1 : 0), ij.second - (dir == 1 ? 1 : 0)});
            if (before != freshAt.end()) continue;  // this run's start is inside a line already covered
          }
          for (int q = 0; q <= order; ++q) Ft.emplace_back(frow, run[q], diff[order][q]);
          ++frow;
        }
      Eigen::SparseMatrix<double> F(frow, nU);
      F.setFromTriplets(Ft.begin(), Ft.end());
      return Eigen::SparseMatrix<double>(F.transpose() * F);
    };
    const Eigen::SparseMatrix<double> PtP = Pn.transpose() * Pn;
    const double scale = std::max(1e-300, PtP.diagonal().cwiseAbs().maxCoeff());
    // Last resort, where even second differences leave new vertices free (a region that fills
    // its rectangle but for a few padding nodes): a faint membrane Σ|x_i − x_j|² over the padded
    // mesh's edges, which places them as calmly as their neighbours allow.
    std::vector<Eigen::Triplet<double>> Mt;
    Eigen::MatrixX3d membraneRhs = Eigen::MatrixX3d::Zero(nU, 3);
    for (const auto& e : paddedTopology.edges())
      for (const auto& [a, b] : {std::pair<int, int>{e.a, e.b}, {e.b, e.a}}) {
        if (a < nv) continue;
        Mt.emplace_back(a - nv, a - nv, 1.0);
        if (b >= nv) Mt.emplace_back(a - nv, b - nv, -1.0);
        else membraneRhs.row(a - nv) += region.vertices.row(b);
      }
    Eigen::SparseMatrix<double> membrane(nU, nU);
    membrane.setFromTriplets(Mt.begin(), Mt.end());
    std::vector<Eigen::Triplet<double>> Wt;
    Eigen::MatrixX3d fidelityRhs = Eigen::MatrixX3d::Zero(nU, 3);
    for (int v = 0; v < nv; ++v)
      if (ringIndex[v] >= 0) Wt.emplace_back(nNew + ringIndex[v], nNew + ringIndex[v], 1.0), fidelityRhs.row(nNew + ringIndex[v]) = region.vertices.row(v);
    Eigen::SparseMatrix<double> fidelity(nU, nU);
    fidelity.setFromTriplets(Wt.begin(), Wt.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    const double hold = o.boundaryFidelity * scale;
    Eigen::MatrixX3d rhs = -(Pn.transpose() * (P * known)) + hold * fidelityRhs;
    bool solved = false;
    for (int lowest : {o.order + 1, 3, 2, 0}) {
      const Eigen::SparseMatrix<double> FtF = gridLineDifferences(std::max(lowest, 2));
      const double fair = o.fairness * scale / std::max(1e-300, FtF.diagonal().cwiseAbs().maxCoeff());
      if (lowest > 0) {
        solver.compute(PtP + fair * FtF + hold * fidelity);
      } else {
        const double faint = 1e-6 * scale / 4;
        solver.compute(PtP + fair * FtF + hold * fidelity + faint * membrane);
        rhs += faint * membraneRhs;
      }
      // LDLᵀ of a singular semi-definite matrix may still "succeed" with a tiny or negative pivot.
      solved = solver.info() == Eigen::Success && solver.vectorD().minCoeff() > 1e-12 * scale;
      if (solved) break;
    }
    if (!solved)
      throw Error("the G2/G1 continuation of the region's boundary cannot be solved on this domain (its system is singular, "
                  "as where a thin strip or a notch leaves grid nodes without neighbours): use the extension sampled from a "
                  "thin-plate fit (extension 'fit', the default) or none");
    Eigen::MatrixX3d x = solver.solve(rhs);
    if (!x.allFinite()) throw Error("the polyharmonic extension failed");
    if (o.meshFairness > 0) {
      // The paper's mesh fairness: the ARAP distortions D_t = J_t − R_t (J_t the triangle's uv → 3D
      // Jacobian, R_t the nearest orthonormal frame, from the extension just solved) should vary
      // little between neighbouring triangles; Σ area-weighted |D_t − D_t'|² over pairs sharing
      // an edge, at least one of them touching an unknown, solved once more with the rest.
      const auto column = [&](int v) { return v >= nv ? v - nv : (ringIndex[v] >= 0 ? nNew + ringIndex[v] : -1); };
      Eigen::MatrixX3d current = padded.vertices;
      for (int v = 0; v < N; ++v)
        if (column(v) >= 0) current.row(v) = x.row(column(v));
      const Eigen::Index T = padded.triangles.rows();
      std::vector<Eigen::Matrix<double, 2, 3>> grad(T);  // J_t = X_t · grad_t: rows u, v; one column per corner
      std::vector<Eigen::Matrix<double, 3, 2>> frame(T);
      std::vector<double> triArea(T);
      for (Eigen::Index t = 0; t < T; ++t) {
        const Eigen::Vector3i f = padded.triangles.row(t).transpose();
        Eigen::Matrix2d E;
        E.col(0) = (puv.row(f[1]) - puv.row(f[0])).transpose();
        E.col(1) = (puv.row(f[2]) - puv.row(f[0])).transpose();
        triArea[t] = 0.5 * std::abs(E.determinant());
        const Eigen::Matrix2d Ei = E.inverse();  // rows: d(edge coefficients)/d(u, v)
        // J = [x1 − x0, x2 − x0] · Ei, so J(:, j) = Σ_corner x_corner · g(j, corner)
        grad[t] << -Ei(0, 0) - Ei(1, 0), Ei(0, 0), Ei(1, 0), -Ei(0, 1) - Ei(1, 1), Ei(0, 1), Ei(1, 1);
        Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
        for (int c = 0; c < 3; ++c) J += current.row(f[c]).transpose() * grad[t].col(c).transpose();
        const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
        frame[t] = svd.matrixU().leftCols<2>() * svd.matrixV().transpose();
      }
      std::map<std::pair<int, int>, Eigen::Index> firstAt;
      std::vector<Eigen::Triplet<double>> Et;
      std::vector<Eigen::RowVector3d> Erhs;
      int row = 0;
      for (Eigen::Index t = 0; t < T; ++t)
        for (int c = 0; c < 3; ++c) {
          int a = padded.triangles(t, c), b = padded.triangles(t, (c + 1) % 3);
          if (a > b) std::swap(a, b);
          const auto [it, fresh] = firstAt.emplace(std::make_pair(a, b), t);
          if (fresh) continue;
          const Eigen::Index t2 = it->second;
          bool touches = false;
          for (const Eigen::Index q : {t, t2})
            for (int k = 0; k < 3; ++k) touches = touches || column(padded.triangles(q, k)) >= 0;
          if (!touches) continue;
          const double w = std::sqrt(0.5 * (triArea[t] + triArea[t2]));
          for (int j = 0; j < 2; ++j, ++row) {
            Eigen::RowVector3d r = -w * (frame[t].col(j) - frame[t2].col(j)).transpose();
            for (const auto& [q, sign] : {std::pair<Eigen::Index, double>{t, 1.0}, {t2, -1.0}})
              for (int k = 0; k < 3; ++k) {
                const int v = padded.triangles(q, k);
                const double g = sign * w * grad[q](j, k);
                if (column(v) >= 0) Et.emplace_back(row, column(v), g);
                else r += g * padded.vertices.row(v);  // a known vertex moves to the right side
              }
            Erhs.push_back(-r);
          }
        }
      Eigen::SparseMatrix<double> Em(row, nU);
      Em.setFromTriplets(Et.begin(), Et.end());
      Eigen::MatrixX3d eb(row, 3);
      for (int r = 0; r < row; ++r) eb.row(r) = Erhs[r];
      const Eigen::SparseMatrix<double> EtE = Em.transpose() * Em;
      const double wm = o.meshFairness * scale / std::max(1e-300, EtE.diagonal().cwiseAbs().maxCoeff());
      const Eigen::SparseMatrix<double> FtF = gridLineDifferences(o.order + 1);
      const double fair = o.fairness * scale / std::max(1e-300, FtF.diagonal().cwiseAbs().maxCoeff());
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> again(PtP + fair * FtF + hold * fidelity + wm * EtE);
      if (again.info() == Eigen::Success) {
        const Eigen::MatrixX3d y = again.solve(-(Pn.transpose() * (P * known)) + hold * fidelityRhs + wm * (Em.transpose() * eb));
        if (y.allFinite()) x = y;
      }
    }
    padded.vertices.bottomRows(nNew) = x.topRows(nNew);
  }

  // Crop to the rectangle: the new vertices inside it (grid lines run along its rim), and the
  // triangles all of whose vertices are kept.
  std::vector<int> newIndex(N, -1);
  int kept = 0;
  const double slack = 1e-9 * (hu + hv);
  for (int v = 0; v < N; ++v) {
    const bool inside = puv(v, 0) >= out.u0 - slack && puv(v, 0) <= out.u1 + slack && puv(v, 1) >= out.v0 - slack && puv(v, 1) <= out.v1 + slack;
    if (v < nv || inside) newIndex[v] = kept++;
  }
  out.mesh.vertices.resize(kept, 3);
  out.uv.resize(kept, 2);
  for (int v = 0; v < N; ++v)
    if (newIndex[v] >= 0) out.mesh.vertices.row(newIndex[v]) = padded.vertices.row(v), out.uv.row(newIndex[v]) = puv.row(v);
  std::vector<Eigen::Vector3i> tris;
  for (Eigen::Index t = 0; t < padded.triangles.rows(); ++t) {
    const int a = newIndex[padded.triangles(t, 0)], b = newIndex[padded.triangles(t, 1)], c = newIndex[padded.triangles(t, 2)];
    if (a >= 0 && b >= 0 && c >= 0) tris.emplace_back(a, b, c);
  }
  out.mesh.triangles.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (size_t k = 0; k < tris.size(); ++k) out.mesh.triangles.row(static_cast<Eigen::Index>(k)) = tris[k].transpose();
  return out;
}

}  // namespace holefill
