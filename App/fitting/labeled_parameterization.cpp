#include "fitting/labeled_parameterization.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>

#include "fitting/arap_terms.h"
#include "fitting/boundary_embedding.h"
#include "fitting/free_flattening.h"
#include "fitting/slim_descent.h"
#include "geometry/error.h"
#include "geometry/polygon2d.h"
#include "mesh/mesh_holes.h"
#include "mesh/mesh_topology.h"
#include "mesh/scan_noise.h"

namespace holefill {

namespace {

const char* sideName(Side s) {
  static const char* names[4] = {"South", "East", "North", "West"};
  return names[static_cast<int>(s)];
}

// Length of a side's curve from its start to parameter t (the whole curve for t = 1).
double curveLength(const GuidingFrame& f, Side s, double t = 1) {
  double len = 0;
  Eigen::Vector3d prev = f.point(s, 0);
  for (int k = 1; k <= 256; ++k) {
    const Eigen::Vector3d p = f.point(s, t * k / 256.0);
    len += (p - prev).norm();
    prev = p;
  }
  return len;
}

// Position along the rectangle's perimeter (anticlockwise from the corner (0, 0)) and back.
double perimeterCoordinate(const Eigen::Vector2d& q, double W, double H) {
  const double tol = 1e-12 * (W + H);
  if (std::abs(q.y()) <= tol) return q.x();
  if (std::abs(q.x() - W) <= tol) return W + q.y();
  if (std::abs(q.y() - H) <= tol) return W + H + (W - q.x());
  return 2 * W + H + (H - q.y());
}
Eigen::Vector2d perimeterPoint(double p, double W, double H) {
  const double L = 2 * (W + H);
  p = std::fmod(std::fmod(p, L) + L, L);
  if (p <= W) return {p, 0};
  if (p <= W + H) return {W, p - W};
  if (p <= 2 * W + H) return {W - (p - W - H), H};
  return {0, H - (p - 2 * W - H)};
}


// A labeled side developed into the plane, from its first vertex (at the origin, heading along +x)
// to its last; one point per vertex of `sp` (positions in `loop`). The side is cut into chords of
// 2% of its length (at least four edges); each turns from the one before by their angle seen
// along the surface's normal at their common end (the triangles' mean between its neighbouring
// ends), which on a cone's arc is the geodesic turn; the vertices between two ends keep their
// place seen along that normal. The turns of consecutive chords telescope: on a plane the
// development is the side's projection, whatever the noise. (Developed edge by edge from the
// triangles' angle sums, every vertex's angle error was summed into the heading: a straight side
// with scan noise of 0.2% of the diagonal turned 75° within 3% of its length, and its middle
// read as a notch 5% deep.)
std::vector<Eigen::Vector2d> developedSide(const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& normal, const std::vector<int>& loop,
                                           const std::vector<int>& sp) {
  const int L = static_cast<int>(loop.size());
  std::vector<int> path;  // loop positions from the side's first vertex to its last
  for (int i = sp.front();; i = (i + 1) % L) {
    path.push_back(i);
    if (i == sp.back()) break;
  }
  const auto point = [&](size_t k) { return Eigen::Vector3d(X.row(loop[path[k]]).transpose()); };
  std::vector<double> s(path.size(), 0.0), edges;
  for (size_t k = 1; k < path.size(); ++k) edges.push_back((point(k) - point(k - 1)).norm()), s[k] = s[k - 1] + edges.back();
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  const double h = std::max(0.02 * s.back(), 4 * edges[edges.size() / 2]);
  std::vector<size_t> ends{0};
  for (size_t k = 1; k + 1 < path.size(); ++k)
    if (s[k] - s[ends.back()] >= h && s.back() - s[k] >= 0.5 * h) ends.push_back(k);
  ends.push_back(path.size() - 1);
  const size_t K = ends.size();
  std::vector<Eigen::Vector3d> n(K, Eigen::Vector3d::Zero());
  for (size_t c = 0; c < K; ++c) {
    for (size_t k = ends[c > 0 ? c - 1 : 0]; k <= ends[std::min(c + 1, K - 1)]; ++k) n[c] += normal.row(loop[path[k]]).transpose();
    if (n[c].norm() > 0) n[c].normalize();
  }
  std::vector<Eigen::Vector2d> at(sp.size());
  Eigen::Vector2d q(0, 0);
  double heading = 0;
  Eigen::Vector3d before = Eigen::Vector3d::Zero();
  size_t j = 0;
  for (size_t c = 0; c + 1 < K; ++c) {
    const Eigen::Vector3d chord = point(ends[c + 1]) - point(ends[c]);
    Eigen::Vector3d e1 = chord - chord.dot(n[c]) * n[c];
    if (!(e1.norm() > 0)) e1 = chord;
    if (c > 0) {
      const Eigen::Vector3d a = before - before.dot(n[c]) * n[c];
      heading += std::atan2(a.cross(e1).dot(n[c]), a.dot(e1));
    }
    before = chord;
    e1.normalize();
    const Eigen::Vector3d e2 = n[c].cross(e1);
    const Eigen::Rotation2D<double> turned(heading);
    for (size_t k = ends[c]; k <= ends[c + 1] && j < sp.size(); ++k)
      if (path[k] == sp[j] && (k < ends[c + 1] || c + 2 == K)) {
        const Eigen::Vector3d d = point(k) - point(ends[c]);
        at[j++] = q + turned * Eigen::Vector2d(d.dot(e1), d.dot(e2));
      }
    q += turned * Eigen::Vector2d(chord.dot(e1), chord.dot(e2));
  }
  return at;
}

// A labeled side is meant to lie on a side of the rectangle, which the map makes straight. Its
// vertices that lie deeper than `depth` × its chord inside the line supporting it are a notch,
// slot or concave arc the side runs round, or a rounded corner: held on the side, they make the
// map singular there (measured: mean curvature 864 against the truth's 0.17 where an arc was
// straightened onto two sides), and the rectangle never reaches past them. They are taken off the
// side (left free, for the extension to continue the surface into), unless fewer than two would
// remain. Depth is measured on the side developed into the plane (developedSide): a side that
// bends with the surface (an arc round a cone) is not mistaken for one that turns within it.
// Returns the number taken off per side; sidePerimeter keeps the others, in order.
std::array<int, 4> releaseInwardStretches(const TriangleMesh& region, const Eigen::MatrixX3i& tri, const std::vector<int>& loop,
                                          std::array<std::vector<int>, 4>& sidePerimeter, double depth) {
  const int L = static_cast<int>(loop.size());
  const Eigen::MatrixX3d& X = region.vertices;
  int turn = 0;  // +1: the loop runs with the triangles (the region on its left), −1 against them
  for (int t = 0; t < tri.rows() && turn == 0; ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = tri(t, k), a = tri(t, (k + 1) % 3);
      if (turn == 0 && v == loop[0] && a == loop[1 % L]) turn = 1;
      if (turn == 0 && v == loop[1 % L] && a == loop[0]) turn = -1;
    }
  if (turn == 0) return {};
  Eigen::MatrixX3d normal = Eigen::MatrixX3d::Zero(X.rows(), 3);  // area-weighted, along the triangles' orientation
  for (int t = 0; t < tri.rows(); ++t) {
    const Eigen::RowVector3d c = (X.row(tri(t, 1)) - X.row(tri(t, 0))).cross(X.row(tri(t, 2)) - X.row(tri(t, 0)));
    for (int k = 0; k < 3; ++k) normal.row(tri(t, k)) += c;
  }
  std::array<int, 4> released{};
  const std::array<std::vector<int>, 4> labeled = sidePerimeter;  // as given, before any side is released
  for (int side = 0; side < 4; ++side) {
    std::vector<int>& sp = sidePerimeter[side];
    if (sp.size() < 3) continue;
    const std::vector<Eigen::Vector2d> at = developedSide(X, normal, loop, sp);
    const Eigen::Vector2d chord = at.back() - at.front();
    if (!(chord.norm() > 0)) continue;
    // The supporting line's direction: the one, within 45° of the chord, along which the most of
    // the side (by length) lies within the depth of it. The chord alone tilts away from the side
    // when one end lies in a concavity (an L's inner corner taken as a label corner), and the
    // side's straight part would then count as deep.
    // Nor is a vertex held whose stretch of the side runs more than 20° off that line: within the
    // depth of it, an arc leaving the side at a corner would be straightened onto it, and the map
    // folds the corner flat there (measured: data max 1.2e-2 at such a junction, on a region
    // whose map was otherwise exact). The direction is the developed side's over ±2% of its
    // chord, so that scan noise on the boundary does not count.
    std::vector<double> cumulative(sp.size(), 0.0);
    for (size_t j = 1; j < sp.size(); ++j) cumulative[j] = cumulative[j - 1] + (at[j] - at[j - 1]).norm();
    std::vector<Eigen::Vector2d> direction(sp.size());
    for (size_t j = 0, lo = 0, hi = 0; j < sp.size(); ++j) {
      const double w = 0.02 * chord.norm();
      while (cumulative[j] - cumulative[lo] > w) ++lo;
      while (hi + 1 < sp.size() && cumulative[hi + 1] - cumulative[j] <= w) ++hi;
      hi = std::max(hi, std::min(j + 1, sp.size() - 1));
      const size_t a = std::min(lo, j > 0 ? j - 1 : 0);
      direction[j] = (at[hi] - at[a]).normalized();
    }
    const double sharp = 30 * M_PI / 180, along20 = std::cos(20 * M_PI / 180);  // a turn; within 20° of a line
    // The window: 3% of the chord, and at least four boundary edges (a staircase boundary of
    // grid cells turns 90° at every step, which is not a notch).
    std::vector<double> edges;
    for (size_t j = 1; j < sp.size(); ++j) edges.push_back(cumulative[j] - cumulative[j - 1]);
    std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
    const double w = std::max(0.03 * chord.norm(), 4 * edges[edges.size() / 2]);
    std::vector<double> turnAt(sp.size(), 0.0);  // the side's turn at j over ±w, radians (0 where the window is cut short)
    // Whether it turns away from the region at a corner somewhere: by more than 60° within the
    // window (an L's inner corner turns 90° there; a concave arc turns gradually, at most 45° on
    // the corpus's noisy crescents, and is a bite for the first pass).
    // The turn is the one between the chords into and out of j in space, seen along the surface's
    // normal there (the triangles' mean over the window): the geodesic turn at the window's
    // scale, which scan noise hardly moves (12° on a straight side under noise of 0.2% of the
    // diagonal; developed from the angle sums, the same side turned 75° there).
    bool reflex = false;
    for (size_t j = 0; j < sp.size(); ++j) {
      size_t lo = j, hi = j;
      while (lo > 0 && cumulative[j] - cumulative[lo] < w) --lo;
      while (hi + 1 < sp.size() && cumulative[hi] - cumulative[j] < w) ++hi;
      if (lo == j || hi == j) continue;
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      for (size_t q = lo; q <= hi; ++q) n += normal.row(loop[sp[q]]).transpose();
      if (!(n.norm() > 0)) continue;
      n.normalize();
      Eigen::Vector3d a = (X.row(loop[sp[j]]) - X.row(loop[sp[lo]])).transpose(), b = (X.row(loop[sp[hi]]) - X.row(loop[sp[j]])).transpose();
      a -= a.dot(n) * n, b -= b.dot(n) * n;
      if (!(a.norm() > 0 && b.norm() > 0)) continue;
      a.normalize(), b.normalize();
      turnAt[j] = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
      reflex = reflex || (turnAt[j] > 2 * sharp && turn * a.cross(b).dot(n) < 0);
    }
    // The opposite side's chord in space: of two straight stretches about as long (the legs of a
    // reflex turn, an L's inner corner labeled within one side), the one running along the
    // opposite side is the side; held on the other, the map turns the region's arm round by 90°
    // (measured: data max 7e-2 on an L labeled by its corner angles, its map ballooned).
    Eigen::Vector3d across = Eigen::Vector3d::Zero();
    if (const std::vector<int>& op = labeled[(side + 2) % 4]; op.size() >= 2)
      across = (X.row(loop[op.back()]) - X.row(loop[op.front()])).transpose().normalized();
    std::vector<int> kept;
    double bestLength = -1, bestTilt = 0;
    // The line supports the whole side: stretches inside it are notches, slots and bites. Where
    // the side turns sharply away from the region on the way (a reflex corner: an L's inner
    // corner inside one side) and hardly any of it lies along such a line (less than a quarter),
    // each leg lies outside the other's line: the line then supports only the stretches running
    // along it, and one leg is held.
    bool alongSide = true;  // the first pass's best line holds a quarter of the side or more
    for (const bool alignedOnly : {false, true})
    for (int k = -45; k <= 45; ++k) {
      if (alignedOnly && k == -45) alongSide = !reflex || bestLength >= 0.25 * cumulative.back();
      if (alignedOnly && alongSide) break;
      const double a = std::atan2(chord.y(), chord.x()) + k * M_PI / 180;
      const Eigen::Vector2d along(std::cos(a), std::sin(a));
      const Eigen::Vector2d outward = turn * Eigen::Vector2d(std::sin(a), -std::cos(a));
      double support = -std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < sp.size(); ++j)
        if (!alignedOnly || direction[j].dot(along) >= along20) support = std::max(support, outward.dot(at[j]));
      std::vector<int> in;
      double length = 0;
      Eigen::Vector3d runs = Eigen::Vector3d::Zero();
      for (size_t j = 0; j < sp.size(); ++j) {
        if (support - outward.dot(at[j]) > depth * chord.norm()) continue;
        if (direction[j].dot(along) < along20) continue;
        if (!in.empty() && in.back() == sp[j - 1]) {
          length += (at[j] - at[j - 1]).norm();
          runs += (X.row(loop[sp[j]]) - X.row(loop[sp[j - 1]])).transpose();
        }
        in.push_back(sp[j]);
      }
      if (across.squaredNorm() > 0 && runs.squaredNorm() > 0) length *= 0.5 + 0.5 * std::abs(runs.normalized().dot(across));
      if (length > bestLength * (1 + 1e-9) || (length >= bestLength * (1 - 1e-9) && std::abs(k) < bestTilt)) {
        bestLength = length, bestTilt = std::abs(k);
        kept = in;
      }
    }
    // Only a stretch that leaves the side at a sharp turn (more than 30° within ±3% of the chord,
    // at the stretch or where it meets the held part) is a notch, slot, bite or horn. A side that
    // bends smoothly away from its line (a blob's rounded corner; an isoline of a wavy surface,
    // which is not straight when developed) is held as labeled: the labels say where the sides run.
    {
      std::vector<char> keep(sp.size(), 0);
      for (size_t j = 0, k = 0; j < sp.size(); ++j)
        if (k < kept.size() && kept[k] == sp[j]) keep[j] = 1, ++k;
      for (size_t j = 0; j < sp.size();) {
        if (keep[j]) {
          ++j;
          continue;
        }
        size_t e = j;
        while (e < sp.size() && !keep[e]) ++e;  // [j, e) left free
        bool turns = false;
        for (size_t q = j > 0 ? j - 1 : 0; q < std::min(e + 1, sp.size()) && !turns; ++q) turns = turnAt[q] > sharp;
        if (!turns) {
          for (size_t q = j; q < e; ++q) keep[q] = 1;
        } else {
          // The held part ends exactly at the sharp turn: held vertices past it would straighten
          // the corner over a few vertices, a singular wedge in the map (measured on the noisy
          // corpus: data max 1.6e-2 there, where scan noise let a few of them pass the tests).
          for (const bool left : {true, false}) {
            const size_t end = left ? j : e;  // the first free, or the first held after the run
            if ((left && j == 0) || (!left && e == sp.size())) continue;
            size_t best = end;
            double most = 0;
            for (size_t q = end; q > 0 && cumulative[end] - cumulative[q] < w; --q)
              if (turnAt[q] > most) most = turnAt[q], best = q;
            for (size_t q = end; q < sp.size() && cumulative[q] - cumulative[end] < w; ++q)
              if (turnAt[q] > most) most = turnAt[q], best = q;
            if (most <= sharp) continue;
            if (left) {
              for (size_t q = best + 1; q < e; ++q) keep[q] = 0;
              for (size_t q = j; q <= best && q < e; ++q) keep[q] = 1;
            } else {
              for (size_t q = j; q < best; ++q) keep[q] = 0;
              for (size_t q = best; q < e; ++q) keep[q] = 1;
            }
          }
        }
        j = e;
      }
      kept.clear();
      for (size_t j = 0; j < sp.size(); ++j)
        if (keep[j]) kept.push_back(sp[j]);
    }
    if (kept.size() < 2 || kept.size() == sp.size()) continue;
    released[side] = static_cast<int>(sp.size() - kept.size());
    sp = kept;
  }
  return released;
}

}  // namespace

