#include "gnurbs/bezier_extraction.h"

#include <algorithm>
#include <array>

#include "geometry/bezier_patch.h"
#include "geometry/error.h"

namespace holefill {

namespace {

struct Extractor {
  const QuadCage& cage;
  const CageTopology& topo;
  std::vector<int> featureEdges;  // per vertex: boundary or sharp edges at it

  int corner(int f, int k) const { return cage.quads(f, ((k % 4) + 4) % 4); }
  Eigen::Vector3d point(int v) const { return cage.vertices.row(v).transpose(); }
  bool feature(int f, int k) const { return isFeatureEdge(corner(f, k), corner(f, k + 1)); }

  // Knot intervals of the edges at A and at B, perpendicular to edge k = (A, B) of f, on the far
  // side of it: in the face across, or in f mirrored across a feature line.
  std::pair<double, double> farIntervals(int f, int k) const {
    const int a = corner(f, k), b = corner(f, k + 1);
    if (feature(f, k)) return {cage.knot(a, corner(f, k - 1)), cage.knot(b, corner(f, k + 2))};
    const int g = topo.acrossFace(f, k), m = topo.acrossEdge(f, k);
    return {cage.knot(a, corner(g, m + 2)), cage.knot(b, corner(g, m + 3))};
  }
  // farIntervals as continuations of f's edges at A and B through them, for f's face points.
  std::pair<double, double> continuations(int f, int k) const {
    const auto far = farIntervals(f, k);
    return {throughEP(corner(f, k), corner(f, k - 1), far.first), throughEP(corner(f, k + 1), corner(f, k + 2), far.second)};
  }
  // The interval continuing spoke (v, s) through v. At an EP no spoke continues it; the two
  // faces beside a spoke would each take the spoke two steps round on their own side, and
  // their face points along the spoke would then sit at different knot fractions (the
  // surface not C² across the spoke even at its regular end, which the G² solve needs). So
  // both take the mean of the spokes two steps round either way: the opposite spoke at valence 4.
  bool smoothEP(int v) const { return topo.isExtraordinary(v) && featureEdges[v] == 0; }
  double throughEP(int v, int s, double own) const {
    if (!smoothEP(v)) return own;
    const auto& sp = topo.spokes(v);
    const int n = static_cast<int>(sp.size());
    const int i = static_cast<int>(std::find(sp.begin(), sp.end(), s) - sp.begin());
    return 0.5 * (cage.knot(v, sp[(i + 2) % n]) + cage.knot(v, sp[(i + n - 2) % n]));
  }

  // The four face points of f, indexed by the corner they are nearest to.
  std::array<Eigen::Vector3d, 4> facePoints(int f) const {
    const int c0 = corner(f, 0), c1 = corner(f, 1), c2 = corner(f, 2), c3 = corner(f, 3);
    const auto left = continuations(f, 3), right = continuations(f, 1), bottom = continuations(f, 0), top = continuations(f, 2);
    // d: intervals along u (row below: d0 d1 d2, row above: d3 d4 d5); e: along v (column left: e0 e1 e2, right: e3 e4 e5).
    const double d[6] = {left.second, cage.knot(c0, c1), right.first, left.first, cage.knot(c3, c2), right.second};
    const double e[6] = {bottom.first, cage.knot(c0, c3), top.second, bottom.second, cage.knot(c1, c2), top.first};
    std::array<Eigen::Vector3d, 4> out;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        double h[3], kk[3];
        for (int n = 0; n < 3; ++n) {
          h[n] = ((2 - j) * d[n] + (1 + j) * d[n + 3]) / 3;
          kk[n] = ((2 - i) * e[n] + (1 + i) * e[n + 3]) / 3;
        }
        const double alpha = (i == 0 ? h[0] : h[0] + h[1]) / (h[0] + h[1] + h[2]);
        const double gamma = (j == 0 ? kk[0] : kk[0] + kk[1]) / (kk[0] + kk[1] + kk[2]);
        const Eigen::Vector3d p = (1 - alpha) * ((1 - gamma) * point(c0) + gamma * point(c3)) +
                                  alpha * ((1 - gamma) * point(c1) + gamma * point(c2));
        out[i == 0 ? (j == 0 ? 0 : 3) : (j == 0 ? 1 : 2)] = p;
      }
    return out;
  }

  // Interval of the feature line's continuation beyond v, away from neighbour `from`. Where
  // the line ends or meets others at v, the line's B-spline interpolates v with a mirrored
  // phantom point (the natural end): the continuation is the edge's own interval, which puts
  // the end's Bézier point a third of the way along the edge rather than on v (a zero-length
  // end tangent, measured as singular normals at every boundary corner of an open cage).
  double continuation(int v, int from) const {
    if (!lineThrough(v)) return cage.knot(v, from);
    for (int s : topo.spokes(v))
      if (s != from && isFeatureEdge(v, s)) return cage.knot(v, s);
    return cage.knot(v, from);
  }
  // A feature line runs on through v (its B-spline's segments join there) unless it ends, meets
  // another, turns at a boundary corner, or passes an EP: a sharp EP is a corner of its creases
  // (g2_gnurbs.cpp: the smooth spokes' G² conditions cannot meet a crease curved through it).
  bool lineThrough(int v) const {
    return featureEdges[v] == 2 && !(topo.onBoundary(v) && topo.facesAround(v).size() == 1) && !topo.isExtraordinary(v);
  }
  bool isFeatureEdge(int a, int b) const {
    if (cage.isSharp(a, b)) return true;
    // A boundary edge is the first or last spoke of a boundary vertex's fan.
    const auto& sp = topo.spokes(a);
    return topo.onBoundary(a) && (sp.front() == b || sp.back() == b);
  }
};

}  // namespace

