#include "brep/sample_models.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <BRepGProp.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeFix_Face.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <random>

#include "geometry/error.h"

namespace holefill::samples {

namespace {

Handle(Geom_BSplineSurface) bezierSurface(const gp_Pnt (&P)[4][4]) {
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) poles.SetValue(i + 1, j + 1, P[i][j]);
  TColStd_Array1OfReal k(1, 2);
  k.SetValue(1, 0.0);
  k.SetValue(2, 1.0);
  TColStd_Array1OfInteger m(1, 2);
  m.SetValue(1, 4);
  m.SetValue(2, 4);
  return new Geom_BSplineSurface(poles, k, k, m, m, 3, 3);
}

TopoDS_Shape sew(const std::vector<TopoDS_Face>& faces, double tol) {
  BRepBuilderAPI_Sewing sewing(tol);
  for (const auto& f : faces) sewing.Add(f);
  sewing.Perform();
  return sewing.SewedShape();
}

// Closed wire of curved edges on `surface` through the uv corner points; each side bulges by `bulge`.
TopoDS_Wire curvedPolygonWire(const Handle(Geom_Surface)& surface, const std::vector<gp_Pnt2d>& corners,
                              const std::vector<double>& bulge) {
  BRepBuilderAPI_MakeWire mw;
  const size_t n = corners.size();
  std::vector<TopoDS_Vertex> verts;
  for (size_t i = 0; i < n; ++i) {
    const gp_Pnt2d a = corners[i], b = corners[(i + 1) % n];
    const gp_Vec2d d(a, b);
    const gp_Vec2d nrm(-d.Y(), d.X());
    Handle(TColgp_HArray1OfPnt2d) pts = new TColgp_HArray1OfPnt2d(1, 3);
    pts->SetValue(1, a);
    pts->SetValue(2, gp_Pnt2d(0.5 * (a.X() + b.X()) + bulge[i] * nrm.X(), 0.5 * (a.Y() + b.Y()) + bulge[i] * nrm.Y()));
    pts->SetValue(3, b);
    Geom2dAPI_Interpolate ip(pts, Standard_False, 1e-9);
    ip.Perform();
    TopoDS_Edge e = BRepBuilderAPI_MakeEdge(ip.Curve(), surface);
    BRepLib::BuildCurves3d(e, 1e-7, GeomAbs_C2, 14, 200);
    mw.Add(e);
  }
  return mw.Wire();
}

TopoDS_Face faceWithHoles(const Handle(Geom_Surface)& surface, const std::vector<TopoDS_Wire>& holes) {
  BRepBuilderAPI_MakeFace base(surface, 1e-7);
  BRepBuilderAPI_MakeFace mf(base.Face());
  for (const auto& w : holes) mf.Add(w);
  TopoDS_Face f = mf.Face();
  ShapeFix_Face fix(f);
  fix.FixOrientation();
  fix.Perform();
  return TopoDS::Face(fix.Face());
}

Handle(Geom_BSplineSurface) wavyPanel() {
  const int n = 6;
  TColgp_Array2OfPnt poles(1, n, 1, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = 100.0 * i / (n - 1), y = 100.0 * j / (n - 1);
      const double z = 12.0 * std::sin(0.045 * x) * std::cos(0.03 * y) + 0.08 * x + 6.0 * ((i + j) % 2 ? 0.5 : -0.5);
      poles.SetValue(i + 1, j + 1, gp_Pnt(x, y, z));
    }
  TColStd_Array1OfReal k(1, 4);
  TColStd_Array1OfInteger m(1, 4);
  const double kv[4] = {0.0, 0.35, 0.7, 1.0};
  const int mv[4] = {4, 1, 1, 4};
  for (int i = 0; i < 4; ++i) { k.SetValue(i + 1, kv[i]); m.SetValue(i + 1, mv[i]); }
  return new Geom_BSplineSurface(poles, k, k, m, m, 3, 3);
}

std::vector<gp_Pnt2d> irregularPolygon(int sides, double cx, double cy, double r, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.35, 0.35), rad(0.6, 1.15);
  std::vector<gp_Pnt2d> pts;
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * M_PI * (i + jitter(rng)) / sides;
    const double rr = r * rad(rng);
    pts.emplace_back(cx + rr * std::cos(a), cy + rr * std::sin(a));
  }
  return pts;
}

}  // namespace

