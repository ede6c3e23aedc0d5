// The variational fill (uvtran.md Sec. 3, Eq. 3-6 and App. A; Welch & Witkin 1992):
// the clamped bicubic B-spline S over a rectangular domain that minimizes
//   fairness(S)  +  G0: Σ w_k |S(uv_k) - B_k|²
//                +  G1: Σ w_k [(S_u·n_k)² + (S_v·n_k)²]                 (linear in the poles)
//                +  G2: Σ w_k (II_S(d_k, d_k)·n_k - κ_k |d_k|²)²       (linearized about the last S)
// at the boundary samples (uv_k = pcurve samples, B_k, n_k, κ_k from the support faces).
//
// Solver: the constraint terms are imposed by an augmented Lagrangian on the same
// factorization (sparse LDLT of the normal equations, the poles eliminated in a band along the
// grid's shorter side; targets are shifted by the
// residual each round), so tolerances far below what a pure penalty reaches are met
// without ill-conditioned weights. Where samples still violate the tolerances, knots
// are inserted at the middle of the u- and v-spans holding them (only spans that hold
// enough samples to pin both halves) and the problem is solved again, until the
// tolerances hold, maxControlPoints is reached, maxRefinements rounds are done, or no
// span can be split (samplesTooSparse: the caller resamples the boundary denser). G2 re-linearizes curvatureIterations times. Everything is solved in
// the caller's (normalized) coordinates; tolerances are in those units.
// HOLEFILL_DEBUG=1 in the environment prints per-level diagnostics (poles, errors, timings) to stderr.
//
// Limits: continuity that the data does not admit (support normals disagreeing at a
// corner, a pcurve that squeezes a boundary feature) cannot be met; the result then
// reports the achieved errors and the violating samples, never a silent downgrade.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "fill/fairness_energy.h"
#include "geometry/bspline_surface.h"

namespace holefill {

enum class Continuity { G0 = 0, G1 = 1, G2 = 2 };
Continuity continuityFromString(const std::string& s);  // "G0" | "G1" | "G2"
std::string toString(Continuity c);

struct FillConstraints {
  std::vector<Eigen::Vector2d> uv;       // pcurve samples on the domain
  std::vector<Eigen::Vector3d> point;    // boundary positions B_k
  std::vector<Eigen::Vector3d> normal;   // unit support normals (ignored where normalValid is false)
  std::vector<Eigen::Vector3d> across;   // unit cross-boundary directions in the support tangent plane
  std::vector<double> curvature;         // support normal curvature along `across`
  std::vector<double> weight;            // arc-length weights
  std::vector<bool> normalValid;
  std::vector<int> edge;                 // boundary edge of each sample (pcurve tangents stay within an edge)
  std::vector<int> order;                // continuity imposed at each sample (0..2, at most the options'); empty: the options'
  std::vector<Eigen::Vector2d> referenceUV;   // optional soft interior reference points
  std::vector<Eigen::Vector3d> referenceXYZ;
  // Points inside the hole the surface passes through (GeomPlate's point constraints, Surface
  // Filling's "vertices"): S(passUV_p) = passXYZ_p, held to the G0 tolerance as the boundary is
  // (position rows with multipliers; spans holding a missed one are split).
  std::vector<Eigen::Vector2d> passUV;
  std::vector<Eigen::Vector3d> passXYZ;
  size_t size() const { return uv.size(); }
  // The continuity order imposed at sample k under `highest` (a crease edge's samples ask G0 only).
  int orderAt(size_t k, Continuity highest) const {
    return order.empty() ? static_cast<int>(highest) : std::min(order[k], static_cast<int>(highest));
  }
};

struct VariationalFillOptions {
  Continuity continuity = Continuity::G1;  // highest order imposed
  double g0Tolerance = 1e-6;     // max |S(uv_k) - B_k| (solve units = hole scale); DESIGN strict tier
  double g1Tolerance = 1e-3;     // max normal angle (radians); DESIGN strict tier
  double g2Tolerance = 0.1;      // max relative curvature deviation; DESIGN tier
  FairnessWeights fairness;      // bending 0.3, rate of bending 0.7
  // Penalties, relative to the mean diagonal of the fairness matrix and normalized per row;
  // the augmented-Lagrangian rounds remove their bias, so they only set the convergence rate.
  double positionWeight = 1e5;   // G0 rows
  double normalWeight = 1e4;     // G1 rows
  double curvatureWeight = 1e3;  // G2 rows
  double referenceWeight = 1e-1; // soft pull to interior reference points (MVC), no multiplier
  double tangentGuideWeight = 1e-4; // soft pull of the cross-boundary derivative towards `across`
  int initialSpans = 10;          // spans along the longer domain side before refinement
  int maxControlPoints = 2500;   // refinement stops before exceeding this many poles
  int minSamplesPerSplit = 4;    // a span is split only while it holds this many boundary samples: a
                                 // span finer than the samples is pinned by none of them and rings
                                 // between them (seen as G0 misses between samples on real edges)
  int maxRefinements = 7;        // knot-insertion rounds
  int multiplierIterations = 40; // augmented-Lagrangian rounds per solve
  double multiplierMargin = 0.01;// rounds continue until every error is below this fraction of its tolerance
  int curvatureIterations = 3;   // G2 re-linearizations per refinement level
  std::function<bool(double)> progress;  // called with a fraction in [0,1]; return false to cancel
};

struct VariationalFillResult {
  BSplineSurface surface;
  double g0 = 0, g1 = 0, g2 = 0;  // max errors at the samples (solve units, radians, relative)
  double passError = 0;           // max |S(passUV) - passXYZ| (solve units); counted as G0
  bool toleranceMet = false;
  int levelMet = -1;           // highest order met in sequence at the samples: -1 none, 0 G0, 1 G0+G1, 2 all
  double worstRatio = 0;       // the worst error relative to its tolerance at the samples
  bool cancelled = false;
  int refinements = 0;
  bool samplesTooSparse = false;  // refinement stopped where the spans hold too few samples to split
  std::vector<int> violatingSamples;
  std::vector<std::string> warnings;
};

// Solves on [u0,u1]x[v0,v1]; knotsU/knotsV give the initial clamped cubic knots (empty: uniform).
VariationalFillResult solveVariationalFill(const FillConstraints& c, double u0, double u1, double v0, double v1,
                                           std::vector<double> knotsU, std::vector<double> knotsV,
                                           const VariationalFillOptions& options = {});

}  // namespace holefill
