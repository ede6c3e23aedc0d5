#include "brep/hole_detection.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <cmath>
#include <set>

#include "brep/boundary_sampling.h"
#include "geometry/error.h"
#include "geometry/occt_bridge.h"

namespace holefill {

std::vector<int> Hole::edgeIndices() const {
  std::vector<int> r;
  for (const auto& e : edges) r.push_back(e.edgeIndex);
  return r;
}

Eigen::Vector3d edgeTangent(const TopoDS_Edge& edge, bool atEnd) {
  BRepAdaptor_Curve c(edge);
  const bool reversed = edge.Orientation() == TopAbs_REVERSED;
  const bool atLast = atEnd != reversed;
  const double t0 = c.FirstParameter(), t1 = c.LastParameter();
  double t = atLast ? t1 : t0;
  gp_Pnt p;
  gp_Vec d;
  c.D1(t, p, d);
  Eigen::Vector3d v = toEigen(d);
  // A vanishing derivative at the end (e.g. a collapsed control polygon): step inside.
  for (int i = 0; i < 8 && v.norm() < 1e-12; ++i) {
    t = atLast ? t1 - (t1 - t0) * std::pow(10.0, -6 + i) : t0 + (t1 - t0) * std::pow(10.0, -6 + i);
    c.D1(t, p, d);
    v = toEigen(d);
  }
  if (v.norm() < 1e-300) return Eigen::Vector3d::Zero();
  v.normalize();
  return reversed ? Eigen::Vector3d(-v) : v;
}

namespace {

struct FreeEdge {
  TopoDS_Edge edge;  // hole orientation
  int edgeIndex, faceIndex;
  TopoDS_Face face;
  int v0 = 0, v1 = 0;  // vertex indices of traversal start / end
};

double parameterAt(const TopoDS_Edge& e, bool atEnd) {
  BRepAdaptor_Curve c(e);
  const bool last = atEnd != (e.Orientation() == TopAbs_REVERSED);
  return last ? c.LastParameter() : c.FirstParameter();
}

double signedTurn(const Eigen::Vector3d& tin, const Eigen::Vector3d& tout, const Eigen::Vector3d& n) {
  return std::atan2(tin.cross(tout).dot(n), tin.dot(tout));
}

}  // namespace

void finishHole(Hole& h, const HoleDetectionOptions& opt) {
  const double cornerRad = opt.cornerAngleDeg * M_PI / 180.0;
  Bnd_Box box;
  std::vector<Eigen::Vector3d> pts, inward;
  std::vector<double> w;
  h.length = 0.0;
  h.corners = 0;
  for (size_t k = 0; k < h.edges.size(); ++k) {
    HoleEdge& he = h.edges[k];
    const HoleEdge& prev = h.edges[(k + h.edges.size() - 1) % h.edges.size()];
    const Eigen::Vector3d tin = edgeTangent(prev.edge, true), tout = edgeTangent(he.edge, false);
    he.turnAtStart = std::acos(std::clamp(tin.dot(tout), -1.0, 1.0));
    he.cornerAtStart = he.turnAtStart > cornerRad;
    if (he.cornerAtStart) ++h.corners;
    BRepAdaptor_Curve c(he.edge);
    he.length = GCPnts_AbscissaPoint::Length(c);
    he.tolerance = BRep_Tool::Tolerance(he.edge);
    h.length += he.length;
    const bool rev = he.edge.Orientation() == TopAbs_REVERSED;
    for (int i = 0; i <= 8; ++i) {
      const double t = c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / 8.0;
      gp_Pnt p;
      gp_Vec d;
      c.D1(t, p, d);
      box.Add(p);
      Eigen::Vector3d n;
      if (i == 0 || i == 8 || d.Magnitude() < 1e-12 || !supportNormal(he.edge, he.support, t, n)) continue;
      const Eigen::Vector3d tan = toEigen(d).normalized() * (rev ? -1.0 : 1.0);
      pts.push_back(toEigen(p));
      inward.push_back(-n.cross(tan));  // into the support's material
      w.push_back(he.length);
    }
  }
  if (!box.IsVoid()) h.scale = std::sqrt(box.SquareExtent());
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double wsum = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) { centroid += w[i] * pts[i]; wsum += w[i]; }
  if (wsum > 0) centroid /= wsum;
  double score = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d toC = centroid - pts[i];
    if (toC.norm() > 1e-12 * h.scale) score += w[i] * inward[i].dot(toC.normalized());
  }
  h.outerScore = wsum > 0 ? score / wsum : 0.0;
  h.outerBoundary = h.outerScore > opt.outerScoreThreshold;
}


