#include "fill/fairness_energy.h"

#include "geometry/bspline_basis.h"

namespace holefill {

namespace {

// 1D Gram matrices G[k](i, i') = ∫ N_i^(k) N_i'^(k) du for k = 0..maxOrder, exact by Gauss-Legendre
// per knot span (p+1 nodes integrate the degree-2p products exactly). Dense n x n, banded in fact.
std::vector<Eigen::MatrixXd> gramMatrices(int p, const std::vector<double>& U, int maxOrder) {
  const int n = static_cast<int>(U.size()) - p - 1;
  std::vector<double> gx, gw;
  gaussLegendre(p + 1, gx, gw);
  std::vector<Eigen::MatrixXd> G(maxOrder + 1, Eigen::MatrixXd::Zero(n, n));
  const std::vector<double> b = breakpoints(U);
  for (size_t s = 0; s + 1 < b.size(); ++s) {
    const double a0 = b[s], a1 = b[s + 1];
    const int span = findSpan(U, p, 0.5 * (a0 + a1));
    for (size_t q = 0; q < gx.size(); ++q) {
      const double u = 0.5 * (a0 + a1) + 0.5 * (a1 - a0) * gx[q], w = 0.5 * (a1 - a0) * gw[q];
      const Eigen::MatrixXd N = basisDerivatives(U, p, span, u, std::min(maxOrder, p));
      for (int k = 0; k <= std::min(maxOrder, p); ++k)
        for (int i = 0; i <= p; ++i)
          for (int j = 0; j <= p; ++j) G[k](span - p + i, span - p + j) += w * N(k, i) * N(k, j);
    }
  }
  return G;
}

}  // namespace

Eigen::SparseMatrix<double> fairnessMatrix(int pu, const std::vector<double>& U, int pv, const std::vector<double>& V,
                                           const FairnessWeights& w) {
  const int nu = static_cast<int>(U.size()) - pu - 1, nv = static_cast<int>(V.size()) - pv - 1;
  // The energy is a sum of separable terms c * ∫∫ (N_i^(k)(u) N_j^(l)(v))², so each term's matrix is
  // the Kronecker product of two 1D Gram matrices: Gu[k] ⊗ Gv[l].
  const std::vector<Eigen::MatrixXd> Gu = gramMatrices(pu, U, 3), Gv = gramMatrices(pv, V, 3);
  struct Term { int k, l; double c; };
  const Term terms[] = {{2, 0, w.bending}, {1, 1, 2 * w.bending}, {0, 2, w.bending},
                        {3, 0, w.rateOfBending}, {2, 1, 3 * w.rateOfBending},
                        {1, 2, 3 * w.rateOfBending}, {0, 3, w.rateOfBending}};
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(static_cast<size_t>(nu) * nv * (2 * pu + 1) * (2 * pv + 1));
  for (int i = 0; i < nu; ++i)
    for (int i2 = std::max(0, i - pu); i2 <= std::min(nu - 1, i + pu); ++i2)
      for (int j = 0; j < nv; ++j)
        for (int j2 = std::max(0, j - pv); j2 <= std::min(nv - 1, j + pv); ++j2) {
          double v = 0.0;
          for (const Term& t : terms)
            if (t.c != 0.0 && t.k <= pu && t.l <= pv) v += t.c * Gu[t.k](i, i2) * Gv[t.l](j, j2);
          if (v != 0.0) trip.emplace_back(i * nv + j, i2 * nv + j2, v);
        }
  Eigen::SparseMatrix<double> A(nu * nv, nu * nv);
  A.setFromTriplets(trip.begin(), trip.end());
  return A;
}

}  // namespace holefill
