#include "learn/bidgcn.h"

#include "geometry/error.h"
#include "learn/learn_library.h"

namespace holefill::learn {

Eigen::MatrixX2d bidgcnParameters(const Eigen::MatrixX3d& p, const std::vector<bool>& boundary, const Eigen::MatrixX2d& boundaryUV,
                                  const BidgcnOptions& o) {
  const int n = static_cast<int>(p.rows());
  HF_CHECK(static_cast<int>(boundary.size()) == n && boundaryUV.rows() == n, "BIDGCN: boundary flags or parameters do not match the points");
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (int k = 0; k < n; ++k)
    if (boundary[k]) lo = lo.cwiseMin(boundaryUV.row(k).transpose()), hi = hi.cwiseMax(boundaryUV.row(k).transpose());
  const Eigen::Vector2d span = hi - lo;
  if (!(span.minCoeff() > 1e-12 * std::max(1.0, span.maxCoeff())))
    throw Error("BIDGCN: the boundary parameters span no area in (u, v); the network needs them around a domain");
  const std::string weights = o.weights.empty() ? defaultBidgcnWeights() : o.weights;
  if (weights.empty()) throw Error("no BIDGCN weights found (looked for Resources/models/bidgcn.pt; set HOLEFILL_BIDGCN_WEIGHTS)");
  const LearnLibrary& lib = learnLibrary();
  std::vector<double> xyz(3 * n), uv(2 * n, 0.0);
  std::vector<unsigned char> flags(n);
  for (int k = 0; k < n; ++k) {
    for (int d = 0; d < 3; ++d) xyz[3 * k + d] = p(k, d);
    flags[k] = boundary[k];
    if (boundary[k])
      for (int d = 0; d < 2; ++d) uv[2 * k + d] = (boundaryUV(k, d) - lo(d)) / span(d);
  }
  char err[512] = {0};
  if (lib.bidgcnPredict(weights.c_str(), xyz.data(), flags.data(), n, o.threads, uv.data(), err, sizeof err))
    throw Error(std::string(err).find("BIDGCN") == std::string::npos ? std::string("BIDGCN: ") + err : std::string(err));
  Eigen::MatrixX2d out(n, 2);
  for (int k = 0; k < n; ++k) {
    if (boundary[k]) {
      out.row(k) = boundaryUV.row(k);
      continue;
    }
    for (int d = 0; d < 2; ++d) out(k, d) = lo(d) + span(d) * uv[2 * k + d];
  }
  if (!out.allFinite()) throw Error("BIDGCN predicted a non-finite parameter");
  return out;
}

}  // namespace holefill::learn
