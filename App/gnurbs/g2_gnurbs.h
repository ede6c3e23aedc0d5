// G² G-NURBS surface of a quad cage (g2-gnurbs.md secs. 2-4): the guidance surface's bicubic
// patch on every face outside EP 1-rings, and on each face of an EP 1-ring a 2×2 grid of
// biquintic patches (the guidance patch elevated and split, sec. 2) whose coefficients are
// re-solved so that every spoke edge is G² (spoke_conditions.h) and the face stays C² inside
// and C² to its regular neighbours. The solve covers each EP, or each pair of EPs joined by an
// edge, with its 1-ring faces. The three coefficient rows along every face edge that is not a
// spoke stay the guidance's ("gray"), which is what keeps the join to regular patches C². The
// other coefficients are chosen under the exact constraints either by our fair solve (the
// default, see G2GnurbsOptions) or by the paper's stepwise least squares (sec. 4.1):
//   1. red/green/blue: the spoke rows 0-1 of the EP sub-patches and row 2 up to column 2, for
//      all spokes jointly, nearest to the guidance in values and differences (eq. (21));
//   2. black: columns 6-7 of the spoke rows beyond the EP sub-patch (fixed by C², eq. (11));
//   3. yellow: row 2, columns 3-5 (eq. (22));
//   4. the rest of each face by thin-plate energy under the C² conditions between its
//      sub-patches (sec. 4.1.3).
// Each step satisfies the projections of all constraints that the later steps need
// (stepwise_least_squares.h), so the conditions hold to solver round-off either way.
// Knot intervals may vary freely except on an EP's own spokes: where those differ, the bicubic
// extraction (whose face points blend the intervals of parallel rows) is not C² across a spoke
// even at its regular end, the gray rows cannot meet the spoke conditions there, and the result
// carries a warning with the residual. Adjacent EPs share one problem (sec. 3.2.2) rather than
// the paper's two decoupled ones; a pair is at most 2N−2 faces. Their shared spoke uses a
// connection of our own (spoke_conditions.h): G² holds exactly; the tangent star at an EP next
// to another can be less round than the guidance's (σ₂/σ₁ 0.60 against the guidance's 0.99 at a
// valence-3 EP next to a valence-5 one); a Catmull–Clark step separates such EPs when that
// matters.
// Sharp edges make C0 creases. At an EP with sharp spokes (a sharp EP) the smooth spokes keep
// their G² conditions and the crease rows are the guidance's crease curves, which the
// extraction ends at the EP as at a corner; the EP sits at its cage vertex, or at its anchor
// (sec. 5.1, V_EP = A_EP), which moves only the EP's 1-ring. Creases elsewhere in a 1-ring make
// the cage refined once; creases ending or turning at regular vertices are reported.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "geometry/bspline_surface.h"
#include "gnurbs/stepwise_least_squares.h"
#include "gnurbs/patch_continuity.h"
#include "gnurbs/quad_cage.h"

namespace holefill {

struct G2GnurbsOptions {
  // How the free coefficients of an EP's 1-ring are chosen, under the same exact constraints:
  //   Fair (default): one solve minimising the thin-plate energy of the change from the
  //     guidance surface over all 1-ring faces. Measured against Stepwise on the sample polar
  //     cages: max |mean curvature| in the 1-ring 0.39 against 1.03 at valence 8 and 0.27
  //     against 0.48 at valence 5; the stepwise red/green/blue fit freezes the low-degree EP half
  //     of each spoke before the rest is seen and leaves a curvature dipole just past the
  //     spoke's middle. Tangent stars at isolated EPs are the guidance's in both.
  //   Stepwise: the paper's sec. 4.1 steps as described above.
  enum class Solve { Fair, Stepwise };
  Solve solve = Solve::Fair;
  double fairPull = 1e-3;       // Fair: weight of the pull to the guidance's values
  // r_i of the connection function ρ; NaN: per valence (connectionRho, spoke_conditions.h).
  // Any other value applies at every EP but valence 3, whose r is forced (valence3Rho).
  double rho = std::nan("");
  // Cages whose EPs are too close (a face with two EPs not on one edge, three EPs joined by
  // edges) or with a sharp edge touching an EP's 1-ring get one Catmull–Clark step first
  // (catmull_clark.h); false: throw instead.
  bool refineWhenNeeded = true;
  StepwiseOptions solver;       // rank and regularisation thresholds of the stepwise solve
  // Extraordinary points of higher valence are refused with a clear error rather than solved
  // for minutes: an EP's cluster solve grows as its valence to the 3.5th power (measured on 2
  // cores, one EP: valence 10 0.4 s, 20 2.4 s, 30 8.8 s, 50 32 s); quad cages in practice stay
  // far below 24 (about 4 s). 0: no limit.
  int maxValence = 24;
};

struct GnurbsPatch {
  int face = -1;  // control face
  int sub = -1;   // -1: the face's bicubic patch; 0..3: sub-patch in splitBezier order (bezier_patch.h)
  BSplineSurface surface;
};

struct G2GnurbsResult {
  QuadCage cage;                          // the cage the patches are over: the input, or its refinement
  int refinements = 0;                    // Catmull–Clark steps applied to the input (0 or 1)
  std::string refinementReason;           // why, naming the EPs of the input cage
  std::vector<GnurbsPatch> patches;       // in control-face order, a face's sub-patches in order
  std::vector<int> extraordinaryPoints;
  int irregularFaces = 0;                 // faces in EP 1-rings (4 biquintic patches each)
  int clusters = 0;                       // independent solves: single EPs and adjacent pairs
  double constraintResidual = 0;          // max |M x − c| over all solves (model units / knot units²)
  double infeasibility = 0;               // largest residual a step could not remove; ~0 on valid input
  std::vector<std::string> warnings;      // e.g. an EP whose conditions could not all be met, and why
};

// Throws Error for invalid cages (CageTopology), anchors away from EPs, and cages needing a
// refinement when options.refineWhenNeeded is off.
G2GnurbsResult buildG2Gnurbs(const QuadCage& cage, const G2GnurbsOptions& options = {});

// buildG2Gnurbs for many cages of one topology (fitting, interactive editing): the cluster
// factorisations depend only on topology and knot intervals, so they are kept between builds.
class G2GnurbsBuilder {
public:
  explicit G2GnurbsBuilder(const G2GnurbsOptions& options = {});
  ~G2GnurbsBuilder();
  G2GnurbsResult build(const QuadCage& cage);

private:
  struct Cache;
  G2GnurbsOptions options_;
  std::unique_ptr<Cache> cache_;
};

// The surface over each control face in face parameters (sub-patches rescaled), for
// cageEdgeContinuity and evaluation; `result` must outlive the function.
FaceJetFunction faceJets(const G2GnurbsResult& result);

}  // namespace holefill
