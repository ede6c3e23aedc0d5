#include "fill/fairness_energy.h"

#include "geometry/bspline_basis.h"

namespace holefill {

Eigen::SparseMatrix<double> fairnessMatrix(int pu, const std::vector<double>& U, int pv, const std::vector<double>& V,
                                           const FairnessWeights& w) {
  const int nu = static_cast<int>(U.size()) - pu - 1, nv = static_cast<int>(V.size()) - pv - 1;
  const int n = nu * nv;
  // Products of derivatives of order >= 2 have degree <= 2p-4 per direction; p+1 nodes are exact.
  std::vector<double> gx, gw;
  gaussLegendre(std::max(pu, pv) + 1, gx, gw);
  const std::vector<double> bu = breakpoints(U), bv = breakpoints(V);
  // The terms as (k, l, coefficient) meaning coefficient * |d^{k+l}S / du^k dv^l|².
  struct Term { int k, l; double c; };
  std::vector<Term> terms = {{2, 0, w.bending}, {1, 1, 2 * w.bending}, {0, 2, w.bending},
                             {3, 0, w.rateOfBending}, {2, 1, 3 * w.rateOfBending},
                             {1, 2, 3 * w.rateOfBending}, {0, 3, w.rateOfBending}};
  const int m = (pu + 1) * (pv + 1);
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd local(m, m);
  Eigen::VectorXd g(m);
  for (size_t a = 0; a + 1 < bu.size(); ++a)
    for (size_t b = 0; b + 1 < bv.size(); ++b) {
      const double u0 = bu[a], u1 = bu[a + 1], v0 = bv[b], v1 = bv[b + 1];
      const int su = findSpan(U, pu, 0.5 * (u0 + u1)), sv = findSpan(V, pv, 0.5 * (v0 + v1));
      local.setZero();
      for (size_t qi = 0; qi < gx.size(); ++qi)
        for (size_t qj = 0; qj < gx.size(); ++qj) {
          const double u = 0.5 * (u0 + u1) + 0.5 * (u1 - u0) * gx[qi];
          const double v = 0.5 * (v0 + v1) + 0.5 * (v1 - v0) * gx[qj];
          const double jac = 0.25 * (u1 - u0) * (v1 - v0) * gw[qi] * gw[qj];
          const Eigen::MatrixXd Nu = basisDerivatives(U, pu, su, u, std::min(3, pu));
          const Eigen::MatrixXd Nv = basisDerivatives(V, pv, sv, v, std::min(3, pv));
          for (const Term& t : terms) {
            if (t.c == 0.0 || t.k > pu || t.l > pv) continue;
            for (int i = 0; i <= pu; ++i)
              for (int j = 0; j <= pv; ++j) g(i * (pv + 1) + j) = Nu(t.k, i) * Nv(t.l, j);
            local.noalias() += (t.c * jac) * g * g.transpose();
          }
        }
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
          const int gi = (su - pu + i / (pv + 1)) * nv + (sv - pv + i % (pv + 1));
          const int gj = (su - pu + j / (pv + 1)) * nv + (sv - pv + j % (pv + 1));
          trip.emplace_back(gi, gj, local(i, j));
        }
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  return A;
}

}  // namespace holefill
