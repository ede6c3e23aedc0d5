#include "fill/adjacent_holes.h"

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include "brep/sample_models.h"
#include "geometry/error.h"
#include "geometry/tolerances.h"

using namespace holefill;

namespace {
int sharedEdges(const TopoDS_Face& a, const TopoDS_Face& b) {
  TopTools_IndexedMapOfShape ea, eb;
  TopExp::MapShapes(a, TopAbs_EDGE, ea);
  TopExp::MapShapes(b, TopAbs_EDGE, eb);
  int n = 0;
  for (int i = 1; i <= ea.Extent(); ++i) n += eb.Contains(ea(i));
  return n;
}
int faceCount(const TopoDS_Shape& s) {
  TopTools_IndexedMapOfShape f;
  TopExp::MapShapes(s, TopAbs_FACE, f);
  return f.Extent();
}
}  // namespace

// The corner blend of a filleted box and the fillet next to it removed, the edge they shared
// given as the dividing curve: two faces sharing that edge, the box closed and valid again,
// G1 (strict) to the neighbours and to each other.
TEST(AdjacentHoles, TwoFacesShareTheDividingEdgeAtG1) {
  TopoDS_Edge divider;
  const TopoDS_Shape shell = samples::filletedBoxAdjacentHoles(&divider);
  const HoleDetectionResult det = detectHoles(shell);
  ASSERT_EQ(det.holes.size(), 1u);
  const std::vector<int> edges = det.holes[0].edgeIndices();
  // Any edge of the loop names it.
  const AdjacentFillResult r = fillAdjacentHoles(shell, {edges[2]}, divider);
  ASSERT_FALSE(r.shape.IsNull()) << r.message;
  EXPECT_EQ(r.status, FillStatus::Ok) << r.message;
  EXPECT_TRUE(r.shapeValid);
  EXPECT_TRUE(r.second.closedSolid) << r.message;
  EXPECT_TRUE(BRepCheck_Analyzer(r.shape).IsValid());
  EXPECT_EQ(faceCount(r.shape), faceCount(shell) + 2);
  EXPECT_EQ(sharedEdges(r.first.face, r.second.face), 1);
  TopTools_IndexedMapOfShape all;
  TopExp::MapShapes(r.shape, TopAbs_EDGE, all);
  EXPECT_TRUE(all(r.sharedEdgeIndex).IsSame(r.shared));
  // Across the shared edge, measured on the two new faces themselves.
  EXPECT_LE(r.across.g0Relative, tol::kG0Strict) << r.message;
  EXPECT_LE(r.across.g1, tol::kG1Strict) << r.message;
  // Each side towards the model, on the loop's own edges.
  for (const HoleFillResult* side : {&r.first, &r.second})
    for (const auto& e : side->report.edges)
      if (e.edgeIndex != r.sharedEdgeIndex) {
        EXPECT_LE(e.g0, tol::kG0Strict * side->report.scale) << "Edge" << e.edgeIndex;
        EXPECT_LE(e.g1, tol::kG1Strict) << "Edge" << e.edgeIndex;
      }
  // The first fill named the divider Edge0 while it was not yet in the model: renamed.
  for (const auto& q : r.first.edgeRequests) EXPECT_GT(q.edgeIndex, 0);
  // The user's shape is untouched: still one open loop.
  EXPECT_EQ(detectHoles(shell).holes.size(), 1u);
}

TEST(AdjacentHoles, ADividerThatDoesNotSplitTheLoopIsRefused) {
  TopoDS_Edge divider;
  const TopoDS_Shape shell = samples::filletedBoxAdjacentHoles(&divider);
  const std::vector<int> edges = detectHoles(shell).holes[0].edgeIndices();
  // Ends far from any vertex of the loop.
  const TopoDS_Edge stray = BRepBuilderAPI_MakeEdge(gp_Pnt(-50, -50, -50), gp_Pnt(-40, -50, -50)).Edge();
  EXPECT_THROW(fillAdjacentHoles(shell, edges, stray), Error);
  // Starts and ends at one vertex.
  const gp_Pnt v = BRep_Tool::Pnt(TopExp::FirstVertex(divider));
  const TopoDS_Edge loop = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(v.Translated(gp_Vec(0, 0, -1)), gp_Dir(1, 0, 0), gp_Dir(0, 0, 1)), 1.0)).Edge();
  EXPECT_THROW(fillAdjacentHoles(shell, edges, loop), Error);
  EXPECT_THROW(fillAdjacentHoles(shell, edges, TopoDS_Edge()), Error);
}
