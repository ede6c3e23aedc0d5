#include "fill/variational_fill.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>

#include "geometry/bspline_basis.h"
#include "geometry/differential_geometry.h"
#include "geometry/error.h"

namespace holefill {

Continuity continuityFromString(const std::string& s) {
  if (s == "G0" || s == "g0" || s == "0") return Continuity::G0;
  if (s == "G1" || s == "g1" || s == "1") return Continuity::G1;
  if (s == "G2" || s == "g2" || s == "2") return Continuity::G2;
  throw Error("unknown continuity '" + s + "': use G0, G1 or G2");
}

std::string toString(Continuity c) { return "G" + std::to_string(static_cast<int>(c)); }

namespace {

constexpr int P = 3;  // bicubic
constexpr int M = (P + 1) * (P + 1);

// Non-zero basis functions (and derivatives) of the surface at one parameter point.
struct LocalBasis {
  int su = 0, sv = 0;
  Eigen::Matrix<double, M, 1> n, nu, nv, nuu, nuv, nvv;
};

LocalBasis localBasis(const std::vector<double>& U, const std::vector<double>& V, double u, double v, int order) {
  LocalBasis b;
  b.su = findSpan(U, P, u);
  b.sv = findSpan(V, P, v);
  const Eigen::MatrixXd Nu = basisDerivatives(U, P, b.su, u, order), Nv = basisDerivatives(V, P, b.sv, v, order);
  for (int i = 0; i <= P; ++i)
    for (int j = 0; j <= P; ++j) {
      const int k = i * (P + 1) + j;
      b.n(k) = Nu(0, i) * Nv(0, j);
      if (order >= 1) { b.nu(k) = Nu(1, i) * Nv(0, j); b.nv(k) = Nu(0, i) * Nv(1, j); }
      if (order >= 2) { b.nuu(k) = Nu(2, i) * Nv(0, j); b.nuv(k) = Nu(1, i) * Nv(1, j); b.nvv(k) = Nu(0, i) * Nv(2, j); }
    }
  return b;
}

// One scalar constraint row: Σ_k coef(k) * (P_{pole(k)} · dir) = target.
struct Row {
  int su, sv;
  Eigen::Matrix<double, M, 1> coef;
  Eigen::Vector3d dir;
  double target, weight;
  bool multiplier;  // takes part in the augmented-Lagrangian target shifts
  int sample;       // -1 for reference rows
};

// The unknowns in the order the factorization eliminates them: pole by pole with the shorter side
// of the grid running fastest, a pole's three coordinates together. A bicubic pole couples only to
// poles at most P rows and columns away, so the matrix is then a band about 3(P·min(nu,nv)+P)
// wide, which a simplicial factorization handles with no wasted work. Measured on corpus fills
// (Eigen's SimplicialLDLT, analysis and factorization): 13x10 poles 0.7 ms against 4.8 ms with
// Eigen's default scalar AMD ordering, 23x15 5.7 against 14.7, 21x57 36 against 92, 57x41 234
// against 372 ms. Nested dissection of the pole grid (separators P poles wide) was tried and lost
// to the band up to the 2,500-pole limit.
Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> bandOrder(int nu, int nv) {
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order(3 * nu * nv);
  for (int iu = 0; iu < nu; ++iu)
    for (int iv = 0; iv < nv; ++iv) {
      const int pole = iu * nv + iv, place = nu <= nv ? iv * nu + iu : pole;
      for (int c = 0; c < 3; ++c) order.indices()(3 * pole + c) = 3 * place + c;
    }
  return order;
}

struct System {
  int nu, nv;
  std::vector<Row> rows;
  Eigen::SparseMatrix<double> H;  // lower triangle, unknowns in elimination order (bandOrder)
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;  // unknown -> its place in H
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt;
  Eigen::VectorXd solve(const Eigen::VectorXd& g) const { return order.transpose() * ldlt.solve(order * g); }
};

int poleIndex(int nv, int su, int sv, int k) { return (su - P + k / (P + 1)) * nv + (sv - P + k % (P + 1)); }

// The normal equations' lower triangle, one 3x3 block per pair of poles whose supports overlap
// (at most P apart in u and in v), summed in place and written column by column in order, never
// through triplets or per-span dense blocks (their memory, not their arithmetic, was the cost).
// A row along a coordinate axis (G0, tangent guide, reference) touches one coordinate; only rows
// along other directions (G1, G2) couple coordinates, and only structurally non-zero entries are
// kept: the interior couples no two coordinates, and the factorization's fill-in depends on that.
void assemble(System& sys, const Eigen::SparseMatrix<double>& A) {
  const int nu = sys.nu, nv = sys.nv, n = nu * nv;
  constexpr int W = 2 * P + 1;                // neighbour offsets per direction
  constexpr int F = P * W + P + 1;            // forward neighbours (ia >= ib) of a pole
  auto slotOf = [](int du, int dv) { return du == 0 ? dv : P + 1 + (du - 1) * W + (dv + P); };
  auto slot = [&](int ia, int ib) { return slotOf(ia / nv - ib / nv, ia % nv - ib % nv); };
  std::vector<Eigen::Matrix3d> band(static_cast<size_t>(n) * F, Eigen::Matrix3d::Zero());
  auto at = [&](int ia, int ib) -> Eigen::Matrix3d& { return band[static_cast<size_t>(ib) * F + slot(ia, ib)]; };

  // Within one span's 4x4 poles the pair (a, b) with a's pole after b's always has the same slot.
  int pairSlot[M][M];
  for (int a = 0; a < M; ++a)
    for (int b = 0; b < M; ++b) {
      const int du = a / (P + 1) - b / (P + 1), dv = a % (P + 1) - b % (P + 1);
      pairSlot[a][b] = (du > 0 || (du == 0 && dv >= 0)) ? slotOf(du, dv) : -1;
    }
  for (const Row& r : sys.rows) {
    int axis = -1;
    for (int d = 0; d < 3; ++d)
      if (r.dir(d) == 1.0 && r.dir((d + 1) % 3) == 0.0 && r.dir((d + 2) % 3) == 0.0) axis = d;
    const Eigen::Matrix3d D = r.weight * r.dir * r.dir.transpose();
    const int base = poleIndex(nv, r.su, r.sv, 0);
    for (int b = 0; b < M; ++b) {
      const int ib = base + (b / (P + 1)) * nv + b % (P + 1);
      Eigen::Matrix3d* column = &band[static_cast<size_t>(ib) * F];
      for (int a = 0; a < M; ++a) {
        if (pairSlot[a][b] < 0) continue;
        const double c = r.coef(a) * r.coef(b);
        if (axis >= 0) column[pairSlot[a][b]](axis, axis) += r.weight * c;
        else column[pairSlot[a][b]] += c * D;
      }
    }
  }
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (it.row() >= j) at(static_cast<int>(it.row()), j).diagonal().array() += it.value();

  sys.H.resize(3 * n, 3 * n);
  sys.H.reserve(static_cast<Eigen::Index>(n) * 3 * 2 * P * W);
  for (int ib = 0; ib < n; ++ib)
    for (int d = 0; d < 3; ++d) {
      sys.H.startVec(3 * ib + d);
      for (int du = 0; du <= P && ib / nv + du < nu; ++du)
        for (int dv = (du == 0 ? 0 : -P); dv <= P; ++dv) {
          const int iv = ib % nv + dv;
          if (iv < 0 || iv >= nv) continue;
          const int ia = ib + du * nv + dv;
          const Eigen::Matrix3d& E = band[static_cast<size_t>(ib) * F + slot(ia, ib)];
          for (int c = (ia == ib ? d : 0); c < 3; ++c)
            if (E(c, d) != 0.0) sys.H.insertBack(3 * ia + c, 3 * ib + d) = E(c, d);
        }
    }
  sys.H.finalize();
  const auto t0 = std::chrono::steady_clock::now();
  sys.order = bandOrder(nu, nv);
  Eigen::SparseMatrix<double> ordered(3 * n, 3 * n);
  ordered.selfadjointView<Eigen::Lower>() = sys.H.selfadjointView<Eigen::Lower>().twistedBy(sys.order);
  sys.H = std::move(ordered);
  sys.ldlt.compute(sys.H);  // reads the lower triangle
  if (std::getenv("HOLEFILL_DEBUG"))
    std::fprintf(stderr, "  factor %.4fs (%d unknowns, %ld nonzeros in the lower triangle, %zu rows)\n",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 3 * n,
                 static_cast<long>(sys.H.nonZeros()), sys.rows.size());
  if (sys.ldlt.info() != Eigen::Success)
    throw Error("the fill's normal equations are singular: the boundary constraints do not determine the surface");
}

Eigen::VectorXd rhs(const System& sys, const std::vector<double>& targets) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * sys.nu * sys.nv);
  for (size_t i = 0; i < sys.rows.size(); ++i) {
    const Row& r = sys.rows[i];
    for (int a = 0; a < M; ++a) {
      const int ia = poleIndex(sys.nv, r.su, r.sv, a);
      g.segment<3>(3 * ia) += (r.weight * targets[i] * r.coef(a)) * r.dir;
    }
  }
  return g;
}

