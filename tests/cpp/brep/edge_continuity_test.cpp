#include "brep/edge_continuity.h"

#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <BRepAdaptor_Surface.hxx>

#include "fill/hole_fill.h"
#include "geometry/error.h"
#include "geometry/tolerances.h"

using namespace holefill;

namespace {

// A box with one edge rounded, the fillet face removed: its loop is tangent to the two walls
// along the fillet's lines and sharp against the two end faces along its arcs.
TopoDS_Shape boxWithoutFillet() {
  TopoDS_Shape box = BRepPrimAPI_MakeBox(100, 80, 60).Shape();
  BRepFilletAPI_MakeFillet mf(box);
  TopExp_Explorer ex(box, TopAbs_EDGE);
  mf.Add(12.0, TopoDS::Edge(ex.Current()));
  const TopoDS_Shape rounded = mf.Shape();
  BRep_Builder B;
  TopoDS_Shell shell;
  B.MakeShell(shell);
  for (TopExp_Explorer f(rounded, TopAbs_FACE); f.More(); f.Next())
    if (BRepAdaptor_Surface(TopoDS::Face(f.Current())).GetType() != GeomAbs_Cylinder) B.Add(shell, f.Current());
  return shell;
}

bool isLine(const HoleEdge& e) {
  double a, b;
  return BRep_Tool::Curve(e.edge, a, b)->DynamicType()->Name() == std::string("Geom_Line");
}

}  // namespace

TEST(EdgeContinuity, FilletLoopHasCreasesAtTheEndFacesAndTangentWalls) {
  const Hole hole = detectHoles(boxWithoutFillet()).holes.at(0);
  ASSERT_EQ(hole.edges.size(), 4u);
  const std::vector<double> mismatch = cornerMismatch(hole);
  const std::vector<EdgeRequest> q = edgeRequests(hole, Continuity::G1, {});
  for (size_t i = 0; i < 4; ++i) {
    if (isLine(hole.edges[i])) {
      EXPECT_LT(mismatch[i], 1e-9) << i;  // the wall's normal is the corner plane's
      EXPECT_EQ(q[i].asked, Continuity::G1);
      EXPECT_EQ(q[i].source, "request");
    } else {
      EXPECT_NEAR(mismatch[i], M_PI / 2, 1e-9) << i;  // the end face is perpendicular to the fillet
      EXPECT_EQ(q[i].asked, Continuity::G0);
      EXPECT_EQ(q[i].source, "crease");
    }
  }
}

TEST(EdgeContinuity, OverridesWinAndAreCappedByTheRequest) {
  const Hole hole = detectHoles(boxWithoutFillet()).holes.at(0);
  std::map<int, Continuity> o;
  for (const auto& e : hole.edges) o[e.edgeIndex] = isLine(e) ? Continuity::G0 : Continuity::G2;
  const std::vector<EdgeRequest> q = edgeRequests(hole, Continuity::G1, o);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(q[i].source, "override");
    EXPECT_EQ(q[i].asked, isLine(hole.edges[i]) ? Continuity::G0 : Continuity::G1);  // G2 capped at the request
  }
  EXPECT_THROW(edgeRequests(hole, Continuity::G1, {{99999, Continuity::G0}}), Error);  // not on the loop
  EdgeContinuityOptions off;
  off.detectCreases = false;
  for (const auto& r : edgeRequests(hole, Continuity::G1, {}, off)) EXPECT_EQ(r.asked, Continuity::G1);
}

TEST(EdgeContinuity, ParsesEdgeLists) {
  const auto m = parseEdgeContinuity("Edge5=G0,7=G2,Edge12=g1");
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m.at(5), Continuity::G0);
  EXPECT_EQ(m.at(7), Continuity::G2);
  EXPECT_EQ(m.at(12), Continuity::G1);
  for (const char* bad : {"", "Edge5", "Edge=G0", "EdgeX=G1", "Edge5=G3", "Face5=G0", "-3=G0"})
    EXPECT_THROW(parseEdgeContinuity(bad), Error) << bad;
}

// The mixed crease/smooth loop (issue 20): G1 asked, creases get G0, the rest strict G1, status ok.
TEST(EdgeContinuity, MixedLoopFillsAtG1WithCreasesAtG0) {
  const TopoDS_Shape model = boxWithoutFillet();
  HoleFillOptions o;
  o.continuity = Continuity::G1;
  const HoleFillResult r = fillHole(model, 0, o);
  EXPECT_EQ(r.status, FillStatus::Ok) << r.message;
  EXPECT_EQ(r.achieved, "G1");
  EXPECT_TRUE(r.faceValid && r.shapeValid);
  EXPECT_LE(r.report.g0Relative, tol::kG0Strict);
  ASSERT_EQ(r.edgeRequests.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const bool line = isLine(r.hole.edges[i]);
    EXPECT_EQ(r.edgeRequests[i].asked, line ? Continuity::G1 : Continuity::G0);
    EXPECT_GE(r.edgeReached[i], line ? 1 : 0);
    for (const auto& e : r.report.edges)
      if (e.edgeIndex == r.edgeRequests[i].edgeIndex && line) EXPECT_LE(e.g1, tol::kG1Strict);
  }
  // Without the detection every edge is asked G1, which the end faces cannot give.
  o.edges.detectCreases = false;
  const HoleFillResult all = fillHole(model, 0, o);
  EXPECT_EQ(all.status, FillStatus::ToleranceNotMet);
  EXPECT_FALSE(all.faultyEdges.empty());
}
