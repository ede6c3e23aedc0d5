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

std::vector<std::pair<LoopEdge, LoopEdge>> crossingEdges(const std::vector<Polygon2>& loops, size_t limit) {
  struct Span {
    double xmin, xmax, ymin, ymax;
    LoopEdge e;
    long long rank;  // among its loop's edges of nonzero length
  };
  // Edges shorter than 1e-14 are left out, and the two either side of them are adjacent: a loop's
  // corners are often sampled by both edges that meet there, a hair apart, and those edges only
  // touch. Adjacent edges share a vertex and never cross properly.
  std::vector<Span> spans;
  std::vector<long long> ranks(loops.size(), 0);
  for (size_t l = 0; l < loops.size(); ++l)
    for (size_t k = 0; k < loops[l].size(); ++k) {
      const auto &a = loops[l][k], &b = loops[l][(k + 1) % loops[l].size()];
      if ((a - b).norm() <= 1e-14) continue;
      spans.push_back({std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.y(), b.y()), {l, k}, ranks[l]++});
    }
  std::sort(spans.begin(), spans.end(), [](const Span& p, const Span& q) { return p.xmin < q.xmin; });
  auto ends = [&](const LoopEdge& e) {
    const Polygon2& l = loops[e.loop];
    return std::pair<const Eigen::Vector2d&, const Eigen::Vector2d&>{l[e.edge], l[(e.edge + 1) % l.size()]};
  };
  std::vector<std::pair<LoopEdge, LoopEdge>> out;
  for (size_t i = 0; i < spans.size() && out.size() < limit; ++i)
    for (size_t j = i + 1; j < spans.size() && spans[j].xmin <= spans[i].xmax && out.size() < limit; ++j) {
      if (spans[j].ymin > spans[i].ymax || spans[j].ymax < spans[i].ymin) continue;
      if (spans[i].e.loop == spans[j].e.loop) {
        const long long n = ranks[spans[i].e.loop], d = (spans[i].rank - spans[j].rank + n) % n;
        if (d == 1 || d == n - 1) continue;
      }
      const auto [a, b] = ends(spans[i].e);
      const auto [c, d] = ends(spans[j].e);
      if (segmentsCross(a, b, c, d)) out.push_back({spans[i].e, spans[j].e});
    }
  return out;
}

bool selfIntersects(const Polygon2& p) { return !crossingEdges({p}, 1).empty(); }

bool loopsCross(const Polygon2& p, const Polygon2& q) {
  for (const auto& [e, f] : crossingEdges({p, q}))
    if (e.loop != f.loop) return true;
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
