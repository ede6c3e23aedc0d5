// UVTran inference from the core (uvtran.md Algorithm 1, steps 3-4): canonicalize the hole's
// ordered boundary, let the network in libholefill_learn.so predict the projection surface,
// map it back to model coordinates, and project the boundary onto it; the projection's (u, v)
// are the pcurve. No torch here: the network is reached through learn_library.h.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geometry/bspline_surface.h"
#include "learn/canonical_boundary.h"

namespace holefill::learn {

struct UvtranOptions {
  std::string weights;  // empty: defaultUvtranWeights()
  int threads = 1;      // torch intra-op threads: the batch of two is too small to share (2 threads
                        // measured 150-500 ms per hole on a busy 2-core machine, 1 thread 10 ms)
  bool augment = true;  // test-time augmentation: also predict from the loop run backwards (which the
                        // network sees mirrored) and average the two surfaces
};

struct UvtranPrediction {
  BSplineSurface surface;           // projection surface, model coordinates, domain [0, 1]^2
  std::vector<Eigen::Vector2d> uv;  // pcurve: one per input loop point
  double maxDistance = 0;           // largest distance of a loop point from the surface (model units)
  double seconds = 0;               // network + projection
  std::string weights;
};

// `loop`: the ordered, closed hole boundary (any number >= 6 of points). Throws holefill::Error
// for bad input, missing library or weights; the caller decides on the fallback.
UvtranPrediction predictUvtran(const std::vector<Eigen::Vector3d>& loop, const UvtranOptions& options = {});

}  // namespace holefill::learn
