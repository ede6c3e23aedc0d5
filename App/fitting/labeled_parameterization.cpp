#include "fitting/labeled_parameterization.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <map>

#include "geometry/error.h"
#include "mesh/mesh_holes.h"
#include "mesh/mesh_topology.h"

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

double signedArea(const Eigen::MatrixX2d& uv, const Eigen::Vector3i& t) {
  const Eigen::Vector2d a = uv.row(t[1]) - uv.row(t[0]), b = uv.row(t[2]) - uv.row(t[0]);
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

}  // namespace

namespace {

LabeledParameterization parameterizeOriented(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                             const LabeledParameterizationOptions& o, bool mayTurn);

}  // namespace

LabeledParameterization parameterizeLabeled(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                            const LabeledParameterizationOptions& o) {
  return parameterizeOriented(region, segments, o, true);
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
    for (int i : ordered[s]) {
      sides.points[side].push_back(region.vertices.row(loop[i]).transpose());
      sidePerimeter[side].push_back(i);
    }
  }
  out.frame = fitGuidingFrame(sides, o.frame);
  const GuidingFrame& f = out.frame;
  auto len = [&](Side s) { return f.labeled[static_cast<int>(s)] ? curveLength(f, s) : -1.0; };
  auto mid = [&](Side s) { return f.point(s, 0.5); };
  auto average = [](double a, double b) { return a < 0 ? b : (b < 0 ? a : 0.5 * (a + b)); };
  double W = average(len(Side::South), len(Side::North)), H = average(len(Side::East), len(Side::West));
  if (W < 0) W = (mid(Side::East) - mid(Side::West)).norm();
  if (H < 0) H = (mid(Side::South) - mid(Side::North)).norm();
  if (!(W > 0 && H > 0)) throw Error("the labeled sides give a rectangle without area");

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
      t.push_back(curveLength(f, static_cast<Side>(side), f.parameters[side][j]) / curveLength(f, static_cast<Side>(side)));
    // Corners sit at the side's ends whatever their projection.
    if ((sidesAt[sp.front()] & ~(1 << side)) != 0) t.front() = 0;
    if ((sidesAt[sp.back()] & ~(1 << side)) != 0) t.back() = 1;
    const double minStep = 1e-3 / static_cast<double>(sp.size());
    bool ordered = true;
    for (size_t j = 1; j < t.size() && ordered; ++j) ordered = t[j] - t[j - 1] > minStep;
    if (ordered) continue;
    const double t0 = t.front() < t.back() ? t.front() : 0, t1 = t.front() < t.back() ? t.back() : 1;
    std::vector<double> arc(sp.size(), 0.0);
    for (size_t j = 1; j < sp.size(); ++j) arc[j] = arc[j - 1] + (region.vertices.row(loop[sp[j]]) - region.vertices.row(loop[sp[j - 1]])).norm();
    for (size_t j = 0; j < sp.size(); ++j) t[j] = t0 + (t1 - t0) * arc[j] / std::max(arc.back(), 1e-300);
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
  const int sCol = nUnknown;
  struct Term {
    int t, i, j;
    double w;
    Eigen::Vector2d x;  // x_i − x_j in the triangle's own isometric frame
  };
  std::vector<Term> terms;
  double reference = 0;
  for (int t = 0; t < nt; ++t) {
    const Eigen::Vector3d p[3] = {region.vertices.row(tri(t, 0)), region.vertices.row(tri(t, 1)), region.vertices.row(tri(t, 2))};
    const Eigen::Vector3d e1 = p[1] - p[0], e2 = p[2] - p[0];
    const double l1 = e1.norm();
    const Eigen::Vector2d x[3] = {{0, 0}, {l1, 0}, {e1.dot(e2) / l1, e1.cross(e2).norm() / l1}};
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;  // edge opposite corner k
      const Eigen::Vector2d u = x[a] - x[k], v = x[b] - x[k];
      const double cot = u.dot(v) / std::max(std::abs(u.x() * v.y() - u.y() * v.x()), 1e-300);
      const double w = std::max(0.5 * cot, 1e-4);  // obtuse corners: a small positive weight keeps the rows real
      terms.push_back({t, tri(t, a), tri(t, b), w, x[a] - x[b]});
      reference += w * (x[a] - x[b]).squaredNorm();
    }
  }
  std::vector<Eigen::Triplet<double>> T;
  int row = 0;
  auto coefficient = [&](int v, int c, double sign, std::vector<Eigen::Triplet<double>>& out, int r, double sw) {
    if (col[v][c] >= 0) out.emplace_back(r, col[v][c], sign * sw);
    else out.emplace_back(r, sCol, sign * sw * target[at[v]][c]);
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
  for (int i = 0; i < L; ++i)
    if (slide[i] >= 0 && o.framePlacement > 0) {
      const int c = slide[i];
      T.emplace_back(row, col[loop[i]][c], sp);
      T.emplace_back(row, sCol, -sp * target[i][c]);
      ++row;
    }
  Eigen::SparseMatrix<double> A(row, sCol + 1);
  A.setFromTriplets(T.begin(), T.end());
  const Eigen::SparseMatrix<double> AtA = A.transpose() * A;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(AtA);
  if (solver.info() != Eigen::Success) throw Error("the ARAP system is singular");

  Eigen::MatrixX2d good = uv;
  double s = 1, goodScale = 1;  // Tutte's start is at scale 1
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
  auto flips = [&](const Eigen::MatrixX2d& m) {
    int n = 0;
    for (int t = 0; t < nt; ++t) n += !pinnedFlat[t] && signedArea(m, tri.row(t).transpose()) <= 0 ? 1 : 0;
    return n;
  };
  const int startFlips = flips(uv);
  double energy = 0;
  for (int it = 0; it < o.iterations; ++it) {
    // Local: the rotation nearest to each triangle's current map.
    std::vector<Eigen::Matrix2d> R(nt, Eigen::Matrix2d::Zero());
    for (const Term& term : terms) R[term.t] += term.w * (uv.row(term.i) - uv.row(term.j)).transpose() * term.x.transpose();
    for (auto& r : R) {
      Eigen::JacobiSVD<Eigen::Matrix2d> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
      Eigen::Matrix2d D = Eigen::Matrix2d::Identity();
      D(1, 1) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
      r = svd.matrixU() * D * svd.matrixV().transpose();
    }
    // Global: the least-squares uv and scale.
    Eigen::VectorXd b = Eigen::VectorXd::Zero(row);  // the frame rows' right side is 0
    int r = 0;
    for (const Term& term : terms) {
      const Eigen::Vector2d e = R[term.t] * term.x;
      for (int c = 0; c < 2; ++c) b[r++] = std::sqrt(term.w) * e[c];
    }
    Eigen::VectorXd z = solver.solve(A.transpose() * b);
    if (!z.allFinite()) throw Error("the ARAP solve failed");
    auto mapOf = [&](const Eigen::VectorXd& zz, Eigen::MatrixX2d& m) {
      for (int v = 0; v < nv; ++v)
        for (int c = 0; c < 2; ++c) m(v, c) = col[v][c] >= 0 ? zz[col[v][c]] : zz[sCol] * target[at[v]][c];
    };
    mapOf(z, uv);
    if (flips(uv) > 0 && flips(good) == 0) {
      // The global step overshot into a fold: step back towards the last map without folds (the
      // unknowns, scale included, blended), halving until none is left (flip repair). Every
      // accepted map is then a fold-free one, and the rotations of the next round come from it.
      Eigen::VectorXd zGood(z.size());
      for (int v = 0; v < nv; ++v)
        for (int c = 0; c < 2; ++c)
          if (col[v][c] >= 0) zGood[col[v][c]] = good(v, c);
      zGood[sCol] = goodScale;
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
    s = z[sCol];
    energy = (A * z - b).head(arapRows).squaredNorm() / reference;
    if (flips(uv) == 0) good = uv, goodScale = s, out.arapEnergy = energy;
    // A fold in an early round that no step back avoids often opens again as the rotations
    // settle: keep going, and keep the last map without folds.
  }
  out.uv = good;
  out.flippedTriangles = flips(good);
  // Tutte's start may hold flat triangles (three boundary vertices on one side of the rectangle),
  // which ARAP opens; only folds left in the returned map are worth a warning.
  if (out.flippedTriangles > 0)
    out.warnings.push_back(std::to_string(out.flippedTriangles) + " triangles stay folded (" + std::to_string(startFlips) +
                           " in Tutte's start)");
  else if (flips(uv) > 0)
    out.warnings.push_back("ARAP folded triangles; the last unfolded map is kept");
  const double kept = goodScale;
  out.width = kept * W;
  out.height = kept * H;
  return out;
}

}  // namespace

}  // namespace holefill
