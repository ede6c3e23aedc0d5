#include "geometry/polygon2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holefill {

double leastAreaRectangleAngle(const std::vector<Eigen::Vector2d>& points) {
  // Andrew's monotone chain.
  std::vector<Eigen::Vector2d> p = points;
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return 0;
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  if (hull.size() < 3) return 0;
  double best = std::numeric_limits<double>::infinity(), angle = 0;
  for (size_t e = 0; e < hull.size(); ++e) {
    const Eigen::Vector2d d = hull[(e + 1) % hull.size()] - hull[e];
    if (!(d.norm() > 0)) continue;
    // Turned by −(the edge's direction), the edge runs along u.
    double a = -std::atan2(d.y(), d.x());
    a = std::fmod(std::fmod(a, M_PI / 2) + M_PI / 2, M_PI / 2);
    const double c = std::cos(a), s = std::sin(a);
    double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, hi[2] = {-lo[0], -lo[1]};
    for (const Eigen::Vector2d& q : hull) {
      const double r[2] = {c * q.x() - s * q.y(), s * q.x() + c * q.y()};
      for (int i = 0; i < 2; ++i) lo[i] = std::min(lo[i], r[i]), hi[i] = std::max(hi[i], r[i]);
    }
    const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    if (area < best * (1 - 1e-12)) best = area, angle = a;
  }
  return angle;
}

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

// Whether the segments cross, or (touch ≥ 0) come within `touch` of each other: the closest
// points of two segments that do not cross include an end of one of them.
bool segmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d, double touch) {
  if (segmentsCross(a, b, c, d)) return true;
  return touch >= 0 && std::min({segmentDistance(a, c, d), segmentDistance(b, c, d), segmentDistance(c, a, b),
                                 segmentDistance(d, a, b)}) <= touch;
}
}  // namespace

double segmentDistance(const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * d - q).norm();
}

std::vector<std::pair<LoopEdge, LoopEdge>> crossingEdges(const std::vector<Polygon2>& loops, size_t limit, double touch) {
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
  const double pad = std::max(touch, 0.0);  // a span grown by it meets every span within `touch`
  for (size_t l = 0; l < loops.size(); ++l)
    for (size_t k = 0; k < loops[l].size(); ++k) {
      const auto &a = loops[l][k], &b = loops[l][(k + 1) % loops[l].size()];
      if ((a - b).norm() <= 1e-14) continue;
      spans.push_back({std::min(a.x(), b.x()) - pad, std::max(a.x(), b.x()) + pad, std::min(a.y(), b.y()) - pad, std::max(a.y(), b.y()) + pad,
                       {l, k}, ranks[l]++});
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
      if (segmentsMeet(a, b, c, d, touch)) out.push_back({spans[i].e, spans[j].e});
    }
  return out;
}

bool selfIntersects(const Polygon2& p) { return !crossingEdges({p}, 1).empty(); }

Polygon2 withoutSelfContacts(Polygon2 loop, double touch) {
  // Each contact is cut out by keeping the larger of the two loops it splits the loop into; a cut
  // can bring its new edge into contact elsewhere, so the search runs again (each cut drops a
  // vertex at least, and the loop keeps three).
  while (loop.size() > 3) {
    const auto meet = crossingEdges({loop}, 1, touch);
    if (meet.empty()) break;
    const size_t n = loop.size(), i = std::min(meet[0].first.edge, meet[0].second.edge), j = std::max(meet[0].first.edge, meet[0].second.edge);
    // Edges i and j split the loop into the vertices i+1 … j and j+1 … i (round the end).
    const Polygon2 inner(loop.begin() + static_cast<std::ptrdiff_t>(i) + 1, loop.begin() + static_cast<std::ptrdiff_t>(j) + 1);
    Polygon2 outer(loop.begin() + static_cast<std::ptrdiff_t>(j) + 1, loop.end());
    outer.insert(outer.end(), loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    Polygon2 kept = std::abs(signedArea(inner)) > std::abs(signedArea(outer)) ? inner : outer;
    if (kept.size() < 3 || kept.size() >= n) break;
    loop = std::move(kept);
  }
  return loop;
}

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
