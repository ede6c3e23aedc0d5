#include "learn/uvtran.h"

#include <chrono>

#include "geometry/error.h"
#include "geometry/surface_projection.h"
#include "learn/learn_library.h"
#include "learn/uvtran_data.h"

namespace holefill::learn {

UvtranPrediction predictUvtran(const std::vector<Eigen::Vector3d>& loop, const UvtranOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  UvtranPrediction p;
  const CanonicalBoundary cb = canonicalizeBoundary(loop);
  p.frame = cb.frame;
  p.weights = opt.weights.empty() ? defaultUvtranWeights() : opt.weights;
  if (p.weights.empty())
    throw Error("no UVTran weights found (looked for Resources/models/uvtran.pt; set HOLEFILL_UVTRAN_WEIGHTS)");
  const LearnLibrary& lib = learnLibrary();
  std::vector<double> in;
  for (const auto& q : cb.points) in.insert(in.end(), {q.x(), q.y(), q.z()});
  double poles[64 * 3], knots[8];
  char err[512] = {0};
  if (lib.predict(p.weights.c_str(), in.data(), static_cast<int>(cb.points.size()), opt.threads, poles, knots, err,
                  sizeof err) != 0)
    throw Error(std::string("UVTran: ") + err);
  BSplineSurface& s = p.surface;
  s.knotsU = clampedCubicKnots({knots[0], knots[1], knots[2], knots[3]});
  s.knotsV = clampedCubicKnots({knots[4], knots[5], knots[6], knots[7]});
  s.poles.resize(64, 3);
  for (int i = 0; i < 64; ++i) {
    const Eigen::Vector3d q(poles[3 * i], poles[3 * i + 1], poles[3 * i + 2]);
    if (!q.allFinite()) throw Error("UVTran predicted a non-finite control point");
    s.poles.row(i) = cb.frame.toModel(q).transpose();  // B-splines are affine invariant
  }
  const ProjectionResult r = projectSequence(s, loop);
  p.uv = r.uv;
  for (double d : r.distance) p.maxDistance = std::max(p.maxDistance, d);
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace holefill::learn
