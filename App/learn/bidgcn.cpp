#include "learn/bidgcn.h"

#include <algorithm>
#include <cmath>

#include "geometry/error.h"
#include "learn/learn_library.h"

namespace holefill::learn {

namespace {

// The boundary points the network is shown. It was trained on 1000 interior and 34 boundary
// points (bidgcn.md sec. 4.2: a boundary a quarter as dense as the interior), and its input layer
// averages boundary and interior messages, so a densely sampled boundary — a scan's, found by its
// alpha shape, has several times more — is far from what it learned. At most
// 34·sqrt(interior/1000) of them are shown, spread evenly by their position along the domain's
// boundary and always with the ones nearest the corners; the others are predicted as interior
// points and then given their known parameters.
std::vector<bool> networkBoundary(const std::vector<bool>& boundary, const Eigen::MatrixX2d& uv, const Eigen::Vector2d& lo,
                                  const Eigen::Vector2d& span) {
  const int n = static_cast<int>(boundary.size());
  std::vector<std::pair<double, int>> along;  // perimeter position in [0, 4) of the unit square
  for (int k = 0; k < n; ++k) {
    if (!boundary[k]) continue;
    const double u = (uv(k, 0) - lo(0)) / span(0), v = (uv(k, 1) - lo(1)) / span(1);
    const double d[4] = {v, 1 - u, 1 - v, u};  // distance to the sides v=0, u=1, v=1, u=0
    const int side = static_cast<int>(std::min_element(d, d + 4) - d);
    const double t[4] = {u, 1 + v, 3 - u, 4 - v};
    along.emplace_back(std::fmod(t[side], 4.0), k);
  }
  const int interior = n - static_cast<int>(along.size());
  const int target = std::max(8, static_cast<int>(std::lround(34 * std::sqrt(std::max(1, interior) / 1000.0))));
  if (static_cast<int>(along.size()) <= target) return boundary;
  std::sort(along.begin(), along.end());
  std::vector<bool> shown(n, false);
  const auto nearest = [&](double s) {  // the boundary point nearest perimeter position s
    int best = along[0].second;
    double bd = 1e300;
    for (const auto& [a, k] : along) {
      const double d = std::min(std::abs(a - s), 4 - std::abs(a - s));
      if (d < bd) bd = d, best = k;
    }
    return best;
  };
  for (int c = 0; c < 4; ++c) shown[nearest(c)] = true;
  const int rest = target - 4;
  for (int q = 0; q < rest; ++q) shown[along[static_cast<size_t>((q + 0.5) * along.size() / rest)].second] = true;
  return shown;
}

}  // namespace

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
  const std::vector<bool> shown = networkBoundary(boundary, boundaryUV, lo, span);
  std::vector<unsigned char> flags(n);
  for (int k = 0; k < n; ++k) {
    for (int d = 0; d < 3; ++d) xyz[3 * k + d] = p(k, d);
    flags[k] = shown[k];
    if (shown[k])
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
