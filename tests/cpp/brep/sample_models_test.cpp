#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <map>

#include "brep/hole_detection.h"
#include "brep/sample_models.h"
#include "geometry/error.h"

using namespace holefill;

// Each bundled sample is a valid shape with the holes its name promises (N corners each), so the
// demo, the docs and the GUI tests that open them show what they say.
TEST(SampleModels, EachSampleIsValidWithTheHolesItsNameSays) {
  const std::map<std::string, std::vector<int>> corners = {
      {"cc_valence5", {5}},       {"filleted_box_corner", {3}}, {"panel_6_sided", {6}},    {"box_minus_face", {4}},
      {"bezier_patch_with_hole", {5}}, {"sheet_two_holes", {4, 5}}, {"open_cylinder", {0}}, {"non_manifold_fin", {4}},
      {"closed_box", {}}};
  for (const std::string& name : samples::names()) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(corners.count(name)) << "a sample without expectations here";
    const TopoDS_Shape s = samples::byName(name);
    ASSERT_FALSE(s.IsNull());
    EXPECT_TRUE(BRepCheck_Analyzer(s).IsValid());
    std::vector<int> found;
    for (const Hole& h : detectHoles(s).holes) found.push_back(h.corners);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, corners.at(name));
  }
  EXPECT_EQ(samples::demoSamples().size(), 3u);
  EXPECT_THROW(samples::byName("no_such_sample"), Error);
}

// The two adjacent holes' sample comes with the dividing edge, which runs between two vertices
// of the one loop it splits.
TEST(SampleModels, AdjacentHolesComeWithTheirDivider) {
  TopoDS_Edge divider;
  const TopoDS_Shape s = samples::filletedBoxAdjacentHoles(&divider);
  ASSERT_FALSE(divider.IsNull());
  const HoleDetectionResult d = detectHoles(s);
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.holes[0].corners, 3);
}