GuidanceSurface extractGuidanceSurface(const QuadCage& cage, const CageTopology& topo) {
  Extractor x{cage, topo, std::vector<int>(topo.vertexCount(), 0)};
  const int nf = topo.faceCount(), nv = topo.vertexCount();
  for (int v = 0; v < nv; ++v)
    for (int s : topo.spokes(v)) x.featureEdges[v] += x.isFeatureEdge(v, s) ? 1 : 0;
  for (const auto& [v, a] : cage.anchors)
    if (!topo.isExtraordinary(v))
      throw Error(cage.vertexName(v) + " has an anchor but is not an extraordinary point; anchors replace EP vertex points");

  std::vector<std::array<Eigen::Vector3d, 4>> F(nf);
  for (int f = 0; f < nf; ++f) F[f] = x.facePoints(f);

  // Vertex points.
  GuidanceSurface out;
  out.vertexPoints.resize(nv, Eigen::Vector3d::Zero());
  for (int v = 0; v < nv; ++v) {
    const auto& fan = topo.facesAround(v);
    const auto& sp = topo.spokes(v);
    if (fan.empty()) continue;
    if (const auto it = cage.anchors.find(v); it != cage.anchors.end()) {
      out.vertexPoints[v] = it->second;
    } else if (x.featureEdges[v] == 0) {
      const int n = static_cast<int>(sp.size());
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double total = 0;
      for (int i = 0; i < n; ++i) {
        const double w = cage.knot(v, sp[(i + n - 1) % n]) * cage.knot(v, sp[(i + 2) % n]);
        sum += w * F[fan[i].face][fan[i].corner];
        total += w;
      }
      out.vertexPoints[v] = sum / total;
    } else if (x.lineThrough(v)) {
      // On a feature line: the junction of its B-spline's two segments at v.
      int a = -1, b = -1;
      for (int s : sp)
        if (x.isFeatureEdge(v, s)) (a < 0 ? a : b) = s;
      const double da = cage.knot(v, a), db = cage.knot(v, b);
      auto near = [&](int w, double dw) {  // the line's Bézier point on edge (v, w) next to v
        const double cv = x.continuation(v, w), cw = x.continuation(w, v);
        return Eigen::Vector3d(x.point(v) + (cv / (cv + dw + cw)) * (x.point(w) - x.point(v)));
      };
      out.vertexPoints[v] = (db * near(a, da) + da * near(b, db)) / (da + db);
    } else {
      out.vertexPoints[v] = x.point(v);  // a line ends or meets others here, a boundary corner, a sharp EP: interpolated
    }
  }

  // Patches.
  out.patches.resize(nf);
  for (int f = 0; f < nf; ++f) {
    Eigen::MatrixX3d B(16, 3);
    auto set = [&](int a, int b, const Eigen::Vector3d& p) { B.row(a * 4 + b) = p.transpose(); };
    // Grid position of the point nearest corner k, and the step from a corner along edge k.
    static const int cu[4] = {0, 3, 3, 0}, cv[4] = {0, 0, 3, 3};
    for (int k = 0; k < 4; ++k) {
      set(cu[k], cv[k], out.vertexPoints[x.corner(f, k)]);
      set(cu[k] == 0 ? 1 : 2, cv[k] == 0 ? 1 : 2, F[f][k]);
    }
    for (int k = 0; k < 4; ++k) {
      const int a = x.corner(f, k), b = x.corner(f, k + 1);
      // The two edge points of edge k: next to corner k (index 0) and to corner k+1 (index 1).
      std::array<Eigen::Vector3d, 2> E;
      if (x.feature(f, k)) {
        const double d = cage.knot(a, b), ca = x.continuation(a, b), cb = x.continuation(b, a);
        E[0] = x.point(a) + (ca / (ca + d + cb)) * (x.point(b) - x.point(a));
        E[1] = x.point(a) + ((ca + d) / (ca + d + cb)) * (x.point(b) - x.point(a));
      } else {
        const int g = topo.acrossFace(f, k), m = topo.acrossEdge(f, k);
        const double fa = cage.knot(a, x.corner(f, k - 1)), fb = cage.knot(b, x.corner(f, k + 2));
        const auto far = x.farIntervals(f, k);
        for (int t = 0; t < 2; ++t) {
          const double mine = t == 0 ? (2 * fa + fb) / 3 : (fa + 2 * fb) / 3;
          const double theirs = t == 0 ? (2 * far.first + far.second) / 3 : (far.first + 2 * far.second) / 3;
          const Eigen::Vector3d& own = F[f][(k + t) % 4];
          const Eigen::Vector3d& other = F[g][t == 0 ? (m + 1) % 4 : m];
          E[t] = (theirs * own + mine * other) / (mine + theirs);
        }
      }
      // Edge k runs from corner k to corner k+1; place its points on the patch border.
      const int a0u = cu[k], a0v = cv[k], a1u = cu[(k + 1) % 4], a1v = cv[(k + 1) % 4];
      for (int t = 0; t < 2; ++t) {
        const double s = t == 0 ? 1.0 / 3 : 2.0 / 3;
        set(static_cast<int>(std::lround(a0u + s * (a1u - a0u))), static_cast<int>(std::lround(a0v + s * (a1v - a0v))), E[t]);
      }
    }
    out.patches[f] = bezierPatch(3, 3, B);
  }
  return out;
}

}  // namespace holefill
