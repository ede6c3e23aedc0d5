#include "geometry/bspline_basis.h"

#include <cmath>

#include "geometry/error.h"

namespace holefill {

int findSpan(const std::vector<double>& U, int p, double u) {
  const int n = static_cast<int>(U.size()) - p - 2;
  HF_CHECK(n >= p, "knot vector too short for its degree");
  if (u >= U[n + 1]) return n;
  if (u <= U[p]) return p;
  int low = p, high = n + 1, mid = (low + high) / 2;
  while (u < U[mid] || u >= U[mid + 1]) {
    if (u < U[mid]) high = mid; else low = mid;
    mid = (low + high) / 2;
  }
  return mid;
}

Eigen::MatrixXd basisDerivatives(const std::vector<double>& U, int p, int span, double u, int nd) {
  // The NURBS Book A2.3, with ndu holding basis values (upper) and knot differences (lower).
  Eigen::MatrixXd ndu(p + 1, p + 1), a(2, p + 1), ders = Eigen::MatrixXd::Zero(nd + 1, p + 1);
  std::vector<double> left(p + 1), right(p + 1);
  ndu(0, 0) = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu(j, r) = right[r + 1] + left[j - r];
      const double temp = ndu(r, j - 1) / ndu(j, r);
      ndu(r, j) = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu(j, j) = saved;
  }
  for (int j = 0; j <= p; ++j) ders(0, j) = ndu(j, p);
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a(0, 0) = 1.0;
    for (int k = 1; k <= nd; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a(s2, 0) = a(s1, 0) / ndu(pk + 1, rk);
        d = a(s2, 0) * ndu(rk, pk);
      }
      const int j1 = (rk >= -1) ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a(s2, j) = (a(s1, j) - a(s1, j - 1)) / ndu(pk + 1, rk + j);
        d += a(s2, j) * ndu(rk + j, pk);
      }
      if (r <= pk) {
        a(s2, k) = -a(s1, k - 1) / ndu(pk + 1, r);
        d += a(s2, k) * ndu(r, pk);
      }
      ders(k, r) = d;
      std::swap(s1, s2);
    }
  }
  double f = p;
  for (int k = 1; k <= nd; ++k) {
    ders.row(k) *= f;
    f *= (p - k);
  }
  return ders;
}

std::vector<double> clampedUniformKnots(int p, int nSpans, double a, double b) {
  HF_CHECK(nSpans >= 1 && b > a, "a knot vector needs at least one span on a non-empty interval");
  std::vector<double> U;
  for (int i = 0; i <= p; ++i) U.push_back(a);
  for (int i = 1; i < nSpans; ++i) U.push_back(a + (b - a) * i / nSpans);
  for (int i = 0; i <= p; ++i) U.push_back(b);
  return U;
}

std::vector<double> breakpoints(const std::vector<double>& U) {
  std::vector<double> b;
  for (double u : U)
    if (b.empty() || u > b.back()) b.push_back(u);
  return b;
}

void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  HF_CHECK(n >= 1 && n <= 8, "Gauss-Legendre order must be 1..8");
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  // Newton iteration on the Legendre polynomial from Chebyshev guesses: exact to machine precision for n <= 8.
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), pp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p1 = 1.0, p2 = 0.0;
      for (int j = 1; j <= n; ++j) {
        const double p3 = p2;
        p2 = p1;
        p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j;
      }
      pp = n * (z * p1 - p2) / (z * z - 1.0);
      const double z1 = z;
      z = z1 - p1 / pp;
      if (std::abs(z - z1) < 1e-15) break;
    }
    x[i] = -z;
    w[i] = 2.0 / ((1.0 - z * z) * pp * pp);
  }
}

}  // namespace holefill
