#include "brep/continuity_report.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <Extrema_ExtPC.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "brep/boundary_sampling.h"
#include "brep/edge_continuity.h"
#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "geometry/occt_bridge.h"
#include "geometry/tolerances.h"

namespace holefill {

std::string ContinuityReport::achieved(double t0, double t1, double t2) const {
  if (!(g0 <= t0)) return "none";
  if (!(g1 <= t1)) return "G0";
  if (!(g2 <= t2)) return "G1";
  return "G2";
}

void writeJsonFields(JsonWriter& j, const ContinuityReport& r) {
  j.field("scale", r.scale).field("samples", r.samples);
  j.field("g0", r.g0).field("g0_relative", r.g0Relative).field("g1", r.g1).field("g2", r.g2);
  j.field("g0_face", r.g0Face).field("g0_face_relative", r.g0FaceRelative).field("edge_tolerance", r.edgeTolerance);
  j.key("str").beginObject();
  j.field("g0_strict", r.g0Strict).field("g0_loose", r.g0Loose).field("g1_strict", r.g1Strict);
  j.field("g1_loose", r.g1Loose).field("g2", r.g2Ok);
  j.endObject();
  j.key("per_edge").beginArray();
  for (const auto& e : r.edges)
    j.beginObject().field("edge", e.edgeIndex).field("g0", e.g0).field("g1", e.g1).field("g2", e.g2)
        .field("g0_face", e.g0Face).field("tolerance", e.tolerance).field("tolerance_before", e.toleranceBefore)
        .field("g1_floor", e.g1Floor).endObject();
  j.endArray();
}

ContinuityReport continuityReport(const TopoDS_Face& face, const Hole& hole, const ContinuityOptions& opt) {
  HF_CHECK(!face.IsNull(), "no face to report on");
  ContinuityReport r;
  r.scale = hole.scale;
  for (const auto& he : hole.edges) {
    const double tol = BRep_Tool::Tolerance(he.edge);
    r.edges.push_back({he.edgeIndex, 0, 0, 0, 0, tol, he.tolerance, 0});
    r.edgeTolerance = std::max(r.edgeTolerance, tol);
  }
  std::vector<BRepAdaptor_Curve> curves;
  std::vector<SupportView> supports;
  for (const auto& he : hole.edges) {
    curves.emplace_back(he.edge);
    supports.emplace_back(he.edge, he.support);
  }
  BRepAdaptor_Surface fs(face, Standard_False);
  const bool frev = face.Orientation() == TopAbs_REVERSED;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge E = TopoDS::Edge(ex.Current());
    if (BRep_Tool::Degenerated(E)) continue;
    BRepAdaptor_Curve2d pc(E, face);
    const double a = pc.FirstParameter(), b = pc.LastParameter();
    // A face that shares the hole's edge (our fills do) is compared at the same curve parameter.
    int shared = -1;
    for (size_t k = 0; k < hole.edges.size(); ++k)
      if (hole.edges[k].edge.IsSame(E)) shared = static_cast<int>(k);
    if (shared < 0 && opt.sharedEdgesOnly) continue;
    for (int i = 0; i <= opt.samplesPerEdge; ++i) {
      const double t = a + (b - a) * i / opt.samplesPerEdge;
      const gp_Pnt2d uv = pc.Value(t);
      const SurfaceJet jf = faceJet(fs, frev, uv.X(), uv.Y());
      // Nearest point of the hole boundary.
      int best = shared;
      double bestD = shared >= 0 ? curves[shared].Value(t).SquareDistance(toPnt(jf.p)) : 1e300, bestT = t;
      for (size_t k = 0; k < curves.size() && shared < 0; ++k) {
        Extrema_ExtPC ext(toPnt(jf.p), curves[k]);
        if (ext.IsDone())
          for (int m = 1; m <= ext.NbExt(); ++m)
            if (ext.SquareDistance(m) < bestD) { bestD = ext.SquareDistance(m); best = int(k); bestT = ext.Point(m).Parameter(); }
        for (double te : {curves[k].FirstParameter(), curves[k].LastParameter()}) {
          const double d = curves[k].Value(te).SquareDistance(toPnt(jf.p));
          if (d < bestD) { bestD = d; best = int(k); bestT = te; }
        }
      }
      if (best < 0) continue;
      const double g0 = std::sqrt(bestD);
      double g1 = 0, g2 = 0;
      const gp_Pnt2d uvB = supports[best].pcurve.Value(bestT);
      const double g0f = (toEigen(supports[best].surface.Value(uvB.X(), uvB.Y())) - jf.p).norm();
      Eigen::Vector3d nf, nb;
      SurfaceJet jb;
      ContinuitySample sample{jf.p, hole.edges[best].edgeIndex};
      if (supports[best].regularJet(bestT, jb, nb) && unitNormal(jf, nf)) {
        g1 = std::acos(std::min(1.0, std::abs(nf.dot(nb))));
        gp_Pnt p;
        gp_Vec d1;
        curves[best].D1(bestT, p, d1);
        if (d1.Magnitude() > 1e-12) {
          const Eigen::Vector3d T = toEigen(d1).normalized();
          r.edges[best].g1Floor = std::max(r.edges[best].g1Floor, std::asin(std::min(1.0, std::abs(nb.dot(T)))));
          const Eigen::Vector3d acrossB = nb.cross(T).normalized();
          const Eigen::Vector3d nfa = nf.dot(nb) < 0 ? Eigen::Vector3d(-nf) : nf;
          const Eigen::Vector3d acrossF = nfa.cross(T).normalized();
          const double kb = normalCurvature(jb, nb, acrossB), kf = normalCurvature(jf, nfa, acrossF);
          g2 = std::abs(kf - kb) / std::max(std::abs(kb), 1.0 / std::max(r.scale, 1e-300));
          sample.normal = nfa;
          sample.curvatureFace = kf;
          sample.curvatureSupport = kb;
        }
      } else {
        g1 = M_PI / 2;  // singular normal on one side: no tangent plane to agree on
      }
      ++r.samples;
      sample.g0 = g0, sample.g1 = g1, sample.g2 = g2;
      r.along.push_back(sample);
      r.g0 = std::max(r.g0, g0);
      r.g0Face = std::max(r.g0Face, g0f);
      r.g1 = std::max(r.g1, g1);
      r.g2 = std::max(r.g2, g2);
      auto& ec = r.edges[best];
      ec.g0 = std::max(ec.g0, g0);
      ec.g0Face = std::max(ec.g0Face, g0f);
      ec.g1 = std::max(ec.g1, g1);
      ec.g2 = std::max(ec.g2, g2);
    }
  }
  if (r.samples == 0) throw Error("the face has no boundary edges to compare with the hole");
  // At a corner the two edge curves pin the tangent plane of any surface through them (its normal
  // is their tangents' cross product): a neighbour whose normal is tilted off that plane is a G1
  // floor there that no such surface beats, as an inexact curve is along the edge (hammer's
  // strips: 2.8e-3 rad at their corners, where every fill missed G1 by that much and no more).
  const std::vector<double> corner = cornerMismatch(hole);
  for (size_t k = 0; k < r.edges.size() && k < corner.size(); ++k)
    if (corner[k] > 0) r.edges[k].g1Floor = std::max(r.edges[k].g1Floor, corner[k]);
  r.g0Relative = r.scale > 0 ? r.g0 / r.scale : r.g0;
  r.g0FaceRelative = r.scale > 0 ? r.g0Face / r.scale : r.g0Face;
  r.g0Strict = r.g0Relative <= tol::kG0Strict;
  r.g0Loose = r.g0Relative <= tol::kG0Loose;
  r.g1Strict = r.g1 <= tol::kG1Strict;
  r.g1Loose = r.g1 <= tol::kG1Loose;
  r.g2Ok = r.g2 <= tol::kG2Tier;
  return r;
}