double rowValue(const System& sys, const Row& r, const Eigen::VectorXd& x) {
  double s = 0.0;
  for (int a = 0; a < M; ++a) s += r.coef(a) * x.segment<3>(3 * poleIndex(sys.nv, r.su, r.sv, a)).dot(r.dir);
  return s;
}

BSplineSurface toSurface(const std::vector<double>& U, const std::vector<double>& V, const Eigen::VectorXd& x) {
  BSplineSurface s;
  s.knotsU = U;
  s.knotsV = V;
  s.poles.resize(s.numU() * s.numV(), 3);
  for (int i = 0; i < s.numU() * s.numV(); ++i) s.poles.row(i) = x.segment<3>(3 * i).transpose();
  return s;
}

struct Errors {
  double g0 = 0, g1 = 0, g2 = 0;  // g0 includes the pass points'
  double pass = 0;
  std::vector<int> violating;
  std::vector<int> violatingPass;  // pass points missed
};

// Jet of the solution x at a sample, from its precomputed local basis (no basis re-evaluation).
SurfaceJet jetAt(const LocalBasis& b, const Eigen::VectorXd& x, int nv, bool second) {
  SurfaceJet j{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
               Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  for (int a = 0; a < M; ++a) {
    const Eigen::Vector3d P = x.segment<3>(3 * poleIndex(nv, b.su, b.sv, a));
    j.p += b.n(a) * P;
    j.su += b.nu(a) * P;
    j.sv += b.nv(a) * P;
    if (second) {
      j.suu += b.nuu(a) * P;
      j.suv += b.nuv(a) * P;
      j.svv += b.nvv(a) * P;
    }
  }
  return j;
}

Errors measure(const std::vector<LocalBasis>& basis, const std::vector<LocalBasis>& passBasis, const Eigen::VectorXd& x, int nv,
               const FillConstraints& c, const VariationalFillOptions& o) {
  Errors e;
  for (size_t p = 0; p < c.passUV.size(); ++p) {
    const double d = (jetAt(passBasis[p], x, nv, false).p - c.passXYZ[p]).norm();
    e.pass = std::max(e.pass, d);
    if (d > o.g0Tolerance) e.violatingPass.push_back(static_cast<int>(p));
  }
  e.g0 = e.pass;
  const bool second = o.continuity == Continuity::G2;
  for (size_t k = 0; k < c.size(); ++k) {
    const SurfaceJet j = jetAt(basis[k], x, nv, second);
    const double e0 = (j.p - c.point[k]).norm();
    double e1 = 0.0, e2 = 0.0;
    Eigen::Vector3d n;
    const bool ok = unitNormal(j, n);
    const int ord = c.orderAt(k, o.continuity);
    if (c.normalValid[k] && ord >= 1)
      e1 = ok ? std::acos(std::min(1.0, std::abs(n.dot(c.normal[k])))) : M_PI / 2;
    if (c.normalValid[k] && ord == 2 && ok) {
      const double kf = normalCurvature(j, n.dot(c.normal[k]) < 0 ? Eigen::Vector3d(-n) : n, c.across[k]);
      e2 = std::abs(kf - c.curvature[k]) / std::max(std::abs(c.curvature[k]), 1.0);
    }
    e.g0 = std::max(e.g0, e0);
    e.g1 = std::max(e.g1, e1);
    e.g2 = std::max(e.g2, e2);
    if (e0 > o.g0Tolerance || e1 > o.g1Tolerance || e2 > o.g2Tolerance) e.violating.push_back(static_cast<int>(k));
  }
  return e;
}

// The worst error relative to its tolerance: the error furthest from its target decides.
double worstRatio(const Errors& e, const VariationalFillOptions& o) {
  double w = e.g0 / o.g0Tolerance;
  if (o.continuity >= Continuity::G1) w = std::max(w, e.g1 / o.g1Tolerance);
  if (o.continuity == Continuity::G2) w = std::max(w, e.g2 / o.g2Tolerance);
  return w;
}

// Highest order met in sequence: -1 none, 0 G0, 1 G0+G1, 2 G0+G1+G2.
int levelMet(const Errors& e, const VariationalFillOptions& o) {
  if (e.g0 > o.g0Tolerance) return -1;
  if (o.continuity >= Continuity::G1 && e.g1 > o.g1Tolerance) return 0;
  if (o.continuity == Continuity::G2 && e.g2 > o.g2Tolerance) return 1;
  return static_cast<int>(o.continuity);
}

// Lexicographic: a G2 request that cannot be met keeps the best G1 (and G0) it found on the way.
bool better(const Errors& a, const Errors& b, const VariationalFillOptions& o) {
  const int la = levelMet(a, o), lb = levelMet(b, o);
  if (la != lb) return la > lb;
  return worstRatio(a, o) < worstRatio(b, o);
}

}  // namespace

