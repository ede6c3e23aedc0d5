#include "gnurbs/spoke_conditions.h"

#include <cmath>

#include "geometry/bspline_basis.h"

namespace holefill {

double eigenPolyhedronB(int valence) { return 2 * std::cos(2 * M_PI / valence); }

double connectionRho(int valence) {
  if (valence == 3) return valence3Rho(isolatedBetaSlope(eigenPolyhedronB(3)));
  if (valence <= 5) return 0.25;
  static const double measured[] = {-5, -4.25, -4.5, -4.75, -5, -5.25, -5.25, -5.375, -5.4, -5.5, -5.6};  // valence 6..16
  return valence <= 16 ? measured[valence - 6] : -5.7;
}


void appendSpokeConditions(const SpokeConnection& k, const std::function<int(int, int)>& a,
                           const std::function<int(int, int)>& b, std::vector<GridCondition>& out) {
  static const std::vector<double> bezier5 = {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
  constexpr int nodes = 9;  // both identities have degree <= 8 in σ
  for (int half = 0; half < 2; ++half) {
    for (int q = 0; q < nodes; ++q) {
      const double sigma = 0.5 * (1 - std::cos(M_PI * (q + 0.5) / nodes));
      double beta, rho;
      // Each half takes the connection of the EP at its own end; a half that ends regular has none.
      const double w = std::pow(1 - sigma, 3), wFar = std::pow(sigma, 3);
      if (half == 0) {
        beta = k.b0 * w;
        rho = k.r * w;
      } else {
        beta = k.epAtBothEnds ? -k.b1 * wFar : 0.0;
        rho = k.epAtBothEnds ? k.r1 * wFar : 0.0;
      }
      const Eigen::MatrixXd B = basisDerivatives(bezier5, 5, 5, sigma, 1);  // B(0, i) values, B(1, i) derivatives
      GridCondition g1, g2;
      for (int i = 0; i < 6; ++i) {
        const int m = 5 * half + i;
        const double v = B(0, i), dv = B(1, i);
        // Local (sub-patch) derivatives: X_t = 5 Σ B_i (X_i1 − X_i0), X_tt = 20 Σ B_i (X_i2 − 2 X_i1 + X_i0),
        // X_s = Σ B_i' X_i0, W_s = 5 Σ B_i' (…) — the factor 2 of the half-spoke parameter cancels.
        auto add = [](GridCondition& c, int id, double w) { c.terms.emplace_back(id, w); };
        // (3): A_t/dA + B_t/dB − β A_s/dS.
        add(g1, a(m, 1), 5 * v / k.dA);
        add(g1, a(m, 0), -5 * v / k.dA - 5 * v / k.dB - beta * dv / k.dS);
        add(g1, b(m, 1), 5 * v / k.dB);
        // (8): B_tt/dB² − A_tt/dA² − ½ρ W + β W_s/dS, W = A_t/dA − B_t/dB.
        const double wa = 5 * (-0.5 * rho * v + beta * dv / k.dS) / k.dA;  // coefficient of (A_i1 − A_i0) in −½ρW + βW_s
        const double wb = -wa * k.dA / k.dB;                               // and of (B_i1 − B_i0)
        add(g2, b(m, 2), 20 * v / (k.dB * k.dB));
        add(g2, b(m, 1), -40 * v / (k.dB * k.dB) + wb);
        add(g2, a(m, 2), -20 * v / (k.dA * k.dA));
        add(g2, a(m, 1), 40 * v / (k.dA * k.dA) + wa);
        add(g2, a(m, 0), 20 * v / (k.dB * k.dB) - 20 * v / (k.dA * k.dA) - wa - wb);
      }
      out.push_back(std::move(g1));
      out.push_back(std::move(g2));
    }
  }
}

}  // namespace holefill
