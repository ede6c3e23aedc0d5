#include "fill/adjacent_holes.h"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Curve.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <algorithm>

#include "brep/boundary_sampling.h"
#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "geometry/occt_bridge.h"

namespace holefill {

namespace {

constexpr double kEndReach = 1e-4;  // of the hole's scale: how far the divider may end from a loop vertex
constexpr int kRibbonPoints = 65;   // samples of the divider the guide surface interpolates
constexpr double kRibbonHalfWidth = 0.05;  // of the hole's scale: the strip's reach to either side of the divider

// The neighbour the first side lacks across the divider D: a ruled strip that contains D,
// R(t, s) = D(t) + s b(t), whose unit normal n(t) blends the model's normals at D's two ends
// (the loop's supports there), made perpendicular to D's tangent T, and b = n x T. The first
// side is asked only G0 along D, so the strip decides no shape; it gives the sampler, the
// parameterizers and the report the normals a support face has. Rows of poles interpolate at
// D's own parameters, so D's pcurve is the line w = 1/2.
TopoDS_Face ribbonAlong(TopoDS_Edge& D, const Handle(Geom_Curve)& C, double f, double l, const Eigen::Vector3d& n0,
                        const Eigen::Vector3d& n1, double scale) {
  const double h = kRibbonHalfWidth * scale;
  TColgp_Array1OfPnt rows[3] = {TColgp_Array1OfPnt(1, kRibbonPoints), TColgp_Array1OfPnt(1, kRibbonPoints),
                                TColgp_Array1OfPnt(1, kRibbonPoints)};
  Handle(TColStd_HArray1OfReal) T = new TColStd_HArray1OfReal(1, kRibbonPoints);
  for (int i = 0; i < kRibbonPoints; ++i) {
    const double w = static_cast<double>(i) / (kRibbonPoints - 1), t = f + (l - f) * w;
    gp_Pnt p;
    gp_Vec d1;
    C->D1(t, p, d1);
    if (d1.Magnitude() < 1e-12) throw Error("the dividing curve has a singular point (zero tangent)");
    const Eigen::Vector3d tan = toEigen(d1).normalized();
    Eigen::Vector3d n = (1 - w) * n0 + w * n1;
    n -= n.dot(tan) * tan;
    if (n.norm() < 1e-9) throw Error("the dividing curve runs along the model's normal: it does not lie across the hole");
    const Eigen::Vector3d b = n.normalized().cross(tan), a = toEigen(p);
    rows[0].SetValue(i + 1, toPnt(a - h * b));
    rows[1].SetValue(i + 1, p);
    rows[2].SetValue(i + 1, toPnt(a + h * b));
    T->SetValue(i + 1, t);
  }
  Handle(Geom_BSplineCurve) curves[3];
  for (int r = 0; r < 3; ++r) {
    Handle(TColgp_HArray1OfPnt) P = new TColgp_HArray1OfPnt(rows[r]);
    GeomAPI_Interpolate interp(P, T, Standard_False, 1e-12);
    interp.Perform();
    if (!interp.IsDone()) throw Error("could not build the guide surface along the dividing curve");
    curves[r] = interp.Curve();
  }
  // Same parameters, same degree: the three rows share their knots.
  const Handle(Geom_BSplineCurve)& c0 = curves[0];
  TColgp_Array2OfPnt poles(1, c0->NbPoles(), 1, 3);
  for (int r = 0; r < 3; ++r)
    for (int i = 1; i <= c0->NbPoles(); ++i) poles.SetValue(i, r + 1, curves[r]->Pole(i));
  TColStd_Array1OfReal vk(1, 2);
  TColStd_Array1OfInteger vm(1, 2);
  vk.SetValue(1, 0.0);
  vk.SetValue(2, 1.0);
  vm.SetValue(1, 3);
  vm.SetValue(2, 3);
  Handle(Geom_BSplineSurface) R =
      new Geom_BSplineSurface(poles, c0->Knots(), vk, c0->Multiplicities(), vm, c0->Degree(), 2);
  BRep_Builder B;
  TopoDS_Face face;
  B.MakeFace(face, R, Precision::Confusion());
  B.UpdateEdge(D, new Geom2d_Line(gp_Pnt2d(0.0, 0.5), gp_Dir2d(1.0, 0.0)), face, Precision::Confusion());
  return face;
}

void renameEdge(HoleFillResult& r, int from, int to) {
  auto swap = [&](int& e) { if (e == from) e = to; };
  for (auto& e : r.hole.edges) swap(e.edgeIndex);
  for (auto& q : r.edgeRequests) swap(q.edgeIndex);
  for (auto& e : r.report.edges) swap(e.edgeIndex);
  for (auto& s : r.report.along) swap(s.edgeIndex);
  for (int& e : r.faultyEdges) swap(e);
}

int rank(FillStatus s) {
  switch (s) {
    case FillStatus::Ok: return 0;
    case FillStatus::ToleranceNotMet: return 1;
    case FillStatus::Cancelled: return 2;
    case FillStatus::Failed: return 3;
  }
  return 3;
}

}  // namespace

AdjacentFillResult fillAdjacentHoles(const TopoDS_Shape& model, const std::vector<int>& holeEdges,
                                     const TopoDS_Edge& divider, const HoleFillOptions& opt) {
  if (model.IsNull()) throw Error("the shape is empty: nothing to fill");
  if (divider.IsNull()) throw Error("no dividing curve given");
  AdjacentFillResult res;
  double f = 0, l = 0;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(divider, f, l);
  if (curve.IsNull()) throw Error("the dividing curve has no 3D curve");

  // The loop on a private copy, and where the divider meets it.
  const TopoDS_Shape work = BRepBuilderAPI_Copy(model, Standard_True, Standard_False).Shape();
  const Hole loop = holeContainingEdges(detectHoles(work, opt.detection), holeEdges);
  const size_t n = loop.edges.size();
  auto nearestStart = [&](const gp_Pnt& p, double& d) {
    int best = -1;
    d = 1e300;
    for (size_t k = 0; k < n; ++k) {
      const double dk = BRep_Tool::Pnt(TopExp::FirstVertex(loop.edges[k].edge, Standard_True)).Distance(p);
      if (dk < d) { d = dk; best = static_cast<int>(k); }
    }
    return best;
  };
  double d0 = 0, d1 = 0;
  const int i0 = nearestStart(curve->Value(f), d0), i1 = nearestStart(curve->Value(l), d1);
  if (std::max(d0, d1) > kEndReach * loop.scale)
    throw Error("the dividing curve must end at two vertices of the hole's loop: its ends lie " +
                std::to_string(d0 / loop.scale) + " and " + std::to_string(d1 / loop.scale) +
                " of the hole's scale from the nearest ones (at most " + std::to_string(kEndReach) + ")");
  if (i0 == i1) throw Error("the dividing curve starts and ends at the same vertex of the loop: it does not split the hole");

  // The shared edge: the divider's curve between the loop's own vertices.
  BRep_Builder B;
  TopoDS_Edge D;
  B.MakeEdge(D, Handle(Geom_Curve)::DownCast(curve->Copy()), Precision::Confusion());
  TopoDS_Vertex va = TopExp::FirstVertex(loop.edges[i0].edge, Standard_True);
  TopoDS_Vertex vb = TopExp::FirstVertex(loop.edges[i1].edge, Standard_True);
  B.Add(D, va.Oriented(TopAbs_FORWARD));
  B.Add(D, vb.Oriented(TopAbs_REVERSED));
  B.Range(D, f, l);
  B.UpdateVertex(va, f, D, std::max(BRep_Tool::Tolerance(va), 1.01 * d0));
  B.UpdateVertex(vb, l, D, std::max(BRep_Tool::Tolerance(vb), 1.01 * d1));
  res.shared = D;

  // D runs from the start of edge i0 to the start of edge i1: the first side is the chain
  // i0..i1-1 closed by D reversed, the second the chain i1..i0-1 closed by D.
  Hole first, second;
  for (size_t k = static_cast<size_t>(i0); k != static_cast<size_t>(i1); k = (k + 1) % n) first.edges.push_back(loop.edges[k]);
  for (size_t k = static_cast<size_t>(i1); k != static_cast<size_t>(i0); k = (k + 1) % n) second.edges.push_back(loop.edges[k]);

  auto stageProgress = [&](double a, double b) {
    HoleFillOptions o = opt;
    if (opt.progress) o.progress = [&, a, b](double x) { return opt.progress(a + (b - a) * x); };
    return o;
  };
  auto finish = [&](const std::string& why, FillStatus status) {
    res.message = why;
    res.status = status;
    return res;
  };

  // 1. The strip standing in for the first side's missing neighbour across D.
  auto normalAtStart = [&](const HoleEdge& he) {
    Eigen::Vector3d n;
    const TopoDS_Vertex v = TopExp::FirstVertex(he.edge, Standard_True);
    if (!supportNormal(he.edge, he.support, BRep_Tool::Parameter(v, he.edge), n))
      throw Error("the model has no normal at a vertex where the dividing curve ends (Edge" + std::to_string(he.edgeIndex) + ")");
    return n;
  };
  TopoDS_Face guide;
  try {
    guide = ribbonAlong(D, curve, f, l, normalAtStart(loop.edges[i0]), normalAtStart(loop.edges[i1]), loop.scale);
  } catch (const Standard_Failure& e) {
    throw Error(std::string("could not build the strip along the dividing curve: ") + e.GetMessageString());
  }
  HoleEdge across;
  across.edge = TopoDS::Edge(D.Reversed());
  across.edgeIndex = 0;
  across.support = guide;
  across.supportIndex = 0;  // not a face of the model
  first.edges.push_back(across);
  finishHole(first, opt.detection);

  // 2. The first side, G0 along D (the second side makes the pair meet), sewn into the copy;
  // then D drops its pcurve on the strip, which is no face of the result.
  HoleFillOptions fo = stageProgress(0.0, 0.5);
  fo.edgeContinuity[0] = Continuity::G0;
  res.first = fillHoleOf(work, first, fo);
  B.UpdateEdge(D, Handle(Geom2d_Curve)(), guide, Precision::Confusion());
  if (res.first.status == FillStatus::Cancelled) return finish("cancelled by the user", FillStatus::Cancelled);
  if (res.first.status == FillStatus::Failed || res.first.shape.IsNull())
    return finish("the first side's fill failed: " + res.first.message, FillStatus::Failed);

  // 3. The second side: a hole of the model with the first face in it, D's neighbour being that face.
  {
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(res.first.shape, TopAbs_EDGE, edges);
    std::vector<int> names{edges.FindIndex(D)};
    const HoleDetectionResult det = detectHoles(res.first.shape, opt.detection);
    const Hole& h = holeContainingEdges(det, names);
    if (h.edges.size() != second.edges.size() + 1)
      return finish("the second side's loop was not found next to the first face (" + std::to_string(h.edges.size()) +
                    " edges, " + std::to_string(second.edges.size() + 1) + " expected)", FillStatus::Failed);
    res.second = fillHoleOf(res.first.shape, h, stageProgress(0.5, 1.0));
  }
  if (res.second.status == FillStatus::Cancelled) return finish("cancelled by the user", FillStatus::Cancelled);
  if (res.second.status == FillStatus::Failed || res.second.shape.IsNull())
    return finish("the second side's fill failed: " + res.second.message, FillStatus::Failed);

  res.shape = res.second.shape;
  TopTools_IndexedMapOfShape edges, faces;
  TopExp::MapShapes(res.shape, TopAbs_EDGE, edges);
  TopExp::MapShapes(res.shape, TopAbs_FACE, faces);
  res.sharedEdgeIndex = edges.FindIndex(D);
  renameEdge(res.first, 0, res.sharedEdgeIndex);
  res.across = faceContinuity(res.shape, faces.FindIndex(res.first.face), faces.FindIndex(res.second.face));
  res.shapeValid = res.first.shapeValid && res.second.shapeValid;
  res.status = rank(res.first.status) > rank(res.second.status) ? res.first.status : res.second.status;
  char buf[200];
  std::snprintf(buf, sizeof buf, "two faces sharing Edge%d: G0 %.3g, G1 %.3g rad, G2 %.3g across it", res.sharedEdgeIndex,
                res.across.g0, res.across.g1, res.across.g2);
  res.message = std::string(buf) + "; first side " + res.first.message + "; second side " + res.second.message;
  return res;
}

Outcome outcome(const AdjacentFillResult& r) {
  const Outcome a = outcome(r.first), b = outcome(r.second);
  Outcome o = exitCode(a) == 2 || (exitCode(a) == 3 && exitCode(b) == 0) ? a : b;
  o.status = toStatus(r.status);
  o.message = r.message;
  o.warnings = r.first.warnings;
  o.warnings.insert(o.warnings.end(), r.second.warnings.begin(), r.second.warnings.end());
  return o;
}

std::string toJson(const AdjacentFillResult& r) {
  JsonWriter j;
  j.beginObject();
  j.field("status", toString(r.status)).field("message", r.message).field("shared_edge", r.sharedEdgeIndex);
  j.field("shape_valid", r.shapeValid);
  j.key("across").beginObject();
  if (r.across.samples > 0) writeJsonFields(j, r.across);
  j.endObject();
  j.key("fills").beginArray().raw(toJson(r.first)).raw(toJson(r.second)).endArray();
  j.endObject();
  return j.str();
}

}  // namespace holefill
