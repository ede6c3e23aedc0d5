#include "brep/face_building.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <Bnd_Box.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <gp_Lin.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_TEdge.hxx>
#include <BRep_TVertex.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <map>
#include <memory>

#include "geometry/error.h"
#include "geometry/occt_bridge.h"

namespace holefill {

FaceBuildResult buildTrimmedFace(const Hole& hole, const Handle(Geom_BSplineSurface)& surface,
                                 const std::vector<BoundarySample>& samples, const std::vector<Eigen::Vector2d>& uv) {
  HF_CHECK(samples.size() == uv.size(), "one pcurve point per boundary sample");
  BRep_Builder B;
  FaceBuildResult res;
  B.MakeFace(res.face, surface, Precision::Confusion());
  TopoDS_Wire wire;
  B.MakeWire(wire);
  for (size_t k = 0; k < hole.edges.size(); ++k) {
    const TopoDS_Edge& E = hole.edges[k].edge;
    std::vector<std::pair<double, Eigen::Vector2d>> pts;
    for (size_t i = 0; i < samples.size(); ++i)
      if (samples[i].edge == static_cast<int>(k)) pts.emplace_back(samples[i].t, uv[i]);
    std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    HF_CHECK(pts.size() >= 2, "an edge of the hole has fewer than two samples");
    Handle(TColgp_HArray1OfPnt2d) P = new TColgp_HArray1OfPnt2d(1, static_cast<int>(pts.size()));
    Handle(TColStd_HArray1OfReal) T = new TColStd_HArray1OfReal(1, static_cast<int>(pts.size()));
    for (size_t i = 0; i < pts.size(); ++i) {
      P->SetValue(static_cast<int>(i) + 1, gp_Pnt2d(pts[i].second.x(), pts[i].second.y()));
      T->SetValue(static_cast<int>(i) + 1, pts[i].first);
    }
    Geom2dAPI_Interpolate interp(P, T, Standard_False, 1e-12);
    interp.Perform();
    if (!interp.IsDone()) throw Error("could not build the pcurve of Edge" + std::to_string(hole.edges[k].edgeIndex));
    Handle(Geom2d_BSplineCurve) pc = interp.Curve();
    // Measure the gap between the edge's curve and its new curve on surface.
    BRepAdaptor_Curve c(E);
    double dev = 0.0;
    const int checks = 4 * static_cast<int>(pts.size());
    for (int i = 0; i <= checks; ++i) {
      const double t = c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / checks;
      const gp_Pnt2d q = pc->Value(t);
      dev = std::max(dev, c.Value(t).Distance(surface->Value(q.X(), q.Y())));
    }
    res.maxEdgeDeviation = std::max(res.maxEdgeDeviation, dev);
    const double tol = std::max(BRep_Tool::Tolerance(E), 1.5 * dev + Precision::Confusion());
    res.priorEdgeTolerances.push_back(BRep_Tool::Tolerance(E));
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(E, v0, v1);
    for (const TopoDS_Vertex& v : {v0, v1})
      if (!v.IsNull()) res.priorVertexTolerances.emplace_back(v, BRep_Tool::Tolerance(v));
    res.pcurves.push_back(pc);
    res.edgeTolerances.push_back(tol);
    B.Add(wire, E);
  }
  wire.Closed(Standard_True);
  B.Add(res.face, wire);
  attachFace(hole, res);
  return res;
}

void attachFace(const Hole& hole, const FaceBuildResult& built) {
  HF_CHECK(built.pcurves.size() == hole.edges.size(), "a built face has one pcurve per hole edge");
  BRep_Builder B;
  for (size_t k = 0; k < hole.edges.size(); ++k) {
    const TopoDS_Edge& E = hole.edges[k].edge;
    const double tol = built.edgeTolerances[k];
    B.UpdateEdge(E, built.pcurves[k], built.face, tol);
    if (BRep_Tool::Tolerance(E) < tol) B.UpdateEdge(E, tol);
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(E, v0, v1);
    for (const TopoDS_Vertex& v : {v0, v1})
      if (!v.IsNull() && BRep_Tool::Tolerance(v) < tol) B.UpdateVertex(v, tol);
  }
}

void detachFace(const Hole& hole, const FaceBuildResult& built) {
  HF_CHECK(built.pcurves.size() == hole.edges.size(), "a built face has one pcurve per hole edge");
  // BRep_Builder only ever raises tolerances; the TShapes take the old values back directly.
  BRep_Builder B;
  for (size_t k = 0; k < hole.edges.size(); ++k) {
    const TopoDS_Edge& E = hole.edges[k].edge;
    B.UpdateEdge(E, Handle(Geom2d_Curve)(), built.face, Precision::Confusion());
    Handle(BRep_TEdge)::DownCast(E.TShape())->Tolerance(built.priorEdgeTolerances[k]);
  }
  for (const auto& [v, t] : built.priorVertexTolerances) Handle(BRep_TVertex)::DownCast(v.TShape())->Tolerance(t);
}

namespace {

// Whether the closed shell is oriented outward, by rays: from a point inside each of the given
// faces (the new face's neighbours first, then the shell's other faces: original faces, whose
// geometry is trusted) along its oriented normal. A ray that leaves without meeting any face of the
// shell, the new one included, shows that the normal points out; three such rays must be found.
// A ray that meets the shell again proves nothing on its own (a missed or grazing crossing would
// flip its parity): it is passed over, and so is a face no ray could be cast from. Only faces whose
// bounding box the ray's line meets are intersected, so this costs a few faces' intersectors
// instead of a classifier over the whole model (BRepLib::OrientClosedSolid took 100 ms of a 130 ms
// fill on a 1.5 MB model). No answer (false) after kMaxRays rays. Rays from the new face itself
// were tried first and were fooled by a fill that overlaps itself.
bool raysLeaveOutward(const TopoDS_Shell& shell, const std::vector<TopoDS_Face>& neighbours, const TopoDS_Face& added) {
  constexpr int kMaxRays = 24;  // a pocket's faces all look into the part; faces elsewhere escape
  std::vector<std::pair<TopoDS_Face, Bnd_Box>> boxes;
  for (TopExp_Explorer ex(shell, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopoDS_Face f = TopoDS::Face(ex.Current());
    Bnd_Box b;
    BRepBndLib::Add(f, b, Standard_False);
    boxes.emplace_back(f, b);
  }
  std::map<size_t, std::unique_ptr<IntCurvesFace_Intersector>> intersectors;  // built once per face met
  // A ray from a point inside `face` along its oriented normal: true when it leaves the shell;
  // false when it meets it again, an intersection failed, or no point of a 5x5 grid of the face's
  // parameter bounds (centre first) is inside the face with a regular normal.
  const double grid[5] = {0.5, 0.3, 0.7, 0.15, 0.85};
  auto rayLeaves = [&](const TopoDS_Face& face) {
    BRepAdaptor_Surface S(face);
    const double u0 = S.FirstUParameter(), u1 = S.LastUParameter(), v0 = S.FirstVParameter(), v1 = S.LastVParameter();
    const double tol = BRep_Tool::Tolerance(face);
    // One polygonal classifier per face: BRepClass_FaceClassifier intersects every pcurve again
    // for each of the up to 25 points (8 of the 13 ms this took on a 1.5 MB model).
    const BRepTopAdaptor_FClass2d inside(face, tol);
    for (double a : grid)
      for (double b : grid) {
        const gp_Pnt2d uv(u0 + a * (u1 - u0), v0 + b * (v1 - v0));
        if (inside.Perform(uv) != TopAbs_IN) continue;
        gp_Pnt p;
        gp_Vec du, dv;
        S.D1(uv.X(), uv.Y(), p, du, dv);
        gp_Vec n = du.Crossed(dv);
        if (n.Magnitude() < 1e-12 * (1 + du.Magnitude() * dv.Magnitude())) continue;
        n.Normalize();
        if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
        const gp_Lin ray(p, gp_Dir(n));
        for (size_t k = 0; k < boxes.size(); ++k) {
          if (boxes[k].first.IsSame(face) || boxes[k].second.IsOut(ray)) continue;
          auto& I = intersectors[k];
          if (!I) I = std::make_unique<IntCurvesFace_Intersector>(boxes[k].first, Precision::Confusion());
          I->Perform(ray, 0.0, Precision::Infinite());
          if (!I->IsDone()) return false;
          for (int h = 1; h <= I->NbPnt(); ++h)
            if (I->WParameter(h) > 10 * tol) return false;  // met the shell again
        }
        return true;
      }
    return false;
  };
  std::vector<TopoDS_Face> from = neighbours;
  for (const auto& entry : boxes) {  // not a structured binding: C++17 lambdas cannot capture one (clang)
    const TopoDS_Face& f = entry.first;
    if (!f.IsSame(added) && std::none_of(neighbours.begin(), neighbours.end(), [&](const TopoDS_Face& g) { return g.IsSame(f); }))
      from.push_back(f);
  }
  int escaped = 0, rays = 0;
  for (const TopoDS_Face& face : from) {
    if (++rays > kMaxRays) return false;
    if (rayLeaves(face) && ++escaped == 3) return true;
  }
  return false;
}

// The new face runs along each shared edge opposite to the neighbour on the other side (a
// consistently oriented shell), so the rays' answer about it holds for the whole solid.
bool orientedLikeItsNeighbours(const TopoDS_Face& face, const TopTools_IndexedDataMapOfShapeListOfShape& edgeFaces) {
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
    if (!edgeFaces.Contains(ex.Current())) return false;
    for (const TopoDS_Shape& f : edgeFaces.FindFromKey(ex.Current()))
      for (TopExp_Explorer fx(f, TopAbs_EDGE); fx.More(); fx.Next())
        if (fx.Current().IsSame(ex.Current()) && fx.Current().Orientation() == ex.Current().Orientation()) return false;
  }
  return true;
}

}  // namespace

SewResult sewFace(const TopoDS_Shape& model, const TopoDS_Face& face, bool computeVolume) {
  // The faces connected to the new face through shared edges form its shell.
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(model, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  TopTools_IndexedMapOfShape inShell;
  std::vector<TopoDS_Shape> queue;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
    if (edgeFaces.Contains(ex.Current()))
      for (const TopoDS_Shape& f : edgeFaces.FindFromKey(ex.Current()))
        if (inShell.Add(f) > 0) queue.push_back(f);
  while (!queue.empty()) {
    const TopoDS_Shape f = queue.back();
    queue.pop_back();
    for (TopExp_Explorer ex(f, TopAbs_EDGE); ex.More(); ex.Next())
      for (const TopoDS_Shape& g : edgeFaces.FindFromKey(ex.Current()))
        if (!inShell.Contains(g)) { inShell.Add(g); queue.push_back(g); }
  }
  BRep_Builder B;
  TopoDS_Shell shell;
  B.MakeShell(shell);
  std::vector<TopoDS_Shape> others;
  TopTools_IndexedMapOfShape added;
  for (TopExp_Explorer ex(model, TopAbs_FACE); ex.More(); ex.Next()) {
    if (added.Contains(ex.Current())) continue;
    added.Add(ex.Current());
    if (inShell.Contains(ex.Current())) B.Add(shell, ex.Current());
    else others.push_back(ex.Current());
  }
  B.Add(shell, face);
  // Closed when every edge of the shell is used by exactly two faces (seams count twice).
  TopTools_IndexedDataMapOfShapeListOfShape shellEdges;
  TopExp::MapShapesAndAncestors(shell, TopAbs_EDGE, TopAbs_FACE, shellEdges);
  bool closed = true;
  for (int i = 1; i <= shellEdges.Extent() && closed; ++i)
    closed = BRep_Tool::Degenerated(TopoDS::Edge(shellEdges.FindKey(i))) || shellEdges(i).Extent() == 2;
  shell.Closed(closed);
  SewResult res;
  TopoDS_Shape main = shell;
  if (closed) {
    BRepBuilderAPI_MakeSolid ms(shell);
    if (ms.IsDone()) {
      TopoDS_Solid solid = ms.Solid();
      // The shell keeps the model's face orientations and the new face is oriented with them
      // (it reuses the loop's edges): only the whole solid may need turning inside out, which it
      // need not when rays from the neighbours leave it.
      std::vector<TopoDS_Face> neighbours;
      for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
        if (edgeFaces.Contains(ex.Current()))
          for (const TopoDS_Shape& f : edgeFaces.FindFromKey(ex.Current()))
            if (std::none_of(neighbours.begin(), neighbours.end(), [&](const TopoDS_Face& g) { return g.IsSame(f); }))
              neighbours.push_back(TopoDS::Face(f));
      if (!orientedLikeItsNeighbours(face, edgeFaces) || !raysLeaveOutward(shell, neighbours, face))
        BRepLib::OrientClosedSolid(solid);
      if (computeVolume) {
        GProp_GProps props;
        BRepGProp::VolumeProperties(solid, props);
        res.volume = props.Mass();
      }
      res.closedSolid = true;
      main = solid;
    }
  }
  if (others.empty()) {
    res.shape = main;
  } else {
    TopoDS_Compound comp;
    B.MakeCompound(comp);
    B.Add(comp, main);
    for (const auto& o : others) B.Add(comp, o);
    res.shape = comp;
  }
  return res;
}

}  // namespace holefill
