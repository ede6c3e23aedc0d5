// B-spline basis functions over a full (clamped) knot vector: span search,
// values and derivatives of the p+1 non-zero basis functions, knot vectors,
// and Gauss-Legendre rules for exact integrals of basis products. Algorithms
// A2.1 and A2.3 of Piegl & Tiller, "The NURBS Book" (2nd ed., ch. 2); used by
// the variational fill (Welch & Witkin 1992 energies, uvtran.md Sec. 3 & App. A).
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace holefill {

// Index of the knot span [U[s], U[s+1]) holding u, with p <= s <= n where
// n + 1 = U.size() - p - 1 is the number of basis functions; u at the right end maps to the last span.
int findSpan(const std::vector<double>& U, int p, double u);

// ders(k, j) = k-th derivative of N_{span-p+j, p} at u, for k = 0..nd, j = 0..p.
Eigen::MatrixXd basisDerivatives(const std::vector<double>& U, int p, int span, double u, int nd);

// Clamped knot vector of degree p on [a, b] with nSpans equal spans.
std::vector<double> clampedUniformKnots(int p, int nSpans, double a, double b);

// Distinct knot values (breakpoints) of a knot vector, in increasing order.
std::vector<double> breakpoints(const std::vector<double>& U);

// Gauss-Legendre nodes and weights of order n (1..8) on [-1, 1].
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace holefill
