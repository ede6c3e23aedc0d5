// Fairness energy of a B-spline surface as a quadratic form in its poles
// (uvtran.md Eq. 3 and App. A, after Welch & Witkin 1992):
//   E = wb * ∫∫ |S_uu|² + 2|S_uv|² + |S_vv|²  +  wr * ∫∫ |S_uuu|² + 3|S_uuv|² + 3|S_uvv|² + |S_vvv|²
// = Σ_c P_c^T A P_c over the three coordinates c. Each term is separable, so A is a sum of
// Kronecker products of 1D Gram matrices of basis derivatives, which are exact (Gauss-Legendre
// per knot span with enough nodes for the polynomial products).
#pragma once

#include <Eigen/Sparse>
#include <vector>

namespace holefill {

struct FairnessWeights {
  double bending = 0.3;         // weight of the thin-plate (bending) term; Rhino's patch uses 0.3
  double rateOfBending = 0.7;   // weight of the rate-of-bending term; Rhino's patch uses 0.7
};

// n×n symmetric positive semi-definite matrix, n = number of poles (index i*numV + j).
Eigen::SparseMatrix<double> fairnessMatrix(int degreeU, const std::vector<double>& knotsU, int degreeV,
                                           const std::vector<double>& knotsV, const FairnessWeights& w);

}  // namespace holefill
