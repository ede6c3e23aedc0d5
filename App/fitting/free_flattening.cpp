#include "fitting/free_flattening.h"

#include <Eigen/Sparse>
#include <cmath>
#include <limits>

#include "fitting/arap_terms.h"
#include "fitting/boundary_embedding.h"
#include "geometry/error.h"
#include "mesh/mesh_holes.h"

namespace holefill {

FreeFlattening flattenFree(const TriangleMesh& region, const FreeFlatteningOptions& o) {
  validateMesh(region, "region");
  const int nv = static_cast<int>(region.vertices.rows()), nt = static_cast<int>(region.triangles.rows());
  if (nt < 2) throw Error("the region has " + std::to_string(nt) + " triangle" + (nt == 1 ? "" : "s") + "; flattening needs several");
  {
    std::vector<char> used(nv, 0);
    for (int t = 0; t < nt; ++t)
      for (int k = 0; k < 3; ++k) used[region.triangles(t, k)] = 1;
    for (int v = 0; v < nv; ++v)
      if (!used[v]) throw Error("the region has vertices used by no triangle; remove them first");
  }
  const Eigen::MatrixX3i& tri = region.triangles;
  double reference = 0;
  const std::vector<ArapTerm> terms = arapTerms(region.vertices, tri, reference);
  if (!(reference > 0)) throw Error("the region's triangles have no extent");

  // Two pins for the start, far apart on the outer boundary (the similarity's four degrees of
  // freedom); ARAP then keeps the first only.
  const MeshHoleReport holes = findMeshHoles(region);
  if (holes.holes.empty()) throw Error("the region is closed: it has no boundary to flatten from");
  const MeshHole* outer = &holes.holes[0];
  for (const auto& h : holes.holes)
    if (h.length > outer->length) outer = &h;
  const auto farthestFrom = [&](int from) {
    int best = from;
    for (int v : outer->loop)
      if ((region.vertices.row(v) - region.vertices.row(from)).squaredNorm() > (region.vertices.row(best) - region.vertices.row(from)).squaredNorm())
        best = v;
    return best;
  };
  const int p0 = farthestFrom(outer->loop.front()), p1 = farthestFrom(p0);
  if (p0 == p1) throw Error("the region's boundary has no extent");

  std::vector<char> turned = trianglesTurnedInInput(region.vertices, tri);
  const auto flips = [&](const Eigen::MatrixX2d& m) {
    int n = 0;
    for (int t = 0; t < nt; ++t) n += !turned[t] && !(signedArea(m, tri.row(t).transpose()) > 0);
    return n;
  };

  // The start: the as-similar-as-possible map (each triangle's edges matched by a similarity
  // a·I + b·J of its own, unknown), p0 at the origin and p1 on the u axis at its distance; or the
  // map given.
  Eigen::MatrixX2d uv(nv, 2);
  const bool given = o.start.rows() > 0;
  if (given) {
    if (o.start.rows() != nv || !o.start.allFinite()) throw Error("the start map must give finite parameters for every vertex of the region");
    uv = o.start;
    // A start that runs the other way round (the labeled map of a region read from its other
    // side: its triangles all turned against these) is mirrored, which keeps it one to one; ARAP's
    // rotations cannot undo a reflection (bspline_uslot_clean_cw: every one of 39,882 triangles
    // counted as a fold, so the restart could never begin, and the labels were not relaxed).
    double area = 0;
    for (int t = 0; t < nt; ++t) area += signedArea(uv, tri.row(t).transpose());
    if (area < 0) uv.col(0) = -uv.col(0);
  } else {
    const double d = (region.vertices.row(p1) - region.vertices.row(p0)).norm();
    std::vector<int> col(2 * nv, -1);
    int n = 0;
    for (int v = 0; v < nv; ++v)
      for (int c = 0; c < 2; ++c)
        if (v != p0 && v != p1) col[2 * v + c] = n++;
    const int ab = n;
    std::vector<Eigen::Triplet<double>> S;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(terms.size()));
    int r = 0;
    for (const ArapTerm& term : terms) {
      const double sw = std::sqrt(term.w);
      for (int c = 0; c < 2; ++c, ++r) {
        for (const auto& [v, sign] : {std::pair<int, double>{term.i, 1.0}, {term.j, -1.0}}) {
          if (col[2 * v + c] >= 0) S.emplace_back(r, col[2 * v + c], sign * sw);
          else if (v == p1 && c == 0) rhs[r] -= sign * sw * d;
        }
        // c = 0: a x − b y; c = 1: b x + a y.
        S.emplace_back(r, ab + 2 * term.t, -sw * (c == 0 ? term.x.x() : term.x.y()));
        S.emplace_back(r, ab + 2 * term.t + 1, -sw * (c == 0 ? -term.x.y() : term.x.x()));
      }
    }
    Eigen::SparseMatrix<double> M(r, ab + 2 * nt);
    M.setFromTriplets(S.begin(), S.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> asap(Eigen::SparseMatrix<double>(M.transpose() * M));
    if (asap.info() != Eigen::Success) throw Error("could not flatten the region (its conformal system is singular)");
    const Eigen::VectorXd z = asap.solve(M.transpose() * rhs);
    if (!z.allFinite()) throw Error("could not flatten the region (its conformal solve failed)");
    for (int v = 0; v < nv; ++v)
      for (int c = 0; c < 2; ++c) uv(v, c) = col[2 * v + c] >= 0 ? z[col[2 * v + c]] : (v == p1 && c == 0 ? d : 0.0);
  }

  // ARAP: p0 held where it is, every other vertex free.
  std::vector<int> col(nv, -1);
  for (int v = 0, n = 0; v < nv; ++v)
    if (v != p0) col[v] = n++;
  std::vector<Eigen::Triplet<double>> T;
  for (size_t k = 0; k < terms.size(); ++k) {
    const double sw = std::sqrt(terms[k].w);
    if (col[terms[k].i] >= 0) T.emplace_back(static_cast<int>(k), col[terms[k].i], sw);
    if (col[terms[k].j] >= 0) T.emplace_back(static_cast<int>(k), col[terms[k].j], -sw);
  }
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(terms.size()), nv - 1);
  A.setFromTriplets(T.begin(), T.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(Eigen::SparseMatrix<double>(A.transpose() * A));
  if (solver.info() != Eigen::Success) throw Error("could not flatten the region (the ARAP system is singular)");
  const Eigen::RowVector2d anchor = uv.row(p0);
  // The local step's rotations of the current map: they give its energy and the next global
  // step's right side, once per round.
  std::vector<Eigen::Matrix2d> R;
  // The same right side serves both coordinates: the rows are per edge, the columns per vertex.
  const auto rightSide = [&]() {
    Eigen::MatrixX2d b(static_cast<Eigen::Index>(terms.size()), 2);
    for (size_t k = 0; k < terms.size(); ++k) {
      const ArapTerm& term = terms[k];
      Eigen::Vector2d e = R[term.t] * term.x;
      // p0's fixed place moves to the right side.
      if (term.i == p0) e -= anchor.transpose();
      if (term.j == p0) e += anchor.transpose();
      b.row(static_cast<Eigen::Index>(k)) = std::sqrt(term.w) * e.transpose();
    }
    return b;
  };
  const auto mapOf = [&](const Eigen::MatrixX2d& z) {
    Eigen::MatrixX2d m(nv, 2);
    for (int v = 0; v < nv; ++v) m.row(v) = col[v] >= 0 ? Eigen::RowVector2d(z.row(col[v])) : anchor;
    return m;
  };
  const auto energyOf = [&](const Eigen::MatrixX2d& m) {  // of m, whose rotations R holds
    double e = 0;
    for (const ArapTerm& term : terms) e += term.w * ((m.row(term.i) - m.row(term.j)).transpose() - R[term.t] * term.x).squaredNorm();
    return e / reference;
  };
  // From a map given, the boundary is kept simple too.
  const auto crosses = [&](const Eigen::MatrixX2d& m) { return boundaryCrosses(holes, m); };
  const auto sound = [&](const Eigen::MatrixX2d& m) { return flips(m) == 0 && !(given && crosses(m)); };
  Eigen::MatrixX2d good = uv;
  bool goodFree = sound(uv);
  R = arapRotations(terms, uv, nt);
  double energy = energyOf(uv), tenBefore = std::numeric_limits<double>::infinity();
  FreeFlattening out;
  out.arapEnergy = energy;
  for (int it = 0; it < std::max(o.iterations, o.maxIterations); ++it) {
    const Eigen::MatrixX2d b = rightSide();
    Eigen::MatrixX2d next = mapOf(solver.solve(A.transpose() * b));
    if (!next.allFinite()) throw Error("could not flatten the region (the ARAP solve failed)");
    bool nextSound = sound(next);
    if (goodFree && !nextSound) {
      // Flip repair: step back towards the last map without folds, halving (none found: the
      // last good map stays, and the next round's rotations come from it).
      bool stepped = false;
      for (double alpha = 0.5; alpha > 1e-3 && !stepped; alpha *= 0.5) {
        const Eigen::MatrixX2d mix = good + alpha * (next - good);
        if (sound(mix)) next = mix, stepped = nextSound = true;
      }
      if (!stepped && given) next = good, nextSound = true;
    }
    uv = next;
    R = arapRotations(terms, uv, nt);
    energy = energyOf(uv);
    if (nextSound) good = uv, goodFree = true, out.arapEnergy = energy;
    else if (!goodFree) good = uv, out.arapEnergy = energy;
    if ((it + 1) % 10 == 0) {
      if (it + 1 >= o.iterations && !(energy < 0.99 * tenBefore)) break;
      tenBefore = energy;
    }
  }
  out.uv = good;
  out.flippedTriangles = flips(good);
  out.boundaryCrosses = crosses(good);
  return out;
}

}  // namespace holefill