namespace {

LabeledParameterization parameterizeOriented(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                             const LabeledParameterizationOptions& o, bool mayTurn);

}  // namespace

namespace {

// Taubin's λ|μ smoothing (λ 0.5, μ −0.53, uniform weights) along the surface normal only: a
// copy whose triangles have the surface's shape rather than its scan noise. At 0.2% of the
// diagonal the corpus's noise is a third of an edge and turns triangles over in 3D, and ARAP held
// to such rest shapes ends far from any map (data max 1.5e-2 on a noisy plane). Tangential moves
// are left out: they would slide vertices over the surface, and the map would then place each
// vertex where its smoothed copy went, not where it is (measured: 1.3e-4 → 1.5e-2 on a clean
// region smoothed in full).
// `tangentially`: inner vertices move by the whole umbrella, boundary vertices by their loop's,
// so that triangles that scan noise turned over (a vertex pushed past its neighbour's edge) open
// again; for the free flattening
// (relaxLabels), whose boundary nothing holds and which such triangles at the rim fold over
// itself (measured: 7,621 of 15,000 triangles turned at 0.2% noise on a crescent of 20,000
// vertices, 220 at the rim).
TriangleMesh denoised(const TriangleMesh& region, int rounds, const ScanNoise& noise, bool tangentially = false) {
  TriangleMesh out = region;
  // Only a noisy region is smoothed; a clean one is mapped as it is, exactly (mesh/scan_noise.h;
  // on every third region of the corpus it estimates the noise to within 5%). The threshold, 0.02
  // of the mean edge, lies between the corpus's clean and noisy regions: measured with the
  // median this estimate divides by 0.917, at most 0.001 on the clean ones and 0.028 or more on
  // the noisy ones.
  if (rounds <= 0 || !(noise.meanEdge > 0) || noise.sigma < 0.02 * noise.meanEdge) return out;
  const MeshTopology topo(region);
  const MeshHoleReport holes = findMeshHoles(region, topo);
  const Eigen::Index nv = region.vertices.rows();
  std::vector<std::vector<int>> ring(nv);
  for (const auto& e : topo.edges()) ring[e.a].push_back(e.b), ring[e.b].push_back(e.a);
  // A boundary jagged by noise at the scale of its edges crosses itself in the map: where it is
  // (its vertices turn by more than 10° at the median; a clean boundary, curved or cornered,
  // turns by a degree or two there), its vertices are smoothed along the loop as well, across it
  // only. A clean boundary is left as it is: smoothed, its corners round off, and the map there
  // is no longer the region's (measured: 1.3e-4 → 4.6e-3 on a clean bitten cylinder).
  std::vector<std::array<int, 2>> along(nv, {-1, -1});
  std::vector<char> boundary(nv, 0);
  std::vector<std::array<int, 2>> loopNeighbours(nv, {-1, -1});
  std::vector<double> turns;
  for (const MeshHole& h : holes.holes)
    for (size_t k = 0; k < h.loop.size(); ++k) {
      const int p = h.loop[(k + h.loop.size() - 1) % h.loop.size()], v = h.loop[k], q = h.loop[(k + 1) % h.loop.size()];
      along[v] = {p, q};
      loopNeighbours[v] = {p, q};
      boundary[v] = 1;
      turns.push_back(angleBetween(region.vertices.row(v) - region.vertices.row(p), region.vertices.row(q) - region.vertices.row(v)));
    }
  if (!turns.empty()) {
    std::nth_element(turns.begin(), turns.begin() + turns.size() / 2, turns.end());
    if (turns[turns.size() / 2] <= 10 * M_PI / 180) std::fill(along.begin(), along.end(), std::array<int, 2>{-1, -1});
  }
  // The copy is smoothed with its triangles in their consistent orientation, so that the vertex
  // normals do not cancel.
  TriangleMesh work{region.vertices, region.triangles};
  for (Eigen::Index t = 0; t < work.triangles.rows(); ++t)
    if (topo.flipped[t]) std::swap(work.triangles(t, 1), work.triangles(t, 2));
  Eigen::MatrixX3d& X = work.vertices;
  auto umbrella = [&](Eigen::Index v) {  // the mean of the neighbours, less the vertex
    Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
    for (int u : ring[v]) mean += X.row(u);
    return Eigen::RowVector3d(mean / static_cast<double>(ring[v].size()) - X.row(v));
  };
  for (int r = 0; r < 2 * rounds; ++r) {
    const Eigen::MatrixX3d normal = vertexNormals(work);
    const double step = r % 2 == 0 ? 0.5 : -0.53;
    Eigen::MatrixX3d next = X;
    for (Eigen::Index v = 0; v < nv; ++v) {
      if (ring[v].empty() || !(normal.row(v).norm() > 0)) continue;
      const Eigen::RowVector3d n = normal.row(v);
      if (tangentially) {
        // Boundary vertices along their loop (Taubin's steps keep it from shrinking).
        next.row(v) += step * (boundary[v] ? Eigen::RowVector3d(0.5 * (X.row(loopNeighbours[v][0]) + X.row(loopNeighbours[v][1])) - X.row(v))
                                           : umbrella(v));
        continue;
      }
      next.row(v) += step * umbrella(v).dot(n) * n;
      if (along[v][0] >= 0) {
        const Eigen::RowVector3d a = X.row(along[v][0]), b = X.row(along[v][1]);
        const Eigen::RowVector3d tangent = (b - a).normalized();
        Eigen::RowVector3d across = 0.5 * (a + b) - X.row(v);
        across -= across.dot(tangent) * tangent + across.dot(n) * n;
        next.row(v) += step * across;
      }
    }
    X = next;
  }
  out.vertices = X;
  return out;
}

}  // namespace