TopoDS_Shape ccExtraordinaryHole(int N, int R, double bend, double h, double jitter, unsigned seed) {
  HF_CHECK(N >= 3 && N <= 12, "valence must be 3..12");
  HF_CHECK(R >= 3, "at least 3 rings are needed for regular patches around the hole");
  auto vertex = [&](int k, int i, int j) {  // sector k, grid (i, j); (i,-1) and (-1,j) fold into neighbours
    k = ((k % N) + N) % N;
    if (j < 0) return std::make_tuple((k + N - 1) % N, 1, i);
    if (i < 0) return std::make_tuple((k + 1) % N, j, 1);
    return std::make_tuple(k, i, j);
  };
  auto position = [&](int k, int i, int j) {
    const double a0 = 2 * M_PI * k / N, a1 = 2 * M_PI * (k + 1) / N;
    const double x = h * (i * std::cos(a0) + j * std::cos(a1)), y = h * (i * std::sin(a0) + j * std::sin(a1));
    const double s = h * R;
    const double z = bend * (0.35 * s * (x * x - 0.6 * y * y) / (s * s) + 0.15 * x + 0.08 * s * std::sin(2.0 * y / s));
    if (jitter <= 0) return gp_Pnt(x, y, z);
    // Deterministic per-vertex noise keyed by a canonical name of the vertex: (0, j) of sector k
    // is (j, 0) of sector k+1, and the EP belongs to no sector.
    int ck = k, ci = i, cj = j;
    if (i == 0 && j == 0) ck = 0;
    else if (i == 0) { ck = (k + 1) % N; ci = j; cj = 0; }
    std::mt19937 rng(seed * 1000003u + static_cast<unsigned>(ck * 10007 + ci * 101 + cj));
    std::uniform_real_distribution<double> d(-jitter * h, jitter * h);
    const double dx = d(rng), dy = d(rng), dz = d(rng);
    return gp_Pnt(x + 0.5 * dx, y + 0.5 * dy, z + dz);
  };
  static const double Mb[4][4] = {{1, 4, 1, 0}, {0, 4, 2, 0}, {0, 2, 4, 0}, {0, 1, 4, 1}};
  std::vector<TopoDS_Face> faces;
  for (int k = 0; k < N; ++k)
    for (int i = 0; i + 2 <= R; ++i)
      for (int j = 0; j + 2 <= R; ++j) {
        if (i == 0 && j == 0) continue;  // the EP's quad: irregular, this is the hole
        gp_Pnt C[4][4];
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) {
            auto [kk, ii, jj] = vertex(k, i - 1 + a, j - 1 + b);
            C[a][b] = position(kk, ii, jj);
          }
        gp_Pnt Bz[4][4];
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) {
            gp_XYZ s(0, 0, 0);
            for (int c = 0; c < 4; ++c)
              for (int d = 0; d < 4; ++d) s += C[c][d].XYZ() * (Mb[a][c] * Mb[b][d] / 36.0);
            Bz[a][b] = gp_Pnt(s);
          }
        faces.push_back(BRepBuilderAPI_MakeFace(bezierSurface(Bz), 1e-7).Face());
      }
  return sew(faces, 1e-6 * h);
}

namespace {
// A box filleted on all its edges, and the index of the corner blend nearest to (dx, dy, dz)
// (a face that is neither a plane nor a cylinder) among its faces.
TopoDS_Shape filletedBox(double dx, double dy, double dz, double radius, TopTools_IndexedMapOfShape& faces, int& corner) {
  TopoDS_Shape box = BRepPrimAPI_MakeBox(dx, dy, dz).Shape();
  BRepFilletAPI_MakeFillet fillet(box);
  for (TopExp_Explorer ex(box, TopAbs_EDGE); ex.More(); ex.Next()) fillet.Add(radius, TopoDS::Edge(ex.Current()));
  fillet.Build();
  HF_CHECK(fillet.IsDone(), "OCCT could not fillet the box");
  const TopoDS_Shape solid = fillet.Shape();
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  corner = 0;
  double best = -1e300;
  for (int i = 1; i <= faces.Extent(); ++i) {
    GeomAdaptor_Surface gs(BRep_Tool::Surface(TopoDS::Face(faces(i))));
    if (gs.GetType() == GeomAbs_Plane || gs.GetType() == GeomAbs_Cylinder) continue;
    GProp_GProps p;
    BRepGProp::SurfaceProperties(faces(i), p);
    const gp_Pnt c = p.CentreOfMass();
    if (c.X() + c.Y() + c.Z() > best) { best = c.X() + c.Y() + c.Z(); corner = i; }
  }
  HF_CHECK(corner > 0, "the filleted box has no corner blend face");
  return solid;
}

TopoDS_Shape shellWithout(const TopoDS_Shape& solid, const std::vector<TopoDS_Shape>& removed) {
  BRep_Builder B;
  TopoDS_Shell shell;
  B.MakeShell(shell);
  for (TopExp_Explorer ex(solid, TopAbs_FACE); ex.More(); ex.Next())
    if (std::none_of(removed.begin(), removed.end(), [&](const TopoDS_Shape& f) { return f.IsSame(ex.Current()); }))
      B.Add(shell, ex.Current());
  return shell;
}
}  // namespace

