// G² conditions across a spoke edge of an EP 1-ring as linear conditions on Bézier
// coefficients (g2-gnurbs.md sec. 3). The faces A and B on the two sides of the spoke are each
// a 2×2 grid of biquintic patches, i.e. 11×11 coefficients; along the spoke, s runs from the
// EP (m = 0) to the other end (m = 10) and t into each face (n = 0 on the spoke). With the
// knot intervals d_s of the spoke and d_A, d_B across it (the intervals of the faces' other
// edges at the EP) the patches are G² along the spoke when, for s on the spoke,
//   (3)  A_t/d_A + B_t/d_B = β(s) A_s/d_s                                    (G1, α = γ = 1)
//   (8)  B_tt/d_B² − A_tt/d_A² = ½ρ(s) W − β(s) W_s/d_s,  W = A_t/d_A − B_t/d_B
// (eq. (8) is eq. (4) with the symmetrising choice δ = ββ' − ½βρ of eq. (6); it yields G² only
// together with (3)). The connection functions:
//   EP with a regular other end (sec. 3.2.1, the paper's): β = b(1 − σ)³, ρ = r(1 − σ)³ on the
//   half next to the EP (σ its own parameter), β = ρ = 0 on the other half, where (3) and (8)
//   then say that the two faces join C² in the knot-interval parameterisation;
//   EPs at both ends: each half takes the same connection from its own EP, β = b₀(1 − σ)³ and
//   β = −b₁σ³ (so β runs as b₁(1 − σ')³ from the far EP), ρ likewise, meeting C² at the middle.
//   The paper's eq. (16), β = b₀(1 − s) − b₁s and ρ = r along the whole spoke, was measured to
//   force a rank-1 tangent star at one or both EPs (σ₂/σ₁ of the tangents = 0 for valences 3+5,
//   5+6, 3+6, 3+3, 6+8; exact G1/G2 on every sample but the EP itself), as were mirrored
//   connections vanishing to order 2 or 4 at the middle; order 3 keeps every EP's own vertex
//   conditions those of an isolated EP.
// Each half of each condition is a polynomial identity of degree ≤ 8 in σ; it holds iff it
// holds at 9 distinct σ, which is how the rows are produced: exact, with no hand-expanded
// coefficient formulas (the paper's eqs. (12)-(20) are their consequences).
//
// b is the G1 connection constant at the EP, from its eigen-polyhedron (the characteristic
// configuration of G1 G-NURBS / G1 non-uniform Catmull–Clark). At s = 0, (3) says that the
// spoke tangents scaled to the knot-interval parameterisation, τ_k = ∂_s R_k / d_k, satisfy
// τ_{i−1} + τ_{i+1} = b_i τ_i around the EP. For planar τ_k this holds with a two-dimensional
// family of tangent stars only if every sector (0, τ_i, τ_{i+1}) has the same area (the cross
// product of the relation with τ_i), and the eigen-polyhedron's spokes, being parameter lines
// of the characteristic map, have unit speed in that parameterisation: |τ_k| equal. Equal
// areas and equal lengths give equal sector angles 2π/N, so b_i = 2 cos(2π/N) for every spoke,
// whatever the knot intervals (they enter through d_s, d_A, d_B instead). At valence 4, b = 0
// and (3), (8) are the C² conditions of the non-uniform bicubic B-spline.
//
// Valence 3 needs more than the paper says. At the EP, the σ-derivative of (3) and (8) at σ = 0
// tie the spokes' tangents T_i, second derivatives C_i and the sectors' twists X_i (uniform
// knots, σ the half-spoke parameter, β'_i and ρ_i spoke i's values at the EP):
//   X_i + X_{i−1} = β'_i T_i + b C_i,   C_{i−1} − C_{i+1} = ½ρ_i (T_{i+1} − T_{i−1}) − b (X_i − X_{i−1}).
// At N = 3 (b = −1, indices mod 3) eliminating C_i makes the twists cancel, leaving
//   (β'_{i−1} + ½ρ_i) T_{i−1} = (β'_{i+1} + ½ρ_i) T_{i+1}
// for every i. Two spoke tangents of a non-degenerate EP are independent, so all three spokes
// need the same β'(0) and ρ(0) = −2β'(0) (valence3Rho). With the paper's r = 1 the only
// solution is T = 0, a degenerate EP (measured: |∂S| = 3e-14 there). With a regular far end,
// β'(0) = −3b gives r = −6. On a spoke to a second EP, β is then quadratic (or cubic) rather
// than the paper's linear eq. (16), so that its slope at the valence-3 end is the same −3b;
// measured: with the linear β a valence-3 EP next to another EP had G1 errors of 1.5–2 rad.
// A connection function with β'(0) = ρ(0) = 0 would avoid the condition but was measured to
// over-constrain the spoke (β of degree 4 makes the spoke curve quadratic; constraint
// residual 8e-6). The derivation assumes equal spoke intervals around the valence-3 EP; other
// intervals there show as a non-zero infeasibility in the result.
#pragma once

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

namespace holefill {

// Σ coefficient · point(id) = 0 over grid-point ids, one scalar condition applied per coordinate.
struct GridCondition {
  std::vector<std::pair<int, double>> terms;
};

double eigenPolyhedronB(int valence);

struct SpokeConnection {
  double dS = 1, dA = 1, dB = 1;  // knot intervals: of the spoke, across it into A and into B
  double b0 = 0;                  // β at the EP end (s = 0)
  double r = 1;                   // ρ's scale r at the EP end (connectionRho)
  // With EPs at both ends: the far EP's b and r; the half next to it takes β = −b1 σ³,
  // ρ = r1 σ³ (its own EP's connection seen from this end).
  bool epAtBothEnds = false;
  double b1 = 0, r1 = 1;
};

// ρ's scale r at an EP of this valence. The paper takes r = 1; that is forced otherwise at
// valence 3 (valence3Rho) and folds the surface at valence 7 and above: measured on the planar
// regular N-sided polar cage, whose surface should stay an injective map with the regular
// star's angle sin(2π/N) as its smallest, r = 1 keeps that only up to valence 5 (valence 6:
// 0.67 against 0.87; valence 7-10 fold). The r that keep it form a window per valence (N = 5:
// [0, 1], 6: [-6.5, -4.75], 7: [-6.5, -4], 8: [-6.5, -4.25], 9: [-6.5, -4.5], 10: [-6.25, -4.75],
// 12: [-5.55, -5], 16: [-5.7, -5.45], 20: ≤ -5.65), and inside it the curvature next to the EP
// falls as r grows (on the curved polar cage with 4 rings, max |κ| × diagonal: valence 5 6.5 at
// r = 1, 2.3 at 0.25; valence 8 32 at -5.5, 8.9 at -4.5). The table takes one step of 0.25
// inside the window's upper end up to valence 11, the middle beyond, and -5.7 past valence 16.
double connectionRho(int valence);

// The slope β'(0) per half-spoke parameter that every spoke of a valence-3 EP with a regular
// far end has (β = b(1 − σ)³), and ρ(0) at a valence-3 EP whose spokes have slope β'(0).
inline double isolatedBetaSlope(double b) { return -3 * b; }
inline double valence3Rho(double betaSlope) { return -2 * betaSlope; }

// Appends the G1 and G2 conditions of the spoke; a(m, n), b(m, n) give the grid-point ids of
// faces A and B (m = 0..10 along the spoke from the EP, n = 0..2 into the face).
void appendSpokeConditions(const SpokeConnection& connection, const std::function<int(int, int)>& a,
                           const std::function<int(int, int)>& b, std::vector<GridCondition>& out);

}  // namespace holefill
