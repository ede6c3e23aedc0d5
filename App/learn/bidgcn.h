// BIDGCN inference from the core (bidgcn.md sec. 4): the interior points' (u, v) of a cloud whose
// boundary points carry theirs, predicted by the network in libholefill_learn.so and reached
// through learn_library.h (no torch here). The cloud must already be in the unit cube (sec. 4.3);
// the boundary parameters' bounding box is mapped onto [0, 1]² for the network, whose sigmoid
// answers there, and the answer is mapped back. A boundary sampled more densely than the
// training clouds' is thinned for the network (the rest keep their given parameters). Used by
// parameterizeCloud(..., Bidgcn).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace holefill::learn {

struct BidgcnOptions {
  std::string weights;  // empty: defaultBidgcnWeights()
  int threads = 1;      // torch intra-op threads (one cloud's graph work shares poorly on 2 cores)
};

// Returns uv per point: boundary rows as given, interior rows predicted. Throws holefill::Error
// for boundary parameters spanning no area, missing weights or library, or a failed prediction.
Eigen::MatrixX2d bidgcnParameters(const Eigen::MatrixX3d& unitCubePoints, const std::vector<bool>& boundary,
                                  const Eigen::MatrixX2d& boundaryUV, const BidgcnOptions& options = {});

}  // namespace holefill::learn
