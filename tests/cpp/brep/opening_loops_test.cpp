#include "brep/opening_loops.h"

#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <string>

#include "brep/sample_models.h"
#include "fill/hole_fill.h"
#include "geometry/error.h"

using namespace holefill;

namespace {

// A washer (radius 10 around a bore of 4, 3 thick) with its top face, an annulus, missing: two
// free loops, the top circles, bound one opening.
TopoDS_Shape washerWithoutTop() {
  const TopoDS_Shape outer = BRepPrimAPI_MakeCylinder(10, 3).Shape(), bore = BRepPrimAPI_MakeCylinder(4, 3).Shape();
  const TopoDS_Shape washer = BRepAlgoAPI_Cut(outer, bore).Shape();
  BRep_Builder b;
  TopoDS_Shell shell;
  b.MakeShell(shell);
  for (TopExp_Explorer x(washer, TopAbs_FACE); x.More(); x.Next()) {
    const TopoDS_Face f = TopoDS::Face(x.Current());
    Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(f));
    if (!plane.IsNull() && plane->Location().Z() > 1.5) continue;  // the top
    b.Add(shell, f);
  }
  return shell;
}

}  // namespace

TEST(OpeningLoops, AWashersMissingTopIsOneOpeningOfTwoLoopsAndIsRefused) {
  const TopoDS_Shape model = washerWithoutTop();
  const HoleDetectionResult d = detectHoles(model);
  ASSERT_EQ(d.holes.size() + d.outerBoundaries.size(), 2u);
  std::vector<const Hole*> loops;
  for (const Hole& h : d.holes) loops.push_back(&h);
  for (const Hole& h : d.outerBoundaries) loops.push_back(&h);
  for (const Hole* h : loops) {
    const std::vector<const Hole*> others = loopsSharingOpening(d, *h);
    ASSERT_EQ(others.size(), 1u);
    EXPECT_NE(others[0]->edgeIndices(), h->edgeIndices());
  }
  // Either loop picked: a clear refusal naming both, never a cap over the other.
  for (const Hole* h : loops) {
    try {
      PreparedHole prepared(model, h->edgeIndices());
      FAIL() << "the washer's opening was taken as one loop";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("2 boundary loops"), std::string::npos) << what;
      EXPECT_NE(what.find("build a face bounded by all of them"), std::string::npos) << what;
    }
  }
}

TEST(OpeningLoops, ATubesTwoEndsAreTwoOpenings) {
  const TopoDS_Shape tube = samples::openCylinder();
  const HoleDetectionResult d = detectHoles(tube);
  for (const Hole& h : d.holes) EXPECT_TRUE(loopsSharingOpening(d, h).empty());
  for (const Hole& h : d.outerBoundaries) EXPECT_TRUE(loopsSharingOpening(d, h).empty());
}

TEST(OpeningLoops, AHoleInASheetIsOneOpeningEvenWithTheOuterBoundaryListedAsAHole) {
  const TopoDS_Shape panel = samples::panelWithHole(6, 11);
  HoleDetectionOptions all;
  all.includeOuterBoundary = true;
  for (const HoleDetectionResult& d : {detectHoles(panel), detectHoles(panel, all)}) {
    const Hole& inner = d.holes[0].corners == 6 ? d.holes[0] : d.holes[1];
    EXPECT_TRUE(loopsSharingOpening(d, inner).empty());
  }
  EXPECT_NO_THROW(PreparedHole(panel, 0));
  // The sheet's outer boundary taken as a hole would cap the hole inside it.
  const HoleDetectionResult d = detectHoles(panel, all);
  const Hole& outer = d.holes[0].corners == 4 ? d.holes[0] : d.holes[1];
  EXPECT_EQ(loopsSharingOpening(d, outer).size(), 1u);
}

TEST(OpeningLoops, TwoHolesSideBySideAreTwoOpenings) {
  const TopoDS_Shape sheet = samples::sheetWithTwoHoles();
  const HoleDetectionResult d = detectHoles(sheet);
  ASSERT_EQ(d.holes.size(), 2u);
  for (const Hole& h : d.holes) EXPECT_TRUE(loopsSharingOpening(d, h).empty());
}
