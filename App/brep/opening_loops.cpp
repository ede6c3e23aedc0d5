#include "brep/opening_loops.h"

#include <BRepAdaptor_Curve.hxx>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>

#include "geometry/polygon2d.h"

namespace holefill {

namespace {

// Points along a loop, in loop order: each edge at 16 even steps of its parameter.
std::vector<Eigen::Vector3d> loopPoints(const Hole& hole) {
  std::vector<Eigen::Vector3d> out;
  for (const HoleEdge& he : hole.edges) {
    BRepAdaptor_Curve c(he.edge);
    const double t0 = c.FirstParameter(), t1 = c.LastParameter();
    const bool reversed = he.edge.Orientation() == TopAbs_REVERSED;
    for (int k = 0; k < 16; ++k) {
      const double f = (k + 0.0) / 16, t = reversed ? t1 - f * (t1 - t0) : t0 + f * (t1 - t0);
      const gp_Pnt p = c.Value(t);
      out.emplace_back(p.X(), p.Y(), p.Z());
    }
  }
  return out;
}

// A loop on the plane that fits it best: its points there, its size (the bounding-box diagonal
// of the 3D points) and the frame to project others with.
struct PlanarLoop {
  Eigen::Vector3d centre, u, v, n;
  Polygon2 polygon;
  double size = 0;
};

PlanarLoop planar(const std::vector<Eigen::Vector3d>& pts) {
  PlanarLoop p;
  Eigen::Vector3d lo = pts.front(), hi = pts.front();
  p.centre.setZero();
  for (const auto& x : pts) p.centre += x, lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  p.centre /= static_cast<double>(pts.size());
  p.size = (hi - lo).norm();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& x : pts) cov += (x - p.centre) * (x - p.centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  p.n = eig.eigenvectors().col(0), p.u = eig.eigenvectors().col(2), p.v = eig.eigenvectors().col(1);
  for (const auto& x : pts) p.polygon.emplace_back((x - p.centre).dot(p.u), (x - p.centre).dot(p.v));
  return p;
}

// Whether every point of `inner` lies strictly inside `outer`'s projection (farther than 1e-3 of
// its size from its boundary) and within a tenth of its size of its plane.
bool nestedIn(const std::vector<Eigen::Vector3d>& inner, const PlanarLoop& outer) {
  const double margin = 1e-3 * outer.size;
  for (const auto& x : inner) {
    const Eigen::Vector3d d = x - outer.centre;
    if (std::abs(d.dot(outer.n)) > 0.1 * outer.size) return false;
    const Eigen::Vector2d q(d.dot(outer.u), d.dot(outer.v));
    if (!contains(outer.polygon, q)) return false;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < outer.polygon.size(); ++k)
      nearest = std::min(nearest, segmentDistance(q, outer.polygon[k], outer.polygon[(k + 1) % outer.polygon.size()]));
    if (nearest <= margin) return false;
  }
  return true;
}

// Every distinct loop of a detection (an outer boundary asked for as a hole is listed twice),
// sampled and put on its plane once.
struct Loop {
  const Hole* hole;
  std::vector<Eigen::Vector3d> points;
  PlanarLoop plane;
};

std::vector<Loop> loopsOf(const HoleDetectionResult& detection) {
  std::vector<Loop> out;
  std::vector<std::vector<int>> seen;
  const auto add = [&](const Hole& h) {
    if (h.edges.empty() || std::find(seen.begin(), seen.end(), h.edgeIndices()) != seen.end()) return;
    seen.push_back(h.edgeIndices());
    Loop l{&h, loopPoints(h), {}};
    if (l.points.size() >= 3) l.plane = planar(l.points);
    out.push_back(std::move(l));
  };
  for (const Hole& h : detection.holes) add(h);
  for (const Hole& h : detection.outerBoundaries) add(h);
  return out;
}

// The loops of `all` that share `own`'s opening: nested in it, or holes it is nested in.
std::vector<const Hole*> sharing(const std::vector<Loop>& all, const Loop& own) {
  std::vector<const Hole*> out;
  if (own.points.size() < 3) return out;
  for (const Loop& other : all) {
    if (other.hole->edgeIndices() == own.hole->edgeIndices() || other.points.size() < 3) continue;
    if (nestedIn(other.points, own.plane) || (!other.hole->outerBoundary && nestedIn(own.points, other.plane))) out.push_back(other.hole);
  }
  return out;
}

}  // namespace

std::vector<const Hole*> loopsSharingOpening(const HoleDetectionResult& detection, const Hole& hole) {
  const std::vector<Loop> all = loopsOf(detection);
  const std::vector<int> mine = hole.edgeIndices();
  for (const Loop& l : all)
    if (l.hole->edgeIndices() == mine) return sharing(all, l);
  Loop own{&hole, loopPoints(hole), {}};  // a hole not of this detection
  if (own.points.size() >= 3) own.plane = planar(own.points);
  return sharing(all, own);
}

std::vector<std::vector<const Hole*>> loopsSharingOpenings(const HoleDetectionResult& detection) {
  const std::vector<Loop> all = loopsOf(detection);
  std::vector<std::vector<const Hole*>> out;
  const auto of = [&](const Hole& h) {
    for (const Loop& l : all)
      if (l.hole->edgeIndices() == h.edgeIndices()) return sharing(all, l);
    return std::vector<const Hole*>{};
  };
  for (const Hole& h : detection.holes) out.push_back(of(h));
  for (const Hole& h : detection.outerBoundaries) out.push_back(of(h));
  return out;
}

}  // namespace holefill
