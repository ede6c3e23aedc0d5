#include "gnurbs/quad_cage.h"

#include <gtest/gtest.h>

#include "geometry/error.h"
#include "gnurbs/sample_cages.h"

namespace holefill {
namespace {

std::string errorOf(const QuadCage& cage) {
  try {
    CageTopology check(cage);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(QuadCage, SampleCagesAreValidAndTheirPointsFound) {
  for (const auto& name : cages::sampleCageNames()) EXPECT_EQ(errorOf(cages::sampleCage(name)), "") << name;
  EXPECT_EQ(CageTopology(cages::sampleCage("cage_valence5")).extraordinaryPoints().size(), 1u);
}

// Issue 22: the Python door passed a cage at 1e300 straight to the construction, which crashed
// FreeCAD (only the OBJ reader bounded coordinates). The topology check bounds them for every door.
TEST(QuadCage, CoordinatesPastTheBoundAreRefusedForEveryDoor) {
  QuadCage far = cages::sampleCage("cage_valence5");
  far.vertices *= 1e300;
  EXPECT_NE(errorOf(far).find("coordinate beyond"), std::string::npos) << errorOf(far);
  QuadCage anchored = cages::sampleCage("cage_valence5");
  const int ep = CageTopology(anchored).extraordinaryPoints()[0];
  anchored.setSharp(ep, anchored.quads(0, 1) == ep ? anchored.quads(0, 2) : anchored.quads(0, 1));
  anchored.anchors[ep] = Eigen::Vector3d(0, 0, 1e300);
  EXPECT_NE(errorOf(anchored).find("anchor"), std::string::npos) << errorOf(anchored);
  QuadCage nan = cages::sampleCage("cage_valence5");
  nan.vertices(2, 1) = std::nan("");
  EXPECT_NE(errorOf(nan).find("non-finite"), std::string::npos);
}

}  // namespace
}  // namespace holefill
