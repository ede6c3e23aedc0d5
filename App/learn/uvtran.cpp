#include "learn/uvtran.h"

#include <algorithm>
#include <chrono>

#include "geometry/error.h"
#include "geometry/surface_projection.h"
#include "learn/learn_library.h"
#include "learn/uvtran_data.h"

namespace holefill::learn {

namespace {

// The loop as the network sees it; `backwards` feeds it in reverse order, which turns the
// canonical frame half a turn about x, so the network answers in v-mirrored parameters.
CanonicalBoundary networkInput(std::vector<Eigen::Vector3d> loop, bool backwards, std::vector<double>& in) {
  if (backwards) std::reverse(loop.begin(), loop.end());
  CanonicalBoundary cb = canonicalizeBoundary(loop);
  for (const auto& q : cb.points) in.insert(in.end(), {q.x(), q.y(), q.z()});
  return cb;
}

// The network's answer in model coordinates, mirrored back in v (pole columns and v knots
// reversed) when it was asked with the loop backwards: always the forward convention.
BSplineSurface surfaceFrom(const double* poles, const double* knots, const CanonicalFrame& frame, bool backwards) {
  BSplineSurface s;
  std::vector<double> kv = {knots[4], knots[5], knots[6], knots[7]};
  if (backwards) kv = {1 - knots[7], 1 - knots[6], 1 - knots[5], 1 - knots[4]};
  s.knotsU = clampedCubicKnots({knots[0], knots[1], knots[2], knots[3]});
  s.knotsV = clampedCubicKnots(kv);
  s.poles.resize(64, 3);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const int k = 8 * i + (backwards ? 7 - j : j);
      const Eigen::Vector3d q(poles[3 * k], poles[3 * k + 1], poles[3 * k + 2]);
      if (!q.allFinite()) throw Error("UVTran predicted a non-finite control point");
      s.poles.row(s.index(i, j)) = frame.toModel(q).transpose();  // B-splines are affine invariant
    }
  return s;
}

}  // namespace

UvtranPrediction predictUvtran(const std::vector<Eigen::Vector3d>& loop, const UvtranOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  UvtranPrediction p;
  std::vector<double> in;
  const CanonicalBoundary fwd = networkInput(loop, false, in);  // input errors first, before the library
  p.weights = opt.weights.empty() ? defaultUvtranWeights() : opt.weights;
  if (p.weights.empty())
    throw Error("no UVTran weights found (looked for Resources/models/uvtran.pt; set HOLEFILL_UVTRAN_WEIGHTS)");
  const LearnLibrary& lib = learnLibrary();
  CanonicalFrame back;
  if (opt.augment) back = networkInput(loop, true, in).frame;  // both directions in one batch
  const int batch = opt.augment ? 2 : 1;
  const int n = static_cast<int>(fwd.points.size());
  std::vector<double> poles(batch * 64 * 3), knots(batch * 8);
  char err[512] = {0};
  if (lib.predict(p.weights.c_str(), in.data(), batch, n, opt.threads, poles.data(), knots.data(), err, sizeof err))
    throw Error(std::string("UVTran: ") + err);
  p.surface = surfaceFrom(poles.data(), knots.data(), fwd.frame, false);
  if (opt.augment) {
    const BSplineSurface b = surfaceFrom(poles.data() + 64 * 3, knots.data() + 8, back, true);
    // Same knot structure (4 interior knots each way): average knots and poles.
    for (size_t k = 0; k < p.surface.knotsU.size(); ++k) {
      p.surface.knotsU[k] = 0.5 * (p.surface.knotsU[k] + b.knotsU[k]);
      p.surface.knotsV[k] = 0.5 * (p.surface.knotsV[k] + b.knotsV[k]);
    }
    p.surface.poles = 0.5 * (p.surface.poles + b.poles);
  }
  ProjectionOptions po;
  po.extension = 0.25;
  const ProjectionResult r = projectSequence(p.surface, loop, po);
  p.uv = r.uv;
  for (double d : r.distance) p.maxDistance = std::max(p.maxDistance, d);
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace holefill::learn