TopoDS_Shape filletedBoxCorner(double dx, double dy, double dz, double radius) {
  TopTools_IndexedMapOfShape faces;
  int corner = 0;
  const TopoDS_Shape solid = filletedBox(dx, dy, dz, radius, faces, corner);
  return shellWithout(solid, {faces(corner)});
}

TopoDS_Shape filletedBoxAdjacentHoles(TopoDS_Edge* divider) {
  TopTools_IndexedMapOfShape faces;
  int corner = 0;
  const TopoDS_Shape solid = filletedBox(100, 80, 60, 12, faces, corner);
  // The cylindrical fillet that shares an edge with the corner blend and runs along x (the longest).
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  TopoDS_Shape fillet;
  TopoDS_Edge shared;
  double longest = -1;
  for (TopExp_Explorer ex(faces(corner), TopAbs_EDGE); ex.More(); ex.Next())
    for (const TopoDS_Shape& f : edgeFaces.FindFromKey(ex.Current())) {
      if (f.IsSame(faces(corner))) continue;
      GeomAdaptor_Surface gs(BRep_Tool::Surface(TopoDS::Face(f)));
      if (gs.GetType() != GeomAbs_Cylinder) continue;
      GProp_GProps p;
      BRepGProp::SurfaceProperties(f, p);
      if (p.Mass() > longest) { longest = p.Mass(); fillet = f; shared = TopoDS::Edge(ex.Current()); }
    }
  HF_CHECK(!fillet.IsNull(), "the filleted box's corner blend has no cylindrical neighbour");
  if (divider) *divider = TopoDS::Edge(BRepBuilderAPI_Copy(shared).Shape());
  return shellWithout(solid, {faces(corner), fillet});
}

TopoDS_Shape panelWithHole(int sides, unsigned seed) {
  Handle(Geom_BSplineSurface) s = wavyPanel();
  std::mt19937 rng(seed);
  const auto corners = irregularPolygon(sides, 0.5, 0.5, 0.22, rng);
  std::uniform_real_distribution<double> bulge(-0.18, 0.22);
  std::vector<double> b;
  for (int i = 0; i < sides; ++i) b.push_back(bulge(rng));
  return faceWithHoles(s, {curvedPolygonWire(s, corners, b)});
}

TopoDS_Shape bezierPatchWithHole() {
  gp_Pnt P[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P[i][j] = gp_Pnt(20.0 * i, 20.0 * j, 10.0 * std::sin(1.1 * i + 0.3) * std::cos(0.8 * j) + 3.0 * i * j / 9.0);
  Handle(Geom_BSplineSurface) s = bezierSurface(P);
  std::mt19937 rng(7);
  const auto corners = irregularPolygon(5, 0.5, 0.48, 0.3, rng);
  return faceWithHoles(s, {curvedPolygonWire(s, corners, {0.1, -0.08, 0.15, 0.05, -0.1})});
}

TopoDS_Shape boxMinusFace() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(30, 20, 10).Shape();
  BRep_Builder B;
  TopoDS_Shell shell;
  B.MakeShell(shell);
  int i = 0;
  for (TopExp_Explorer ex(box, TopAbs_FACE); ex.More(); ex.Next(), ++i)
    if (i != 5) B.Add(shell, ex.Current());  // the last face of MakeBox is the top (z = 10)
  return shell;
}

