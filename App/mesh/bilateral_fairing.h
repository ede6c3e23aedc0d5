// Fairing of a refined patch by the bilateral mesh filter of Fleishman, Drori and Cohen-Or
// as Hu et al. apply it (section III.D): each new vertex v moves along its area-weighted
// normal n by the weighted mean of the offsets h_i = <n, v − q_i> of its 1-ring neighbours,
// with closeness weights exp(−t²/2σ_c²), t = |v − q_i|, and feature weights exp(−h²/2σ_s²);
// loop vertices never move. The paper's pseudo-code adds n·mean where Fleishman subtracts;
// adding pushes v away from its neighbours' plane, so we subtract.
// σ_c and σ_s scale with the local density d_v, the mean distance from v to its 1-ring. The
// paper sets them to "0.1 and 0.5 of the current vertex density" but also says the
// neighbourhood radius is assigned to σ_c; with the 1-ring as neighbourhood, σ_c = 0.1·d_v
// would give neighbours at 0.8·d_v and 1.2·d_v weights e^40 apart (the filter degenerates to
// the nearest neighbour), so the default reads σ_c as the neighbourhood radius, σ_c = d_v,
// and keeps σ_s = 0.5·d_v. Both factors are options.
#pragma once

#include "mesh/hole_patch.h"

namespace holefill {

struct BilateralOptions {
  int iterations = 3;                  // paper
  double closenessScale = 1.0;         // σ_c = closenessScale · d_v (see above)
  double featureScale = 0.5;           // σ_s = featureScale · d_v (paper)
};

struct BilateralResult {
  double maxMove = 0;                  // largest displacement of a vertex in the last iteration
};

BilateralResult bilateralFair(HolePatch& patch, const BilateralOptions& options = {});

}  // namespace holefill
