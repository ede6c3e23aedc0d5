#include "brep/hole_detection.h"

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pln.hxx>
#include <limits>

#include "brep/sample_models.h"
#include "brep/shape_io.h"
#include "geometry/error.h"

using namespace holefill;

TEST(HoleDetection, BoxMinusFaceIsOneFourSidedHole) {
  const auto d = detectHoles(samples::boxMinusFace());
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.holes[0].edges.size(), 4u);
  EXPECT_EQ(d.holes[0].corners, 4);
  EXPECT_NEAR(d.holes[0].length, 2 * (30 + 20), 1e-9);
  EXPECT_TRUE(d.nonManifoldEdges.empty());
}

TEST(HoleDetection, FilletedBoxCornerIsThreeSided) {
  const auto d = detectHoles(samples::filletedBoxCorner());
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.holes[0].corners, 3);
  EXPECT_EQ(d.holes[0].edges.size(), 3u);
}

TEST(HoleDetection, ExtraordinaryPointHoleHasValenceCorners) {
  for (int n : {3, 5, 6}) {
    const auto d = detectHoles(samples::ccExtraordinaryHole(n));
    ASSERT_EQ(d.holes.size(), 1u) << "valence " << n;
    EXPECT_EQ(d.holes[0].corners, n);
    EXPECT_EQ(static_cast<int>(d.holes[0].edges.size()), 2 * n);  // two patch edges per side
    ASSERT_EQ(d.outerBoundaries.size(), 1u);  // the ring's outer rim is not a hole
  }
}

TEST(HoleDetection, SheetInnerHoleNotOuterBoundaryUnlessAsked) {
  const TopoDS_Shape panel = samples::panelWithHole(6, 11);
  const auto d = detectHoles(panel);
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.holes[0].corners, 6);
  EXPECT_LT(d.holes[0].outerScore, 0.0);
  ASSERT_EQ(d.outerBoundaries.size(), 1u);
  EXPECT_EQ(d.outerBoundaries[0].corners, 4);
  HoleDetectionOptions all;
  all.includeOuterBoundary = true;
  EXPECT_EQ(detectHoles(panel, all).holes.size(), 2u);
}

TEST(HoleDetection, ShellWithTwoHoles) {
  const auto d = detectHoles(samples::sheetWithTwoHoles());
  ASSERT_EQ(d.holes.size(), 2u);
  EXPECT_EQ(d.holes[0].corners + d.holes[1].corners, 4 + 5);
  // Every edge belongs to one hole only and names a real model edge.
  std::set<int> seen;
  for (const auto& h : d.holes)
    for (int e : h.edgeIndices()) EXPECT_TRUE(seen.insert(e).second);
}

TEST(HoleDetection, LoopMeetingASeamEdge) {
  const TopoDS_Shape cyl = samples::openCylinder();
  const auto d = detectHoles(cyl);
  ASSERT_EQ(d.holes.size(), 1u);
  ASSERT_EQ(d.holes[0].edges.size(), 1u);  // the circle; the seam is used twice by its face, never free
  EXPECT_EQ(d.holes[0].corners, 0);
  EXPECT_NEAR(d.holes[0].length, 2 * M_PI * 10, 1e-6);
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(cyl, TopAbs_EDGE, edges);
  const TopoDS_Edge circle = TopoDS::Edge(edges(d.holes[0].edges[0].edgeIndex));
  EXPECT_FALSE(BRep_Tool::IsClosed(circle, d.holes[0].edges[0].support));  // not the seam
}

TEST(HoleDetection, NonManifoldEdgesAreReportedNotGuessed) {
  const auto d = detectHoles(samples::nonManifoldFin());
  ASSERT_EQ(d.nonManifoldEdges.size(), 1u);
  EXPECT_EQ(d.nonManifoldEdges[0], 1);
  for (const auto& h : d.holes)
    for (int e : h.edgeIndices()) EXPECT_NE(e, 1);
  EXPECT_FALSE(d.warnings.empty());
}

TEST(HoleDetection, LoopsTouchingAtAVertexStaySeparate) {
  // A plane with two square holes that share one corner vertex.
  gp_Pln pln;
  BRepBuilderAPI_MakeFace base(pln, -10, 10, -10, 10);
  auto v = [](double x, double y) { return BRepBuilderAPI_MakeVertex(gp_Pnt(x, y, 0)).Vertex(); };
  const TopoDS_Vertex c = v(0, 0);
  auto square = [&](double sx, double sy) {
    const TopoDS_Vertex a = v(sx * 4, 0), b = v(sx * 4, sy * 4), d = v(0, sy * 4);
    BRepBuilderAPI_MakeWire w;
    w.Add(BRepBuilderAPI_MakeEdge(c, a));
    w.Add(BRepBuilderAPI_MakeEdge(a, b));
    w.Add(BRepBuilderAPI_MakeEdge(b, d));
    w.Add(BRepBuilderAPI_MakeEdge(d, c));
    return w.Wire();
  };
  BRepBuilderAPI_MakeFace mf(base.Face());
  mf.Add(TopoDS::Wire(square(1, 1).Reversed()));
  mf.Add(TopoDS::Wire(square(-1, -1).Reversed()));
  const auto d = detectHoles(mf.Face());
  ASSERT_EQ(d.holes.size(), 2u);
  for (const auto& h : d.holes) {
    EXPECT_EQ(h.edges.size(), 4u);
    EXPECT_EQ(h.corners, 4);
    EXPECT_NEAR(h.length, 16.0, 1e-9);
  }
}

TEST(HoleDetection, ClosedSolidHasNoHoles) {
  const auto d = detectHoles(samples::byName("closed_box"));
  EXPECT_TRUE(d.holes.empty());
  EXPECT_TRUE(d.outerBoundaries.empty());
}

TEST(HoleDetection, BadInputsAreClearErrors) {
  EXPECT_THROW(detectHoles(TopoDS_Shape()), Error);
  TopoDS_Compound empty;
  BRep_Builder().MakeCompound(empty);
  EXPECT_THROW(detectHoles(empty), Error);  // no faces
  EXPECT_THROW(shapeFromBrepString("this is not BREP text"), Error);
  EXPECT_THROW(shapeFromBrepString(""), Error);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  TopoDS_Compound c;
  BRep_Builder().MakeCompound(c);
  BRep_Builder().Add(c, BRepBuilderAPI_MakeVertex(gp_Pnt(nan, 0, 0)).Vertex());
  EXPECT_THROW(validateShape(c), Error);
}