TopoDS_Shape openCylinder() {
  const TopoDS_Shape cyl = BRepPrimAPI_MakeCylinder(10, 30).Shape();
  BRep_Builder B;
  TopoDS_Shell shell;
  B.MakeShell(shell);
  for (TopExp_Explorer ex(cyl, TopAbs_FACE); ex.More(); ex.Next()) {
    GeomAdaptor_Surface gs(BRep_Tool::Surface(TopoDS::Face(ex.Current())));
    GProp_GProps p;
    BRepGProp::SurfaceProperties(ex.Current(), p);
    if (gs.GetType() == GeomAbs_Plane && p.CentreOfMass().Z() > 15) continue;  // remove the top cap
    B.Add(shell, ex.Current());
  }
  return shell;
}

TopoDS_Shape sheetWithTwoHoles() {
  Handle(Geom_BSplineSurface) s = wavyPanel();
  std::mt19937 rng(3);
  const auto a = irregularPolygon(4, 0.28, 0.3, 0.13, rng);
  const auto b = irregularPolygon(5, 0.7, 0.68, 0.14, rng);
  return faceWithHoles(s, {curvedPolygonWire(s, a, {0.05, 0.05, 0.05, 0.05}),
                           curvedPolygonWire(s, b, {0.1, -0.05, 0.1, 0.0, 0.05})});
}

TopoDS_Shape nonManifoldFin() {
  const TopoDS_Shape box = boxMinusFace();
  // A fin face sharing the box's first edge: that edge then has three faces.
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(box, TopAbs_EDGE, edges);
  const TopoDS_Edge e = TopoDS::Edge(edges(1));
  TopoDS_Vertex v0, v1;
  TopExp::Vertices(e, v0, v1);
  const gp_Pnt p0 = BRep_Tool::Pnt(v0), p1 = BRep_Tool::Pnt(v1);
  const gp_Pnt q0(p0.X() - 15, p0.Y() - 15, p0.Z()), q1(p1.X() - 15, p1.Y() - 15, p1.Z());
  const TopoDS_Edge a = BRepBuilderAPI_MakeEdge(v1, BRepBuilderAPI_MakeVertex(q1).Vertex());
  BRepBuilderAPI_MakeWire mw;
  mw.Add(e);
  mw.Add(a);
  const TopoDS_Edge b = BRepBuilderAPI_MakeEdge(TopExp::LastVertex(a), BRepBuilderAPI_MakeVertex(q0).Vertex());
  mw.Add(b);
  mw.Add(BRepBuilderAPI_MakeEdge(TopExp::LastVertex(b), v0));
  const TopoDS_Face fin = BRepBuilderAPI_MakeFace(mw.Wire(), Standard_True);
  BRep_Builder B;
  TopoDS_Compound c;
  B.MakeCompound(c);
  B.Add(c, box);
  B.Add(c, fin);
  return c;
}

namespace {
// Every named sample, built only when asked for; the first three are the demo's.
const std::vector<std::pair<std::string, std::function<TopoDS_Shape()>>>& registry() {
  static const std::vector<std::pair<std::string, std::function<TopoDS_Shape()>>> r = {
      {"cc_valence5", [] { return ccExtraordinaryHole(5); }},
      {"filleted_box_corner", [] { return filletedBoxCorner(); }},
      {"panel_6_sided", [] { return panelWithHole(6, 11); }},
      {"box_minus_face", boxMinusFace},
      {"bezier_patch_with_hole", bezierPatchWithHole},
      {"sheet_two_holes", sheetWithTwoHoles},
      {"open_cylinder", openCylinder},
      {"non_manifold_fin", nonManifoldFin},
      {"closed_box", [] { return BRepPrimAPI_MakeBox(30, 20, 10).Shape(); }}};
  return r;
}
constexpr size_t kDemoSamples = 3;
}  // namespace

std::vector<NamedSample> demoSamples() {
  std::vector<NamedSample> d;
  for (size_t i = 0; i < kDemoSamples; ++i) d.push_back({registry()[i].first, registry()[i].second()});
  return d;
}

TopoDS_Shape byName(const std::string& name) {
  for (const auto& [n, make] : registry())
    if (n == name) return make();
  if (name.rfind("cc_valence", 0) == 0 && name.size() > 10 && name.find_first_not_of("0123456789", 10) == std::string::npos)
    return ccExtraordinaryHole(std::stoi(name.substr(10)));
  throw Error("unknown sample '" + name + "'");
}

std::vector<std::string> names() {
  std::vector<std::string> n;
  for (const auto& entry : registry()) n.push_back(entry.first);
  return n;
}

}  // namespace holefill::samples