ContinuityReport faceContinuity(const TopoDS_Shape& model, int a, int b, const ContinuityOptions& options) {
  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(model, TopAbs_FACE, faces);
  TopExp::MapShapes(model, TopAbs_EDGE, edges);
  for (int k : {a, b})
    if (k < 1 || k > faces.Extent())
      throw Error("face " + std::to_string(k) + " does not exist: the shape has " + std::to_string(faces.Extent()) + " faces");
  if (a == b) throw Error("select two different faces");
  const TopoDS_Face fa = TopoDS::Face(faces(a)), fb = TopoDS::Face(faces(b));
  TopTools_IndexedMapOfShape edgesOfA;
  TopExp::MapShapes(fa, TopAbs_EDGE, edgesOfA);
  Hole hole;
  Bnd_Box box;
  for (TopExp_Explorer ex(fb, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge e = TopoDS::Edge(ex.Current());
    if (BRep_Tool::Degenerated(e) || !edgesOfA.Contains(e)) continue;
    bool seen = false;
    for (const auto& he : hole.edges) seen = seen || he.edge.IsSame(e);
    if (seen) continue;
    HoleEdge he;
    he.edge = e;
    he.edgeIndex = edges.FindIndex(e);
    he.support = fa;
    he.supportIndex = a;
    he.tolerance = BRep_Tool::Tolerance(e);
    hole.edges.push_back(he);
    BRepBndLib::Add(e, box);
  }
  if (hole.edges.empty())
    throw Error("faces " + std::to_string(a) + " and " + std::to_string(b) + " share no edge: select two adjacent faces");
  hole.scale = std::sqrt(box.SquareExtent());
  ContinuityOptions o = options;
  o.sharedEdgesOnly = true;
  return continuityReport(fb, hole, o);
}

}  // namespace holefill
