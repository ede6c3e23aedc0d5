#include "geometry/polygon2d.h"

#include <algorithm>
#include <cmath>

namespace holefill {

double signedArea(const Polygon2& p) {
  double a = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const auto& q = p[i];
    const auto& r = p[(i + 1) % p.size()];
    a += q.x() * r.y() - r.x() * q.y();
  }
  return 0.5 * a;
}

bool contains(const Polygon2& p, const Eigen::Vector2d& x) {
  bool in = false;
  for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y() > x.y()) != (p[j].y() > x.y()) &&
        x.x() < (p[j].x() - p[i].x()) * (x.y() - p[i].y()) / (p[j].y() - p[i].y()) + p[i].x())
      in = !in;
  }
  return in;
}

namespace {
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}
}  // namespace

bool selfIntersects(const Polygon2& p) {
  // Drop repeated vertices (corners are sampled by both adjacent edges).
  Polygon2 q;
  for (const auto& v : p)
    if (q.empty() || (v - q.back()).norm() > 1e-14) q.push_back(v);
  while (q.size() > 1 && (q.front() - q.back()).norm() <= 1e-14) q.pop_back();
  const size_t n = q.size();
  if (n < 4) return false;
  // Sort-free O(n^2) with a bounding-box reject; loops have at most a few thousand samples.
  for (size_t i = 0; i < n; ++i) {
    const auto &a = q[i], &b = q[(i + 1) % n];
    const double xmin = std::min(a.x(), b.x()), xmax = std::max(a.x(), b.x());
    const double ymin = std::min(a.y(), b.y()), ymax = std::max(a.y(), b.y());
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      const auto &c = q[j], &d = q[(j + 1) % n];
      if (std::max(c.x(), d.x()) < xmin || std::min(c.x(), d.x()) > xmax || std::max(c.y(), d.y()) < ymin ||
          std::min(c.y(), d.y()) > ymax)
        continue;
      if (segmentsCross(a, b, c, d)) return true;
    }
  }
  return false;
}

bool loopsCross(const Polygon2& p, const Polygon2& q) {
  for (size_t i = 0; i < p.size(); ++i) {
    const auto &a = p[i], &b = p[(i + 1) % p.size()];
    for (size_t j = 0; j < q.size(); ++j)
      if (segmentsCross(a, b, q[j], q[(j + 1) % q.size()])) return true;
  }
  return false;
}

Eigen::VectorXd meanValueCoordinates(const Polygon2& p, const Eigen::Vector2d& x) {
  const size_t n = p.size();
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  std::vector<double> r(n), tanHalf(n);
  for (size_t i = 0; i < n; ++i) {
    r[i] = (p[i] - x).norm();
    if (r[i] < 1e-15) { w(static_cast<Eigen::Index>(i)) = 1.0; return w; }
  }
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = p[i] - x, b = p[(i + 1) % n] - x;
    const double ang = std::atan2(cross(a, b), a.dot(b));
    tanHalf[i] = std::tan(0.5 * ang);
  }
  for (size_t i = 0; i < n; ++i) {
    if (r[i] == 0.0) continue;
    w(static_cast<Eigen::Index>(i)) = (tanHalf[(i + n - 1) % n] + tanHalf[i]) / r[i];
  }
  const double s = w.sum();
  return std::abs(s) > 0 ? Eigen::VectorXd(w / s) : w;
}

}  // namespace holefill