namespace {

// A side's points for its guiding-frame curve (mesh-extension.md sec. 4.1): its labeled vertices in
// running order and, across each gap between two of them (unlabeled vertices between two
// segments of the side, or a stretch left free), the paper's arc: the cubic Hermite curve from
// the one segment's end to the other's start with their end tangents, each as long as the
// distance between the two ends, sampled as densely as the gap's own vertices. Without it the
// frame's curve spans the gap by its bending term alone. `at[j]`: the frame point of side vertex j.
std::vector<Eigen::Vector3d> sidePointsWithArcs(const Eigen::MatrixX3d& x, const std::vector<int>& loop, const std::vector<int>& side,
                                                std::vector<int>& at) {
  const int L = static_cast<int>(loop.size());
  std::vector<Eigen::Vector3d> pts;
  at.assign(side.size(), -1);
  auto point = [&](int i) { return Eigen::Vector3d(x.row(loop[((i % L) + L) % L]).transpose()); };
  for (size_t j = 0; j < side.size(); ++j) {
    if (j > 0) {
      const int a = side[j - 1], b = side[j], gap = ((b - a) % L + L) % L - 1;
      if (gap > 0) {
        // The ends' tangents over up to three edges of each segment (one edge is noise on a scan).
        int back = 0, ahead = 0;
        while (back < 3 && j - 1 >= static_cast<size_t>(back) + 1 && ((side[j - 1 - back] - side[j - 2 - back]) % L + L) % L == 1) ++back;
        while (ahead < 3 && j + ahead + 1 < side.size() && ((side[j + ahead + 1] - side[j + ahead]) % L + L) % L == 1) ++ahead;
        const Eigen::Vector3d p0 = point(a), p1 = point(b);
        const double span = (p1 - p0).norm();
        Eigen::Vector3d m0 = back > 0 ? Eigen::Vector3d(p0 - point(side[j - 1 - back])) : Eigen::Vector3d(p1 - p0);
        Eigen::Vector3d m1 = ahead > 0 ? Eigen::Vector3d(point(side[j + ahead]) - p1) : Eigen::Vector3d(p1 - p0);
        if (m0.norm() > 0 && m1.norm() > 0 && span > 0) {
          m0 *= span / m0.norm();
          m1 *= span / m1.norm();
          for (int k = 1; k <= gap; ++k) {
            const double t = static_cast<double>(k) / (gap + 1), t2 = t * t, t3 = t2 * t;
            pts.push_back((2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * m1);
          }
        }
      }
    }
    at[j] = static_cast<int>(pts.size());
    pts.push_back(point(side[j]));
  }
  return pts;
}

}  // namespace

LabeledParameterization parameterizeLabeled(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                            const LabeledParameterizationOptions& o) {
  validateMesh(region, "region");
  const ScanNoise noise = estimateScanNoise(region);
  const TriangleMesh smooth = denoised(region, o.denoise, noise);
  LabeledParameterization p = parameterizeOriented(smooth, segments, o, true);
  p.mapped = smooth.vertices;
  p.noise = noise;
  return p;
}

namespace {

// mayTurn: when the labels run S, E, N, W clockwise along the triangles' own orientation, the
// region is read from its other side (its triangles turned), once.
LabeledParameterization parameterizeOriented(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                             const LabeledParameterizationOptions& o, bool mayTurn) {
  validateMesh(region, "region");
  const int nv = static_cast<int>(region.vertices.rows()), nt = static_cast<int>(region.triangles.rows());
  if (nt < 2) throw Error("the region has " + std::to_string(nt) + " triangle" + (nt == 1 ? "" : "s") + "; fitting needs a region of several");
  const MeshTopology topo(region);
  if (topo.nonManifoldEdges > 0) throw Error("the region has " + std::to_string(topo.nonManifoldEdges) + " non-manifold edges; fit a manifold region");
  if (topo.nonOrientableComponents > 0) throw Error("the region cannot be oriented consistently");
  if (topo.components != 1) throw Error("the region has " + std::to_string(topo.components) + " separate pieces; fit one connected region at a time");
  if (topo.unusedVertices > 0) throw Error("the region has vertices used by no triangle; remove them first");
  // Triangles read in the topology's consistent orientation.
  Eigen::MatrixX3i tri = region.triangles;
  for (int t = 0; t < nt; ++t)
    if (topo.flipped[t]) std::swap(tri(t, 1), tri(t, 2));

  const MeshHoleReport holes = findMeshHoles(region, topo);
  if (holes.holes.empty()) throw Error("the region is closed: it has no boundary to label");
  const MeshHole* outer = &holes.holes[0];
  for (const auto& h : holes.holes)
    if (h.length > outer->length) outer = &h;
  LabeledParameterization out;
  out.perimeter = outer->loop;
  const std::vector<int>& loop = out.perimeter;
  const int L = static_cast<int>(loop.size());
  std::vector<int> at(nv, -1);
  for (int k = 0; k < L; ++k) at[loop[k]] = k;

  // Segments: on the perimeter, consecutive (either way round), one side per vertex but at shared corners.
  std::vector<int> label(L, -1), labelEnds(L, 0);
  std::vector<std::pair<int, int>> spans;  // (first perimeter index, side) per segment, for ordering
  std::vector<std::vector<int>> ordered;   // each segment's perimeter indices, anticlockwise
  for (size_t s = 0; s < segments.size(); ++s) {
    const auto& seg = segments[s];
    const std::string who = std::string(sideName(seg.side)) + " segment " + std::to_string(s + 1);
    if (seg.vertices.empty()) throw Error(who + " names no vertex");
    std::vector<int> idx;
    for (int v : seg.vertices) {
      if (v < 0 || v >= nv || at[v] < 0) throw Error(who + ": vertex " + std::to_string(v) + " is not on the region's outer boundary");
      idx.push_back(at[v]);
    }
    bool forward = true, backward = true;
    for (size_t k = 1; k < idx.size(); ++k) {
      forward = forward && idx[k] == (idx[k - 1] + 1) % L;
      backward = backward && idx[k] == (idx[k - 1] + L - 1) % L;
    }
    if (!forward && !backward) throw Error(who + ": its vertices are not consecutive along the boundary");
    if (!forward) std::reverse(idx.begin(), idx.end());
    const int side = static_cast<int>(seg.side);
    for (size_t k = 0; k < idx.size(); ++k) {
      const bool end = k == 0 || k + 1 == idx.size();
      int& cur = label[idx[k]];
      if (cur >= 0 && cur != side && !(end && labelEnds[idx[k]]))
        throw Error("vertex " + std::to_string(loop[idx[k]]) + " is labeled both " + sideName(static_cast<Side>(cur)) + " and " +
                    sideName(seg.side) + "; a vertex may carry two labels only where two segments meet");
      if (cur < 0) cur = side, labelEnds[idx[k]] = end;
    }
    spans.emplace_back(idx[0], side);
    ordered.push_back(idx);
  }
  // Anticlockwise around the region the labels must run South, East, North, West (cyclically).
  std::vector<size_t> order(segments.size());
  for (size_t s = 0; s < order.size(); ++s) order[s] = s;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return spans[a].first < spans[b].first; });
  int descents = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    const int a = spans[order[k]].second, b = spans[order[(k + 1) % order.size()]].second;
    descents += b < a ? 1 : 0;
  }
  if (descents > 1) {
    int ascents = 0;
    for (size_t k = 0; k < order.size(); ++k)
      ascents += spans[order[(k + 1) % order.size()]].second > spans[order[k]].second ? 1 : 0;
    // The labels run S, E, N, W the other way round: the triangles face away from the side the
    // labels were given on (a scan's faces often do). The region is the same seen from its other
    // side, and so is the surface fitted to it.
    if (mayTurn && ascents <= 1) {
      TriangleMesh turned = region;
      turned.triangles.col(1).swap(turned.triangles.col(2));
      LabeledParameterization r = parameterizeOriented(turned, segments, o, false);
      r.warnings.insert(r.warnings.begin(), "the labels run South, East, North, West clockwise along the region's triangles: "
                                            "the region is read from its other side");
      return r;
    }
    throw Error("the labels are out of order: going anticlockwise around the region they must run South, East, North, West");
  }

  // The guiding frame over the labeled points, each side's segments in running order.
  LabeledSides sides;
  std::array<std::vector<int>, 4> sidePerimeter;  // perimeter index of each frame point
  size_t start = 0;  // begin at the first segment after a change of side, so a side's segments stay together
  for (size_t k = 0; k < order.size(); ++k)
    if (spans[order[k]].second != spans[order[(k + order.size() - 1) % order.size()]].second) {
      start = k;
      break;
    }
  for (size_t k = 0; k < order.size(); ++k) {
    const size_t s = order[(start + k) % order.size()];
    const int side = spans[s].second;
    for (int i : ordered[s]) sidePerimeter[side].push_back(i);
  }
  std::array<int, 4> releasedCount{};
  bool anyReleased = false;
  if (o.releaseDepth >= 0) {
    releasedCount = releaseInwardStretches(region, tri, loop, sidePerimeter, o.releaseDepth);
    for (int side = 0; side < 4; ++side) {
      if (releasedCount[side] == 0) continue;
      anyReleased = true;
      out.warnings.push_back(std::to_string(releasedCount[side]) + " vertices of the " + sideName(static_cast<Side>(side)) +
                             " side lie inside the line supporting it (a notch, slot, concave arc or rounded corner): left free");
    }
  }
  std::array<std::vector<int>, 4> frameIndex;  // where each of a side's perimeter points sits among its frame points
  for (int side = 0; side < 4; ++side) sides.points[side] = sidePointsWithArcs(region.vertices, loop, sidePerimeter[side], frameIndex[side]);
  out.frame = fitGuidingFrame(sides, o.frame);
  const GuidingFrame& f = out.frame;
  auto len = [&](Side s) { return f.labeled[static_cast<int>(s)] ? curveLength(f, s) : -1.0; };
  auto mid = [&](Side s) { return f.point(s, 0.5); };
  auto average = [](double a, double b) { return a < 0 ? b : (b < 0 ? a : 0.5 * (a + b)); };
  double W = average(len(Side::South), len(Side::North)), H = average(len(Side::East), len(Side::West));
  if (W < 0) W = (mid(Side::East) - mid(Side::West)).norm();
  if (H < 0) H = (mid(Side::South) - mid(Side::North)).norm();
  if (!(W > 0 && H > 0)) throw Error("the labeled sides give a rectangle without area");
  // W and H start Tutte's embedding; ARAP then sets them. A side whose frame curve was continued
  // far past its labels (a corner extrapolated from a short stretch: measured 90 units on a region
  // 10 across) would start it far off its proportions: no side is longer than half the perimeter.
  double perimeterLength = 0;
  for (int k = 0; k < L; ++k) perimeterLength += (region.vertices.row(loop[(k + 1) % L]) - region.vertices.row(loop[k])).norm();
  W = std::min(W, 0.5 * perimeterLength);
  H = std::min(H, 0.5 * perimeterLength);

  // Targets of the labeled perimeter vertices at scale 1.
  std::vector<Eigen::Vector2d> target(L, Eigen::Vector2d::Zero());
  std::vector<bool> fixed(L, false);
  std::vector<int> sidesAt(L, 0);  // bit per side labeling the perimeter vertex
  std::vector<int> slide(L, -1);   // the coordinate a labeled vertex off the corners slides along (0: u, 1: v)
  for (int side = 0; side < 4; ++side)
    for (int i : sidePerimeter[side]) sidesAt[i] |= 1 << side;
  // Where each labeled vertex lies along its side: the arc length of its projection on the frame
  // curve (not the Bezier parameter: a degree-raised curve runs at uneven speed, measured: a
  // straight side's point 60% along sat at parameter 0.73, which would stretch the map). Where
  // the projections do not follow the side's own order (a concave stretch, a notch or slot the
  // frame's curve passes by), they would send vertices onto one point or back over each other,
  // and the map folds at its boundary: that side's vertices are then placed by their arc length
  // along the labeled boundary itself, between its first and last projections.
  std::array<std::vector<double>, 4> along;
  for (int side = 0; side < 4; ++side) {
    const auto& sp = sidePerimeter[side];
    if (sp.empty()) continue;
    std::vector<double>& t = along[side];
    for (size_t j = 0; j < sp.size(); ++j)
      t.push_back(curveLength(f, static_cast<Side>(side), f.parameters[side][frameIndex[side][j]]) / curveLength(f, static_cast<Side>(side)));
    // Corners sit at the side's ends whatever their projection.
    if ((sidesAt[sp.front()] & ~(1 << side)) != 0) t.front() = 0;
    if ((sidesAt[sp.back()] & ~(1 << side)) != 0) t.back() = 1;
    const double minStep = 1e-3 / static_cast<double>(sp.size());
    bool ordered = true;
    for (size_t j = 1; j < t.size() && ordered; ++j) ordered = t[j] - t[j - 1] > minStep;
    if (ordered && releasedCount[side] == 0) continue;
    double t0 = t.front() < t.back() ? t.front() : 0, t1 = t.front() < t.back() ? t.back() : 1;
    if (releasedCount[side] > 0) {
      // A side with vertices left free: its frame curve reaches past them to corners guessed from
      // what is left, and ARAP places the side's vertices (no frame placement term). This is the
      // start only: by arc length, short of a corner the labels do not reach.
      t0 = (sidesAt[sp.front()] & ~(1 << side)) != 0 ? 0 : std::clamp(t.front(), 0.05, 0.45);
      t1 = (sidesAt[sp.back()] & ~(1 << side)) != 0 ? 1 : std::clamp(t.back(), 0.55, 0.95);
    }
    std::vector<double> arc(sp.size(), 0.0);
    for (size_t j = 1; j < sp.size(); ++j) arc[j] = arc[j - 1] + (region.vertices.row(loop[sp[j]]) - region.vertices.row(loop[sp[j - 1]])).norm();
    for (size_t j = 0; j < sp.size(); ++j) t[j] = t0 + (t1 - t0) * arc[j] / std::max(arc.back(), 1e-300);
    if (releasedCount[side] == 0)
      out.warnings.push_back(std::string("the ") + sideName(static_cast<Side>(side)) +
                             " side's vertices do not follow its frame curve in order (a concave stretch): placed by arc length");
  }
  for (int side = 0; side < 4; ++side)
    for (size_t j = 0; j < sidePerimeter[side].size(); ++j) {
      const int i = sidePerimeter[side][j];
      if (fixed[i]) continue;
      // Where two adjacent sides' segments meet, the vertex is the rectangle's corner itself.
      static const int cornerBits[4] = {1 | 2, 2 | 4, 4 | 8, 8 | 1};  // S|E, E|N, N|W, W|S
      static const double cornerU[4] = {1, 1, 0, 0}, cornerV[4] = {0, 1, 1, 0};
      bool corner = false;
      for (int c = 0; c < 4; ++c)
        if ((sidesAt[i] & cornerBits[c]) == cornerBits[c]) {
          target[i] = {cornerU[c] * W, cornerV[c] * H};
          corner = true;
        }
      if (corner) {
        fixed[i] = true;
        continue;
      }
      const double t = along[side][j];
      static const auto place = [](int s, double t, double W, double H) -> Eigen::Vector2d {
        switch (s) {
          case 0: return {t * W, 0};
          case 1: return {W, t * H};
          case 2: return {(1 - t) * W, H};
          default: return {0, (1 - t) * H};
        }
      };
      target[i] = place(side, t, W, H);
      fixed[i] = true;
      slide[i] = side % 2 == 0 ? 0 : 1;
    }

  // Start: Tutte's embedding, the perimeter on the rectangle (free stretches by arc length).
  Eigen::MatrixX2d uv = Eigen::MatrixX2d::Zero(nv, 2);
  std::vector<bool> onRim(nv, false);
  {
    std::vector<int> anchors;
    for (int i = 0; i < L; ++i)
      if (fixed[i]) anchors.push_back(i);
    for (size_t a = 0; a < anchors.size(); ++a) {
      const int i0 = anchors[a], i1 = anchors[(a + 1) % anchors.size()];
      const double p0 = perimeterCoordinate(target[i0], W, H);
      double p1 = perimeterCoordinate(target[i1], W, H);
      if (p1 <= p0) p1 += 2 * (W + H);
      double total = 0;
      for (int i = i0; i != i1; i = (i + 1) % L) total += (region.vertices.row(loop[(i + 1) % L]) - region.vertices.row(loop[i])).norm();
      double run = 0;
      for (int i = i0; i != i1; i = (i + 1) % L) {
        uv.row(loop[i]) = (fixed[i] ? target[i] : perimeterPoint(p0 + (p1 - p0) * run / std::max(total, 1e-300), W, H)).transpose();
        run += (region.vertices.row(loop[(i + 1) % L]) - region.vertices.row(loop[i])).norm();
      }
    }
    for (int i = 0; i < L; ++i) onRim[loop[i]] = true;
    std::vector<Eigen::Triplet<double>> T;
    Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(nv, 2);
    for (int v = 0; v < nv; ++v)
      if (onRim[v]) T.emplace_back(v, v, 1.0), rhs.row(v) = uv.row(v);
    for (const auto& e : topo.edges())
      for (const auto& [a, b] : {std::pair<int, int>{e.a, e.b}, {e.b, e.a}})
        if (!onRim[a]) T.emplace_back(a, a, 1.0), T.emplace_back(a, b, -1.0);
    Eigen::SparseMatrix<double> A(nv, nv);
    A.setFromTriplets(T.begin(), T.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
    if (lu.info() != Eigen::Success) throw Error("could not embed the region in the plane (Tutte's system is singular)");
    uv = lu.solve(rhs);
  }

  // ARAP: rows √w ((u_i − u_j) − R_t (x_i − x_j)) per triangle edge and coordinate; unknowns the
  // free vertices' uv, the along-side coordinate of labeled vertices (their other coordinate is
  // their side's, times the scale s), and s. The frame's placement along the side is a soft term
  // (framePlacement): held hard, a frame whose extrapolated corner is off (a missing corner on a
  // curved region, measured 0.47 off on a cylinder) squeezes the labeled stretch and folds the map.
  std::vector<std::array<int, 2>> col(nv, {-1, -1});
  int nUnknown = 0;
  for (int v = 0; v < nv; ++v) {
    if (!(onRim[v] && fixed[at[v]])) col[v] = {nUnknown, nUnknown + 1}, nUnknown += 2;
    else if (slide[at[v]] >= 0) col[v][slide[at[v]]] = nUnknown++;
  }
  // The rectangle's width and height are unknowns too (columns dimCol, dimCol + 1): a labeled
  // vertex's held coordinate is 0 or one of them, so ARAP sets the proportions where the frame's
  // are only a guess (sides with vertices left free, corners continued from short stretches).
  const int dimCol = nUnknown;
  const double dim0[2] = {W, H};
  using Term = ArapTerm;
  double reference = 0;
  const std::vector<Term> terms = arapTerms(region.vertices, tri, reference);
  std::vector<Eigen::Triplet<double>> T;
  int row = 0;
  auto coefficient = [&](int v, int c, double sign, std::vector<Eigen::Triplet<double>>& out, int r, double sw) {
    if (col[v][c] >= 0) out.emplace_back(r, col[v][c], sign * sw);
    else if (target[at[v]][c] != 0) out.emplace_back(r, dimCol + c, sign * sw * target[at[v]][c] / dim0[c]);
  };
  for (const Term& term : terms)
    for (int c = 0; c < 2; ++c, ++row) {
      const double sw = std::sqrt(term.w);
      coefficient(term.i, c, 1, T, row, sw);
      coefficient(term.j, c, -1, T, row, sw);
    }
  const int arapRows = row;
  double meanWeight = 0;
  for (const Term& term : terms) meanWeight += term.w / terms.size();
  const double sp = std::sqrt(o.framePlacement * meanWeight);
  for (int i = 0; i < L; ++i) {
    if (slide[i] < 0 || o.framePlacement <= 0) continue;
    int side = 0;
    while (!(sidesAt[i] & (1 << side))) ++side;
    if (releasedCount[side] > 0) continue;  // its frame curve is a guess past the vertices left free
    const int c = slide[i];
    T.emplace_back(row, col[loop[i]][c], sp);
    T.emplace_back(row, dimCol + c, -sp * target[i][c] / dim0[c]);
    ++row;
  }
  // A faint hold on W and H at their start, so that a dimension no labeled vertex sets (two
  // opposite sides labeled) is still determined; elsewhere it is negligible.
  const int holdRow = row;
  const double hold = 1e-6 * std::sqrt(meanWeight);
  for (int c = 0; c < 2; ++c) T.emplace_back(row++, dimCol + c, hold);
  Eigen::SparseMatrix<double> A(row, dimCol + 2);
  A.setFromTriplets(T.begin(), T.end());
  const Eigen::SparseMatrix<double> AtA = A.transpose() * A;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(AtA);
  if (solver.info() != Eigen::Success) throw Error("the ARAP system is singular");

  Eigen::MatrixX2d good = uv;
  double goodDim[2] = {W, H};
  // A triangle whose three vertices are all held on one side of the rectangle (an ear of the
  // labeled boundary: three consecutive vertices of one side) is flat in every map and cannot be
  // opened; it is not a fold. Counting it as one kept Tutte's start over every ARAP iterate on 29
  // of the corpus's 63 regions (every concave one): only triangles turned over count.
  std::vector<char> pinnedFlat(nt, 0);
  for (int t = 0; t < nt; ++t) {
    int common = 0xF;
    for (int k = 0; k < 3; ++k) {
      const int v = tri(t, k);
      common &= onRim[v] && fixed[at[v]] ? sidesAt[at[v]] : 0;
    }
    pinnedFlat[t] = common != 0;
  }
  // A triangle the input itself has turned over (its normal against its corners' mean normals:
  // scan noise of a third of an edge does this to some) folds in every map; it is not the map's
  // fold, and counting it kept Tutte's start on the corpus's noisiest regions.
  {
    const std::vector<char> turned = trianglesTurnedInInput(region.vertices, tri);
    for (int t = 0; t < nt; ++t)
      if (turned[t]) pinnedFlat[t] = 1;
  }
  // Tutte's start also lays the ears of stretches left free flat along the rectangle; ARAP opens
  // them, and only their turning over counts.
  const double flat = 1e-12 * W * H;
  std::vector<char> startFlat(nt, 0);
  for (int t = 0; t < nt; ++t) startFlat[t] = std::abs(signedArea(uv, tri.row(t).transpose())) <= flat;
  auto flips = [&](const Eigen::MatrixX2d& m) {
    int n = 0;
    for (int t = 0; t < nt; ++t) {
      if (pinnedFlat[t]) continue;
      const double a = signedArea(m, tri.row(t).transpose());
      n += (startFlat[t] ? a < -flat : a <= 0) ? 1 : 0;
    }
    return n;
  };
  const int startFlips = flips(uv);
  if (anyReleased &&
      std::any_of(target.begin(), target.end(), [](const Eigen::Vector2d& q) { return q.x() != 0 || q.y() != 0; })) {
    // With stretches left free, Tutte's start squeezes each onto the rectangle between its held
    // neighbours (an inner arc of 150 vertices onto a short piece of a side), and ARAP, stepping
    // back from every fold, does not open it in its rounds (measured: a crescent's horn shot out
    // of the rectangle). ARAP starts instead from the as-similar-as-possible map (Liu et al.
    // 2008; LSCM's energy): the same rows with a similarity a·I + b·J per triangle, unknown, so
    // one linear solve gives a conformal map that opens the free stretches. Kept when it turns no
    // triangle over.
    const int ab = dimCol + 2;
    std::vector<Eigen::Triplet<double>> S;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(row + 2);
    int r = 0;
    for (const Term& term : terms) {
      const double sw = std::sqrt(term.w);
      for (int c = 0; c < 2; ++c, ++r) {
        coefficient(term.i, c, 1, S, r, sw);
        coefficient(term.j, c, -1, S, r, sw);
        // c = 0: a x − b y; c = 1: b x + a y.
        S.emplace_back(r, ab + 2 * term.t, -sw * (c == 0 ? term.x.x() : term.x.y()));
        S.emplace_back(r, ab + 2 * term.t + 1, -sw * (c == 0 ? -term.x.y() : term.x.x()));
      }
    }
    for (const auto& tr : T)
      if (tr.row() >= arapRows) S.push_back(tr);
    // Its scale: W and H held at their starts, each that a labeled vertex uses; ARAP then frees
    // them. (Holding only W, the similarities let H shrink: on a crescent whose inner arc was left
    // free, H fell from 5.65 to 0.013, the held sides ran into one line and the map ballooned
    // around it, 56 triangles turned over. Holding the similarities' mean scale instead couples
    // every triangle in one row, and the normal equations turn dense.)
    bool uses[2] = {false, false};
    for (int i = 0; i < L; ++i)
      if (fixed[i])
        for (int c = 0; c < 2; ++c) uses[c] = uses[c] || target[i][c] != 0;
    if (!uses[0] && !uses[1]) uses[0] = true;
    double total = 0;
    for (const Term& term : terms) total += term.w;
    const double unit = std::sqrt(total);
    for (int c = 0; c < 2; ++c) rhs[holdRow + c] = hold * dim0[c];
    int pins = 0;
    for (int c = 0; c < 2; ++c)
      if (uses[c]) {
        S.emplace_back(row + pins, dimCol + c, unit);
        rhs[row + pins] = unit * dim0[c];
        ++pins;
      }
    Eigen::SparseMatrix<double> M(row + pins, ab + 2 * nt);
    M.setFromTriplets(S.begin(), S.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> asap(Eigen::SparseMatrix<double>(M.transpose() * M));
    if (asap.info() == Eigen::Success) {
      const Eigen::VectorXd z = asap.solve(M.transpose() * rhs.head(row + pins));
      Eigen::MatrixX2d m(nv, 2);
      for (int v = 0; v < nv; ++v)
        for (int c = 0; c < 2; ++c) m(v, c) = col[v][c] >= 0 ? z[col[v][c]] : z[dimCol + c] * target[at[v]][c] / dim0[c];
      if (z.allFinite() && z[dimCol] > 0 && z[dimCol + 1] > 0 && flips(m) == 0) {
        uv = m;
        good = m;
        goodDim[0] = z[dimCol], goodDim[1] = z[dimCol + 1];
      }
    }
  }
  double energy = 0, goodEnergy = std::numeric_limits<double>::infinity(), lastDim[2] = {W, H};
  // The local step: the rotation nearest to each triangle's map, as the global step's right side.
  auto localStep = [&](const Eigen::MatrixX2d& m) {
    const std::vector<Eigen::Matrix2d> R = arapRotations(terms, m, nt);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(row);  // the frame rows' right side is 0
    for (int c = 0; c < 2; ++c) b[holdRow + c] = hold * dim0[c];
    int r = 0;
    for (const Term& term : terms) {
      const Eigen::Vector2d e = R[term.t] * term.x;
      for (int c = 0; c < 2; ++c) b[r++] = std::sqrt(term.w) * e[c];
    }
    return b;
  };
  auto mapOf = [&](const Eigen::VectorXd& zz, Eigen::MatrixX2d& m) {
    for (int v = 0; v < nv; ++v)
      for (int c = 0; c < 2; ++c) m(v, c) = col[v][c] >= 0 ? zz[col[v][c]] : zz[dimCol + c] * target[at[v]][c] / dim0[c];
  };
  auto unknownsOf = [&](const Eigen::MatrixX2d& m, const double dim[2]) {
    Eigen::VectorXd zz(dimCol + 2);
    for (int v = 0; v < nv; ++v)
      for (int c = 0; c < 2; ++c)
        if (col[v][c] >= 0) zz[col[v][c]] = m(v, c);
    zz[dimCol] = dim[0], zz[dimCol + 1] = dim[1];
    return zz;
  };
  auto arapRounds = [&](int rounds) {
    double tenBefore = std::numeric_limits<double>::infinity();  // the energy ten rounds ago
    // Past the rounds asked for, ARAP goes on only from a map without folds, and what it reaches
    // is kept only if it ends without folds too; otherwise the map of the last asked-for round
    // (going on through folds, a noisy crescent's map ended with 1,377 of 10,174 triangles
    // folded, which SLIM relaxed to a map of ARAP energy 0.99, and its fit missed by 8e-2).
    struct State {
      Eigen::MatrixX2d uv, good;
      double energy, goodEnergy, arapEnergy, goodDim[2], lastDim[2];
    };
    std::optional<State> asked;
    for (int it = 0; it < std::max(rounds, o.maxIterations); ++it) {
      if (it == rounds) {
        if (flips(uv) > 0) break;
        asked = State{uv, good, energy, goodEnergy, out.arapEnergy, {goodDim[0], goodDim[1]}, {lastDim[0], lastDim[1]}};
      }
      // Local, then global: the least-squares uv and scale.
      const Eigen::VectorXd b = localStep(uv);
      Eigen::VectorXd z = solver.solve(A.transpose() * b);
      if (!z.allFinite()) throw Error("the ARAP solve failed");
      mapOf(z, uv);
      if (flips(uv) > 0 && flips(good) == 0) {
        // The global step overshot into a fold: step back towards the last map without folds (the
        // unknowns, scale included, blended), halving until none is left (flip repair). Every
        // accepted map is then a fold-free one, and the rotations of the next round come from it.
        const Eigen::VectorXd zGood = unknownsOf(good, goodDim);
        Eigen::MatrixX2d mix(nv, 2);
        for (double alpha = 0.5; alpha > 1e-3; alpha *= 0.5) {
          const Eigen::VectorXd zm = zGood + alpha * (z - zGood);
          mapOf(zm, mix);
          if (flips(mix) == 0) {
            z = zm;
            uv = mix;
            break;
          }
        }
      }
      energy = (A * z - b).head(arapRows).squaredNorm() / reference;
      lastDim[0] = z[dimCol], lastDim[1] = z[dimCol + 1];
      if (flips(uv) == 0) good = uv, goodDim[0] = z[dimCol], goodDim[1] = z[dimCol + 1], out.arapEnergy = goodEnergy = energy;
      // A fold in an early round that no step back avoids often opens again as the rotations
      // settle: keep going, and keep the last map without folds.
      if ((it + 1) % 10 == 0) {
        if (it + 1 >= rounds && !(energy < 0.99 * tenBefore)) break;
        tenBefore = energy;
      }
    }
    if (asked && flips(uv) > 0) {
      uv = asked->uv, good = asked->good, energy = asked->energy, goodEnergy = asked->goodEnergy, out.arapEnergy = asked->arapEnergy;
      goodDim[0] = asked->goodDim[0], goodDim[1] = asked->goodDim[1], lastDim[0] = asked->lastDim[0], lastDim[1] = asked->lastDim[1];
    }
  };
  arapRounds(o.iterations);
  if (const int folded = flips(uv); folded > 0) {
    // ARAP's rounds end folded (where a stretch left free meets a held side, measured on the
    // corpus: 12 slivers on a clean B-spline region, whose fit then missed by 6.7e-2; or every
    // round folds and the last map without folds is Tutte's start, a crescent's inner arc laid
    // along a side). The last map without folds is then relaxed by SLIM (slim_descent.h), whose
    // steps stop short of turning a triangle over: the same labeled vertices held, the rectangle's
    // width and height free, ears and triangles turned over in the input left out; triangles that
    // map flat (a free stretch laid along a side by Tutte's start), which the barrier cannot weigh,
    // are weighed by ARAP's energy instead, and the result must have none folded. ARAP then goes on from it, its steps
    // held back to maps without folds as before.
    SlimProblem sp;
    sp.triangles = tri;
    sp.rest = restShapes(region.vertices, tri);
    sp.skip = pinnedFlat;
    sp.soft.assign(nt, 0);
    for (int t = 0; t < nt; ++t) sp.soft[t] = !(signedArea(good, tri.row(t).transpose()) > 0);
    std::vector<Eigen::Triplet<double>> M;
    for (int v = 0; v < nv; ++v)
      for (int c = 0; c < 2; ++c) {
        if (col[v][c] >= 0) M.emplace_back(2 * v + c, col[v][c], 1.0);
        else if (target[at[v]][c] != 0) M.emplace_back(2 * v + c, dimCol + c, target[at[v]][c] / dim0[c]);
      }
    sp.map.resize(2 * nv, dimCol + 2);
    sp.map.setFromTriplets(M.begin(), M.end());
    try {
      const SlimResult relaxed = slimDescent(sp, unknownsOf(good, goodDim));
      Eigen::MatrixX2d m(nv, 2);
      mapOf(relaxed.z, m);
      if (flips(m) == 0 && !boundaryCrosses(holes, m)) {
        good = uv = m;
        goodDim[0] = relaxed.z[dimCol], goodDim[1] = relaxed.z[dimCol + 1];
        out.arapEnergy = goodEnergy = energy = (A * relaxed.z - localStep(m)).head(arapRows).squaredNorm() / reference;
        const double relaxedEnergy = goodEnergy;
        arapRounds(o.iterations);
        if (boundaryCrosses(holes, good)) {
          // ARAP's steps keep triangles from turning over, not the free boundary from running over
          // itself: the relaxed map is kept then.
          good = m;
          goodDim[0] = relaxed.z[dimCol], goodDim[1] = relaxed.z[dimCol + 1];
          out.arapEnergy = goodEnergy = relaxedEnergy;
        }
        uv = good;
        energy = goodEnergy;
        lastDim[0] = goodDim[0], lastDim[1] = goodDim[1];
        out.warnings.push_back("ARAP folded " + std::to_string(folded) + " of " + std::to_string(nt) +
                               " triangles; the map was relaxed without folds instead (SLIM)");
      }
    } catch (const Error&) {
      // No triangle left to weigh: the map is left as ARAP ended it.
    }
  }
  out.uv = good;
  out.flippedTriangles = flips(good);
  out.width = goodDim[0];
  out.height = goodDim[1];
  const int lastFlips = flips(uv);
  const bool lastCrosses = lastFlips > 0 && boundaryCrosses(holes, uv);
  if (lastFlips > 0 && lastFlips <= std::max(2, nt / 100) && energy < 0.8 * goodEnergy && !lastCrosses) {
    // Scan noise on a held side can push a boundary vertex past its inner neighbour, and the
    // sliver between them folds in every map that holds the side; flip repair then kept an early
    // map (Tutte's start on most of the corpus's noisy regions, data max ten times the noise;
    // measured: 47 of 9,993 triangles folded at 0.2% noise, ARAP energy 0.026 against the start's
    // far larger). The converged map is kept when its folds are such slivers: at most 1% of the
    // triangles, its boundary simple. (SLIM, tried first, had left some of them folded too, or run
    // its free boundary over itself; on clean regions such slivers sit where a free stretch meets
    // a held side.)
    out.warnings.push_back(std::to_string(lastFlips) +
                           " sliver triangles stay folded at the boundary (scan noise, or a free stretch meeting a held side); the converged map is kept");
    out.uv = uv;
    out.flippedTriangles = lastFlips;
    out.arapEnergy = energy;
    out.width = lastDim[0];
    out.height = lastDim[1];
  } else if (out.flippedTriangles > 0) {
    // Tutte's start may hold flat triangles (three boundary vertices on one side of the
    // rectangle), which ARAP opens; only folds left in the returned map are worth a warning.
    out.warnings.push_back(std::to_string(out.flippedTriangles) + " triangles stay folded in the map (" + std::to_string(startFlips) +
                           " in Tutte's start): the fit there follows a folded parameterization; corner labels on a smooth "
                           "stretch of boundary or sides of very different lengths fold it (move those corners, or let the labels relax)");
  } else if (lastFlips > 0) {
    out.warnings.push_back("ARAP folded " + std::to_string(lastFlips) + " of " + std::to_string(nt) + " triangles" +
                           (lastCrosses ? " and its boundary crossed itself" : "") + "; the last unfolded map is kept");
  }
  if (anyReleased) {
    // The map with every labeled vertex held, as labeled, is kept instead where leaving the
    // stretches free did not pay: they ran over each other or folded, or ARAP, started from a map
    // far from its own (a side of a strongly curved surface, whose development turns sharply),
    // ended more distorted than the held map.
    LabeledParameterizationOptions heldOptions = o;
    heldOptions.releaseDepth = -1;
    LabeledParameterization held = parameterizeOriented(region, segments, heldOptions, false);
    const bool crosses = boundaryCrosses(holes, out.uv);
    if (crosses || !(out.arapEnergy < held.arapEnergy)) {
      char why[160];
      std::snprintf(why, sizeof why, "%s (ARAP energy %.3g against %.3g held)",
                    crosses ? "they ran over each other" : "the map was no less distorted", out.arapEnergy, held.arapEnergy);
      held.warnings.insert(held.warnings.begin(), std::string("labeled stretches inside their sides' lines were tried free, and held again: ") + why);
      return held;
    }
  }
  return out;
}

}  // namespace

