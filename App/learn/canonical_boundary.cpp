#include "learn/canonical_boundary.h"

#include <cmath>

#include "geometry/error.h"

namespace holefill::learn {

Eigen::Vector3d CanonicalFrame::toCanonical(const Eigen::Vector3d& p) const {
  return scale * (rotation * (p - origin)) + Eigen::Vector3d::Constant(0.5);
}

Eigen::Vector3d CanonicalFrame::toModel(const Eigen::Vector3d& q) const {
  return origin + rotation.transpose() * ((q - Eigen::Vector3d::Constant(0.5)) / scale);
}

namespace {

void checkLoop(const std::vector<Eigen::Vector3d>& loop) {
  if (loop.size() < 6)
    throw Error("a hole boundary needs at least 6 samples for the learned parameterizer, got " +
                std::to_string(loop.size()));
  for (const auto& p : loop)
    if (!p.allFinite()) throw Error("the hole boundary has non-finite coordinates (NaN or infinity)");
}

// Arc-length weight of each polyline vertex (half of each adjacent segment).
std::vector<double> vertexWeights(const std::vector<Eigen::Vector3d>& loop, double& length) {
  const size_t n = loop.size();
  std::vector<double> w(n, 0.0);
  length = 0;
  for (size_t i = 0; i < n; ++i) {
    const double l = (loop[(i + 1) % n] - loop[i]).norm();
    w[i] += 0.5 * l;
    w[(i + 1) % n] += 0.5 * l;
    length += l;
  }
  return w;
}

}  // namespace

CanonicalFrame canonicalFrame(const std::vector<Eigen::Vector3d>& loop, const CanonicalBoundaryOptions& opt) {
  checkLoop(loop);
  double length = 0;
  const std::vector<double> w = vertexWeights(loop, length);
  if (!(length > 0)) throw Error("the hole boundary is degenerate: all its points coincide");
  CanonicalFrame f;
  for (size_t i = 0; i < loop.size(); ++i) f.origin += w[i] * loop[i];
  f.origin /= length;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < loop.size(); ++i) C += w[i] * (loop[i] - f.origin) * (loop[i] - f.origin).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  const Eigen::Vector3d var = es.eigenvalues();  // increasing
  if (!(var(1) > 1e-10 * var(2)))
    throw Error("the hole boundary is degenerate: its points lie on a line, so it encloses no area");
  Eigen::Vector3d ex = es.eigenvectors().col(2), ez = es.eigenvectors().col(0);
  // x by the third moment, so a mirror-symmetric loop is the only one left ambiguous.
  double m3 = 0;
  for (size_t i = 0; i < loop.size(); ++i) m3 += w[i] * std::pow((loop[i] - f.origin).dot(ex), 3);
  if (m3 < 0) ex = -ex;
  Eigen::Vector3d ey = ez.cross(ex);
  // z so the loop turns counter-clockwise about it.
  double area = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d a = loop[i] - f.origin, b = loop[(i + 1) % loop.size()] - f.origin;
    area += a.dot(ex) * b.dot(ey) - b.dot(ex) * a.dot(ey);
  }
  if (area < 0) { ez = -ez; ey = -ey; }
  f.rotation.row(0) = ex.transpose();
  f.rotation.row(1) = ey.transpose();
  f.rotation.row(2) = ez.transpose();
  double r2 = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d d = f.rotation * (loop[i] - f.origin);
    r2 += w[i] * (d.x() * d.x() + d.y() * d.y());
  }
  f.scale = opt.rmsRadius / std::sqrt(r2 / length);
  return f;
}

CanonicalBoundary canonicalizeBoundary(const std::vector<Eigen::Vector3d>& loop, const CanonicalBoundaryOptions& opt) {
  HF_CHECK(opt.samples >= 6, "the learned parameterizer needs at least 6 boundary samples");
  CanonicalBoundary cb;
  cb.frame = canonicalFrame(loop, opt);
  const int n = static_cast<int>(loop.size());
  std::vector<Eigen::Vector3d> q(n);
  for (int i = 0; i < n; ++i) q[i] = cb.frame.toCanonical(loop[i]);
  double area = 0;
  for (int i = 0; i < n; ++i) area += q[i].x() * q[(i + 1) % n].y() - q[(i + 1) % n].x() * q[i].y();
  const bool reversed = area < 0;  // only by round-off: the frame made the loop counter-clockwise
  // Walk counter-clockwise from the vertex of largest x.
  int start = 0;
  for (int i = 1; i < n; ++i)
    if (q[i].x() > q[start].x()) start = i;
  const int step = reversed ? -1 : 1;
  std::vector<double> acc(n + 1, 0.0);
  std::vector<int> order(n + 1);
  for (int k = 0; k <= n; ++k) order[k] = ((start + step * k) % n + n) % n;
  for (int k = 1; k <= n; ++k) acc[k] = acc[k - 1] + (q[order[k]] - q[order[k - 1]]).norm();
  const double L = acc[n];
  int seg = 0;
  for (int s = 0; s < opt.samples; ++s) {
    const double target = L * s / opt.samples;
    while (seg < n - 1 && acc[seg + 1] <= target) ++seg;
    const double len = acc[seg + 1] - acc[seg];
    const double f = len > 0 ? (target - acc[seg]) / len : 0.0;
    cb.points.push_back((1 - f) * q[order[seg]] + f * q[order[seg + 1]]);
    // Position along the input polyline: between order[seg] and its neighbour in walking direction.
    const double a = order[seg];
    double p = reversed ? a - f : a + f;
    if (p < 0) p += n;
    cb.loopParameter.push_back(p);
  }
  return cb;
}

}  // namespace holefill::learn