HoleDetectionResult detectHoles(const TopoDS_Shape& model, const HoleDetectionOptions& opt) {
  if (model.IsNull()) throw Error("the shape is empty: give a shell, an open solid or a compound of faces");
  HoleDetectionResult res;
  TopTools_IndexedMapOfShape edgeMap, faceMap, vertexMap;
  TopExp::MapShapes(model, TopAbs_EDGE, edgeMap);
  TopExp::MapShapes(model, TopAbs_FACE, faceMap);
  if (faceMap.Extent() == 0) throw Error("the shape has no faces: give a shell, an open solid or a compound of faces");

  // Every use of every edge by a face, with the orientation composed down from the model.
  std::vector<std::vector<std::pair<int, TopoDS_Edge>>> uses(edgeMap.Extent() + 1);
  std::vector<TopoDS_Face> faceUse(faceMap.Extent() + 1);
  for (TopExp_Explorer fx(model, TopAbs_FACE); fx.More(); fx.Next()) {
    const TopoDS_Face f = TopoDS::Face(fx.Current());
    const int fi = faceMap.FindIndex(f);
    if (!faceUse[fi].IsNull()) continue;  // a face shared twice in a compound: count it once
    faceUse[fi] = f;
    for (TopExp_Explorer ex(f, TopAbs_EDGE); ex.More(); ex.Next())
      uses[edgeMap.FindIndex(ex.Current())].emplace_back(fi, TopoDS::Edge(ex.Current()));
  }

  std::vector<FreeEdge> free;
  for (int i = 1; i <= edgeMap.Extent(); ++i) {
    if (uses[i].size() > 2) res.nonManifoldEdges.push_back(i);
    if (uses[i].size() != 1 || BRep_Tool::Degenerated(TopoDS::Edge(edgeMap(i)))) continue;
    FreeEdge fe;
    fe.edge = TopoDS::Edge(uses[i][0].second.Reversed());
    fe.edgeIndex = i;
    fe.faceIndex = uses[i][0].first;
    fe.face = faceUse[fe.faceIndex];
    const TopoDS_Vertex a = TopExp::FirstVertex(fe.edge, Standard_True), b = TopExp::LastVertex(fe.edge, Standard_True);
    if (a.IsNull() || b.IsNull()) {
      res.warnings.push_back("Edge" + std::to_string(i) + " has no vertices and was skipped");
      continue;
    }
    fe.v0 = vertexMap.Add(a);
    fe.v1 = vertexMap.Add(b);
    free.push_back(fe);
  }
  if (!res.nonManifoldEdges.empty()) {
    std::string list;
    for (int e : res.nonManifoldEdges) list += (list.empty() ? "Edge" : ", Edge") + std::to_string(e);
    res.warnings.push_back("non-manifold edges (used by more than two faces) were left out: " + list);
  }

  std::vector<std::vector<int>> outgoing(vertexMap.Extent() + 1);
  for (size_t i = 0; i < free.size(); ++i) outgoing[free[i].v0].push_back(static_cast<int>(i));
  std::vector<bool> used(free.size(), false);

  for (size_t s = 0; s < free.size(); ++s) {
    if (used[s]) continue;
    std::vector<int> loop{static_cast<int>(s)};
    used[s] = true;
    bool closed = false;
    while (true) {
      const FreeEdge& cur = free[loop.back()];
      const int v = cur.v1;
      std::vector<int> cand;
      for (int o : outgoing[v])
        if (!used[o]) cand.push_back(o);
      const bool canClose = v == free[s].v0;
      if (cand.empty()) { closed = canClose; break; }
      int best = -1;
      if (cand.size() > 1 || canClose) {
        // Several ways on: take the leftmost turn about the support normal.
        const Eigen::Vector3d tin = edgeTangent(cur.edge, true);
        Eigen::Vector3d n;
        if (!supportNormal(cur.edge, cur.face, parameterAt(cur.edge, true), n)) n = Eigen::Vector3d::Zero();
        double bestTurn = -1e9;
        if (canClose) bestTurn = signedTurn(tin, edgeTangent(free[s].edge, false), n);
        for (int o : cand) {
          const double turn = signedTurn(tin, edgeTangent(free[o].edge, false), n);
          if (turn > bestTurn + 1e-9) { bestTurn = turn; best = o; }
        }
        if (best < 0) { closed = true; break; }
      } else {
        best = cand[0];
      }
      used[best] = true;
      loop.push_back(best);
    }
    std::string names;
    for (int i : loop) names += (names.empty() ? "Edge" : ", Edge") + std::to_string(free[i].edgeIndex);
    if (!closed) {
      res.warnings.push_back("free boundary chain does not close (" + names + "): not a hole");
      continue;
    }
    Hole h;
    for (int i : loop) {
      HoleEdge he;
      he.edge = free[i].edge;
      he.edgeIndex = free[i].edgeIndex;
      he.support = free[i].face;
      he.supportIndex = free[i].faceIndex;
      h.edges.push_back(he);
    }
    finishHole(h, opt);
    if (h.outerBoundary) res.outerBoundaries.push_back(h);
    if (!h.outerBoundary || opt.includeOuterBoundary) res.holes.push_back(h);
  }
  return res;
}

const Hole& holeContainingEdges(const HoleDetectionResult& det, const std::vector<int>& idx) {
  HF_CHECK(!idx.empty(), "no edges given to name the hole");
  auto search = [&](const std::vector<Hole>& list) -> const Hole* {
    for (const Hole& h : list) {
      const std::vector<int> mine = h.edgeIndices();
      const std::set<int> s(mine.begin(), mine.end());
      bool all = true;
      for (int e : idx) all = all && s.count(e);
      if (all) return &h;
    }
    return nullptr;
  };
  if (const Hole* h = search(det.holes)) return *h;
  if (const Hole* h = search(det.outerBoundaries)) return *h;
  std::string names;
  for (int e : idx) names += (names.empty() ? "Edge" : ", Edge") + std::to_string(e);
  // Said in any door's words: a GUI user has no 'holes' command to run.
  if (det.holes.empty() && det.outerBoundaries.empty())
    throw Error(names + " is on no hole: the shape is closed (every edge joins two faces); remove a face to open a hole, "
                "or pick a shape that has one");
  throw Error("no hole loop contains " + names + ": pick edges of one free boundary (edges that border one face only)");
}

}  // namespace holefill