LabeledParameterization relaxLabels(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                    const LabeledParameterization& labeled, const LabeledParameterizationOptions& o) {
  const MeshTopology topo(region);
  Eigen::MatrixX3i tri = region.triangles;
  for (Eigen::Index t = 0; t < tri.rows(); ++t)
    if (topo.flipped[t]) std::swap(tri(t, 1), tri(t, 2));
  const Eigen::MatrixX3d relaxedCopy = denoised(region, o.denoise, labeled.noise, true).vertices;
  const TriangleMesh flattened{relaxedCopy, tri};
  FreeFlattening flat = flattenFree(flattened);
  if (flat.flippedTriangles > 0 || flat.boundaryCrosses) {
    // ARAP keeps triangles from turning over, not distant parts of the boundary from overlapping
    // (measured on the corpus: an arm of a saddle's U-slot over the other, a steep B-spline L's
    // arm over its inner corner), and such a map trims nothing. Started from the labeled map,
    // which is one to one, and kept so at every step.
    FreeFlatteningOptions from;
    from.start = labeled.uv;
    flat = flattenFree(flattened, from);
  }
  if (flat.flippedTriangles > 0)
    throw Error("the region's free flattening folds " + std::to_string(flat.flippedTriangles) + " triangles");
  if (flat.boundaryCrosses)
    throw Error("the region's free flattening runs its boundary over itself (a surface too curved to lie flat in one piece)");
  std::vector<Eigen::Vector2d> rim;
  for (int v : labeled.perimeter) rim.push_back(flat.uv.row(v).transpose());
  const double snug = leastAreaRectangleAngle(rim);
  static const Eigen::Vector2d where[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  std::array<Eigen::Vector2d, 4> centre;
  centre.fill(Eigen::Vector2d::Zero());
  std::array<int, 4> count{};
  Eigen::Vector2d all = Eigen::Vector2d::Zero();
  int total = 0;
  for (const LabeledSegment& s : segments)
    for (int v : s.vertices) {
      centre[static_cast<int>(s.side)] += flat.uv.row(v).transpose();
      ++count[static_cast<int>(s.side)];
      all += flat.uv.row(v).transpose();
      ++total;
    }
  if (total == 0) throw Error("no labeled vertex to orient the flattening by");
  all /= total;
  double best = -std::numeric_limits<double>::infinity(), angle = 0;
  bool mirror = false;
  for (const bool m : {false, true})
    for (int quarter = 0; quarter < 4; ++quarter) {
      const double a = (m ? -snug : snug) + quarter * M_PI / 2;
      const Eigen::Matrix2d turn = Eigen::Rotation2Dd(a).toRotationMatrix();
      double score = 0;
      for (int side = 0; side < 4; ++side) {
        if (count[side] == 0) continue;
        Eigen::Vector2d d = centre[side] / count[side] - all;
        if (m) d.x() = -d.x();
        score += (turn * d).dot(where[side]);
      }
      if (score > best) best = score, angle = a, mirror = m;
    }
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(angle).toRotationMatrix();
  LabeledParameterization out = labeled;
  out.uv.resize(flat.uv.rows(), 2);
  for (Eigen::Index v = 0; v < flat.uv.rows(); ++v) {
    Eigen::Vector2d q = flat.uv.row(v).transpose();
    if (mirror) q.x() = -q.x();
    out.uv.row(v) = (R * q).transpose();
  }
  const Eigen::RowVector2d lo = out.uv.colwise().minCoeff();
  out.uv.rowwise() -= lo;
  out.width = out.uv.col(0).maxCoeff();
  out.height = out.uv.col(1).maxCoeff();
  out.flippedTriangles = flat.flippedTriangles;
  out.arapEnergy = flat.arapEnergy;
  // The perimeter anticlockwise in the new map.
  Polygon2 loop;
  for (int v : out.perimeter) loop.push_back(out.uv.row(v).transpose());
  if (signedArea(loop) < 0) std::reverse(out.perimeter.begin(), out.perimeter.end());
  out.warnings.clear();
  return out;
}

}  // namespace holefill