VariationalFillResult solveVariationalFill(const FillConstraints& c, double u0, double u1, double v0, double v1,
                                           std::vector<double> U, std::vector<double> V,
                                           const VariationalFillOptions& o) {
  HF_CHECK(c.size() >= 6, "the fill needs at least 6 boundary samples");
  HF_CHECK(c.order.empty() || c.order.size() == c.size(), "one continuity order per boundary sample");
  HF_CHECK(c.passUV.size() == c.passXYZ.size(), "one position per pass point");
  for (size_t p = 0; p < c.passUV.size(); ++p)
    if (!c.passUV[p].allFinite() || !c.passXYZ[p].allFinite()) throw Error("pass point " + std::to_string(p) + " is not finite");
  HF_CHECK(u1 > u0 && v1 > v0, "the fill domain is empty");
  for (size_t k = 0; k < c.size(); ++k)
    if (!c.uv[k].allFinite() || !c.point[k].allFinite() || !std::isfinite(c.curvature[k]))
      throw Error("boundary sample " + std::to_string(k) + " is not finite (NaN or infinite coordinates)");
  const double du = u1 - u0, dv = v1 - v0;
  if (U.empty()) U = clampedUniformKnots(P, std::max(3, int(std::lround(o.initialSpans * du / std::max(du, dv)))), u0, u1);
  if (V.empty()) V = clampedUniformKnots(P, std::max(3, int(std::lround(o.initialSpans * dv / std::max(du, dv)))), v0, v1);
  double W = 0;
  for (double w : c.weight) W += w;
  HF_CHECK(W > 0, "boundary samples carry no length");

  VariationalFillResult res;
  Errors bestErr;
  bool haveBest = false;
  const int order = o.continuity == Continuity::G2 ? 2 : 1;
  const int totalRounds = o.maxRefinements + 1;

  double previousRatio = std::numeric_limits<double>::infinity();
  for (int level = 0; level <= o.maxRefinements; ++level) {
    System sys;
    sys.nu = static_cast<int>(U.size()) - P - 1;
    sys.nv = static_cast<int>(V.size()) - P - 1;
    const Eigen::SparseMatrix<double> A = fairnessMatrix(P, U, P, V, o.fairness);
    std::vector<LocalBasis> basis;
    basis.reserve(c.size());
    for (size_t k = 0; k < c.size(); ++k) basis.push_back(localBasis(U, V, c.uv[k].x(), c.uv[k].y(), order));
    std::vector<LocalBasis> passBasis;
    for (const Eigen::Vector2d& uv : c.passUV) passBasis.push_back(localBasis(U, V, uv.x(), uv.y(), 0));
    // Penalties are relative to the fairness stiffness, which grows like h^-5 as spans shrink, and
    // each row is normalized by its own coefficient norm: every constraint then outweighs the
    // fairness of the poles it touches by the same factor at every refinement level.
    const double stiffness = A.diagonal().mean();
    const double n = static_cast<double>(c.size());
    auto rowWeight = [&](double rho, const Eigen::Matrix<double, M, 1>& coef, size_t k) {
      return rho * stiffness * (c.weight[k] * n / W) / std::max(coef.squaredNorm(), 1e-300);
    };
    for (size_t k = 0; k < c.size(); ++k) {
      const LocalBasis& b = basis[k];
      for (int d = 0; d < 3; ++d)
        sys.rows.push_back({b.su, b.sv, b.n, Eigen::Vector3d::Unit(d), c.point[k](d), rowWeight(o.positionWeight, b.n, k), true, int(k)});
      if (c.orderAt(k, o.continuity) >= 1 && c.normalValid[k]) {
        sys.rows.push_back({b.su, b.sv, b.nu, c.normal[k], 0.0, rowWeight(o.normalWeight, b.nu, k), true, int(k)});
        sys.rows.push_back({b.su, b.sv, b.nv, c.normal[k], 0.0, rowWeight(o.normalWeight, b.nv, k), true, int(k)});
      }
    }
    // Tangent guide: the linear G1 rows are also met by a surface whose cross-boundary derivative
    // vanishes (a degenerate, flat-folded fill, e.g. over the open end of a tube). A soft pull of
    // that derivative towards `across`, at the boundary's own speed, picks the proper branch:
    // the fill leaves the boundary where the support would continue.
    if (o.continuity >= Continuity::G1 && o.tangentGuideWeight > 0)
      for (size_t k = 0; k < c.size(); ++k) {
        if (!c.normalValid[k] || c.orderAt(k, o.continuity) < 1) continue;
        const size_t a = (k > 0 && c.edge[k - 1] == c.edge[k]) ? k - 1 : k;
        const size_t b = (k + 1 < c.size() && c.edge[k + 1] == c.edge[k]) ? k + 1 : k;
        const Eigen::Vector2d t = c.uv[b] - c.uv[a];
        const double luv = t.norm(), l3 = (c.point[b] - c.point[a]).norm();
        if (a == b || luv <= 0 || l3 <= 0) continue;
        const Eigen::Vector2d w(-t.y() / luv, t.x() / luv);  // left of a counter-clockwise loop: inside
        const LocalBasis& bk = basis[k];
        const Eigen::Matrix<double, M, 1> coef = w.x() * bk.nu + w.y() * bk.nv;
        const Eigen::Vector3d target = (l3 / luv) * c.across[k];
        for (int d = 0; d < 3; ++d)
          sys.rows.push_back({bk.su, bk.sv, coef, Eigen::Vector3d::Unit(d), target(d),
                              rowWeight(o.tangentGuideWeight, coef, k), false, int(k)});
      }
    // A pass point weighs as a boundary sample of the mean arc-length weight.
    for (size_t p = 0; p < c.passUV.size(); ++p) {
      const LocalBasis& b = passBasis[p];
      const double w = o.positionWeight * stiffness / std::max(b.n.squaredNorm(), 1e-300);
      for (int d = 0; d < 3; ++d) sys.rows.push_back({b.su, b.sv, b.n, Eigen::Vector3d::Unit(d), c.passXYZ[p](d), w, true, -1});
    }
    for (size_t k = 0; k < c.referenceUV.size(); ++k) {
      const LocalBasis b = localBasis(U, V, c.referenceUV[k].x(), c.referenceUV[k].y(), 0);
      for (int d = 0; d < 3; ++d)
        sys.rows.push_back({b.su, b.sv, b.n, Eigen::Vector3d::Unit(d), c.referenceXYZ[k](d),
                            o.referenceWeight * stiffness / c.referenceUV.size(), false, -1});
    }
    const size_t fixedRows = sys.rows.size();
    Eigen::VectorXd x;
    const int curvatureRounds = o.continuity == Continuity::G2 ? o.curvatureIterations + 1 : 1;
    std::vector<double> carried;  // the fixed rows' shifted targets after the last curvature round
    for (int cr = 0; cr < curvatureRounds; ++cr) {
      sys.rows.resize(fixedRows);
      if (cr > 0) {
        // Linearize the cross-boundary normal curvature about the current surface.
        for (size_t k = 0; k < c.size(); ++k) {
          if (!c.normalValid[k] || c.orderAt(k, o.continuity) < 2) continue;
          const SurfaceJet j = jetAt(basis[k], x, sys.nv, false);
          const Eigen::Vector2d ab = parameterDirection(j, c.across[k]);
          const double len2 = (ab(0) * j.su + ab(1) * j.sv).squaredNorm();
          const LocalBasis& b = basis[k];
          Eigen::Matrix<double, M, 1> coef = ab(0) * ab(0) * b.nuu + 2 * ab(0) * ab(1) * b.nuv + ab(1) * ab(1) * b.nvv;
          sys.rows.push_back({b.su, b.sv, coef, c.normal[k], c.curvature[k] * len2,
                              rowWeight(o.curvatureWeight, coef, k), true, int(k)});
        }
      }
      const auto ta = std::chrono::steady_clock::now();
      assemble(sys, A);
      const double tAssemble = std::chrono::duration<double>(std::chrono::steady_clock::now() - ta).count();
      const auto ti = std::chrono::steady_clock::now();
      int iterations = 0;
      // The fixed rows (G0, G1, guides) are the same in every curvature round: their shifted targets
      // (the multipliers) carry over, so a G2 round starts from the G0 and G1 the last one reached
      // instead of from the plain penalty solution (which, on long thin fills, its few rounds before
      // stalling did not bring back to the G0 tolerance: the G2-linearized rounds then lost to the
      // unlinearized one, and the fill met G0 but missed G2 by a factor 40).
      std::vector<double> targets(sys.rows.size());
      for (size_t i = 0; i < sys.rows.size(); ++i)
        targets[i] = i < fixedRows && i < carried.size() ? carried[i] : sys.rows[i].target;
      Errors levelBest;
      Eigen::VectorXd levelX;
      std::vector<double> history;
      for (int it = 0; it <= o.multiplierIterations; ++it, ++iterations) {
        x = sys.solve(rhs(sys, targets));
        const Errors e = measure(basis, passBasis, x, sys.nv, c, o);
        if (it == 0 || better(e, levelBest, o)) { levelBest = e; levelX = x; }
        // Keep iterating past the tolerance: the multiplier rounds are cheap and the margin
        // is what the interior (set only through the boundary) inherits.
        const double ratio = worstRatio(e, o);
        if (e.violating.empty() && e.violatingPass.empty() && ratio < o.multiplierMargin) break;
        // Stalled: more rounds will not pay. Above the tolerance the knots, not the multipliers,
        // are what is missing; below it the remaining error is the discretization's.
        history.push_back(ratio);
        if (history.size() > 4 && ratio > 0.8 * history[history.size() - 5]) break;
        for (size_t i = 0; i < sys.rows.size(); ++i)
          if (sys.rows[i].multiplier) targets[i] -= rowValue(sys, sys.rows[i], x) - sys.rows[i].target;
      }
      // Carried only from a round that missed: one that met every tolerance needs no help, and a
      // fresh start lets the next round's own multiplier rounds run on to the margin, which the
      // interior inherits (a patch refilled on its own pcurves at G2 moved 1.2e-6 of its size off
      // itself when a met round's multipliers were carried and the next round stopped at once).
      if (levelBest.violating.empty() && levelBest.violatingPass.empty()) carried.clear();
      else carried.assign(targets.begin(), targets.begin() + fixedRows);
      x = levelX;
      if (std::getenv("HOLEFILL_DEBUG"))
        std::fprintf(stderr, "[fill] level %d poles %dx%d cr %d: g0 %.3g g1 %.3g g2 %.3g violating %zu; assemble %.3fs, %d rounds %.3fs\n",
                     level, sys.nu, sys.nv, cr, levelBest.g0, levelBest.g1, levelBest.g2, levelBest.violating.size(), tAssemble,
                     iterations, std::chrono::duration<double>(std::chrono::steady_clock::now() - ti).count());
      if (!haveBest || better(levelBest, bestErr, o) || (levelBest.violating.empty() && levelBest.violatingPass.empty())) {
        bestErr = levelBest;
        res.surface = toSurface(U, V, x);
        haveBest = true;
      }
    }
    res.refinements = level;
    if (o.progress && !o.progress(double(level + 1) / totalRounds)) { res.cancelled = true; break; }
    if ((bestErr.violating.empty() && bestErr.violatingPass.empty()) || level == o.maxRefinements) break;
    // Refine: split every u-span and v-span that holds a violating sample and enough samples.
    std::map<int, int> inU, inV;  // samples per span
    for (size_t k = 0; k < c.size(); ++k) {
      ++inU[findSpan(U, P, c.uv[k].x())];
      ++inV[findSpan(V, P, c.uv[k].y())];
    }
    std::set<double> newU, newV;
    bool blocked = false;
    for (int k : bestErr.violating) {
      const int su = findSpan(U, P, c.uv[k].x()), sv = findSpan(V, P, c.uv[k].y());
      if (inU[su] >= o.minSamplesPerSplit) newU.insert(0.5 * (U[su] + U[su + 1]));
      else blocked = true;
      if (inV[sv] >= o.minSamplesPerSplit) newV.insert(0.5 * (V[sv] + V[sv + 1]));
      else blocked = true;
    }
    // A missed pass point's spans are split whatever they hold: the point pins its own span
    // (the boundary's rule is about spans between boundary samples).
    for (int p : bestErr.violatingPass) {
      const int su = findSpan(U, P, c.passUV[p].x()), sv = findSpan(V, P, c.passUV[p].y());
      newU.insert(0.5 * (U[su] + U[su + 1]));
      newV.insert(0.5 * (V[sv] + V[sv + 1]));
    }
    // A blocked span needs denser samples, not knots: say so, and stop once the splits that
    // remain possible no longer help (they refine the other direction only).
    const double ratioNow = worstRatio(bestErr, o);
    if (blocked) res.samplesTooSparse = true;
    if ((newU.empty() && newV.empty()) || (blocked && ratioNow > 0.9 * previousRatio)) {
      res.warnings.push_back("knot refinement stopped at " + std::to_string(sys.nu) + "x" + std::to_string(sys.nv) +
                             " poles: spans holding violating samples hold fewer than " +
                             std::to_string(o.minSamplesPerSplit) + " boundary samples");
      break;
    }
    previousRatio = ratioNow;
    const int nuNew = sys.nu + static_cast<int>(newU.size()), nvNew = sys.nv + static_cast<int>(newV.size());
    if (nuNew * nvNew > o.maxControlPoints) {
      res.warnings.push_back("knot refinement stopped at " + std::to_string(sys.nu) + "x" + std::to_string(sys.nv) +
                             " poles (maxControlPoints " + std::to_string(o.maxControlPoints) + ")");
      break;
    }
    for (double k : newU) U.insert(std::upper_bound(U.begin(), U.end(), k), k);
    for (double k : newV) V.insert(std::upper_bound(V.begin(), V.end(), k), k);
  }
  if (std::getenv("HOLEFILL_DEBUG"))
    for (int k : bestErr.violating)
      std::fprintf(stderr, "[fill] violating sample %d (edge %d) at uv (%.4g %.4g)\n", k, c.edge[k], c.uv[k].x(), c.uv[k].y());
  res.g0 = bestErr.g0;
  res.g1 = bestErr.g1;
  res.g2 = bestErr.g2;
  res.passError = bestErr.pass;
  res.violatingSamples = bestErr.violating;
  res.toleranceMet = bestErr.violating.empty() && bestErr.violatingPass.empty();
  res.levelMet = levelMet(bestErr, o);
  res.worstRatio = worstRatio(bestErr, o);
  return res;
}

}  // namespace holefill
