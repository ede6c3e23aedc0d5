#include "brep/face_building.h"

#include <gtest/gtest.h>

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_ListIteratorOfListOfCurveRepresentation.hxx>
#include <BRep_TEdge.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>

#include "brep/sample_models.h"
#include "fill/parameterizer.h"
#include "geometry/bspline_surface.h"
#include "geometry/occt_bridge.h"

using namespace holefill;

namespace {

int curvesOnSurface(const TopoDS_Edge& e) {
  int n = 0;
  for (BRep_ListIteratorOfListOfCurveRepresentation it(Handle(BRep_TEdge)::DownCast(e.TShape())->Curves()); it.More(); it.Next())
    if (it.Value()->IsCurveOnSurface()) ++n;
  return n;
}

struct EdgeState {
  std::vector<int> pcurves;
  std::vector<double> edgeTol, vertexTol;
};

EdgeState stateOf(const Hole& h) {
  EdgeState s;
  for (const auto& he : h.edges) {
    s.pcurves.push_back(curvesOnSurface(he.edge));
    s.edgeTol.push_back(BRep_Tool::Tolerance(he.edge));
    TopoDS_Vertex a, b;
    TopExp::Vertices(he.edge, a, b);
    s.vertexTol.push_back(BRep_Tool::Tolerance(a));
    s.vertexTol.push_back(BRep_Tool::Tolerance(b));
  }
  return s;
}

// A deliberately poor surface (the plane z = mean height over the pcurve domain), so building on
// it must raise the edges' tolerances: what detachFace has to put back.
Handle(Geom_BSplineSurface) flatSurface(const Parameterization& P, double z) {
  BSplineSurface s;
  s.degreeU = s.degreeV = 1;
  s.knotsU = {P.u0, P.u0, P.u1, P.u1};
  s.knotsV = {P.v0, P.v0, P.v1, P.v1};
  s.poles.resize(4, 3);
  int k = 0;
  for (double u : {P.u0, P.u1})
    for (double v : {P.v0, P.v1}) s.poles.row(k++) << u, v, z;
  return toOcct(s);
}

// The hole's edges are as `expected` says, and carry the built face's pcurves or not.
void expectState(const Hole& hole, const FaceBuildResult& built, const EdgeState& expected, bool attached) {
  const EdgeState now = stateOf(hole);
  EXPECT_EQ(now.pcurves, expected.pcurves);
  EXPECT_EQ(now.edgeTol, expected.edgeTol);
  EXPECT_EQ(now.vertexTol, expected.vertexTol);
  for (const auto& he : hole.edges) {
    double f, l;
    EXPECT_EQ(BRep_Tool::CurveOnSurface(he.edge, built.face, f, l).IsNull(), !attached);
  }
}

}  // namespace

TEST(FaceBuilding, DetachPutsTheEdgesBackAndAttachRestoresTheFace) {
  const TopoDS_Shape model = BRepBuilderAPI_Copy(samples::panelWithHole(6, 3)).Shape();
  const Hole hole = detectHoles(model).holes.at(0);
  const std::vector<BoundarySample> samples = sampleBoundary(hole);
  const Parameterization P = parameterize(hole, samples, ParamMethod::NearestPlane);
  double z = 0;
  for (const auto& s : samples) z += s.point.z() / samples.size();
  const EdgeState before = stateOf(hole);

  const FaceBuildResult built = buildTrimmedFace(hole, flatSurface(P, z), samples, P.uv);
  ASSERT_FALSE(built.face.IsNull());
  ASSERT_EQ(built.pcurves.size(), hole.edges.size());
  const EdgeState on = stateOf(hole);
  bool raised = false;
  for (size_t k = 0; k < hole.edges.size(); ++k) {
    EXPECT_EQ(on.pcurves[k], before.pcurves[k] + 1);
    EXPECT_GE(on.edgeTol[k], before.edgeTol[k]);
    EXPECT_NEAR(on.edgeTol[k], built.edgeTolerances[k], 0);
    raised = raised || on.edgeTol[k] > 10 * before.edgeTol[k];
  }
  EXPECT_TRUE(raised) << "the flat surface lies off the boundary: the build must raise tolerances";

  detachFace(hole, built);
  expectState(hole, built, before, false);
  attachFace(hole, built);
  expectState(hole, built, on, true);
}

TEST(FaceBuilding, SewnFaceClosesTheBoxAsASolid) {
  // Sewing is topological: the face shares the hole's edges, so the box's shell closes whatever
  // the surface (here a poor one; the fill's own surface is tested in hole_fill_test).
  const TopoDS_Shape model = BRepBuilderAPI_Copy(samples::boxMinusFace()).Shape();
  const Hole hole = detectHoles(model).holes.at(0);
  const std::vector<BoundarySample> samples = sampleBoundary(hole);
  const Parameterization P = parameterize(hole, samples, ParamMethod::NearestPlane);
  const FaceBuildResult built = buildTrimmedFace(hole, flatSurface(P, 0.0), samples, P.uv);
  const SewResult sr = sewFace(model, built.face);
  EXPECT_TRUE(sr.closedSolid);
  EXPECT_EQ(sr.volume, 0.0);  // not asked
  int faces = 0;
  for (TopExp_Explorer ex(sr.shape, TopAbs_FACE); ex.More(); ex.Next()) ++faces;
  EXPECT_EQ(faces, 6);
}
