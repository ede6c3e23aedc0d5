#include <gtest/gtest.h>

#include "geometry/error.h"
#include "schema_checks.h"
#include "options/hole_fill_schema.h"

using namespace holefill;

// The schema reads and writes the very fields the fill uses: each set through the schema lands
// in HoleFillOptions where the fill reads it, and reads back the same.
TEST(HoleFillSchema, EachOptionReachesTheFieldTheFillReads) {
  const auto& s = holeFillSchema();
  HoleFillOptions o;
  const OptionValues values = {
      {"method", "mvc"},        {"continuity", "G2"},        {"tolerance", "0.002"},          {"angularTolerance", "0.01"},
      {"curvatureTolerance", "0.2"}, {"maxControlPoints", "600"}, {"edgeContinuity", "Edge5=G0,Edge7=G1"},
      {"points", "1,2,3;-0.5,0,0.001"},
      {"detectCreases", "false"}, {"modelAccuracy", "false"}, {"weights", "/tmp/u.pt"}, {"computeVolume", "true"},
      {"checkModel", "true"}};
  setEveryOption(s, o, values);
  EXPECT_EQ(o.method, ParamMethod::MeanValue);
  EXPECT_EQ(o.continuity, Continuity::G2);
  EXPECT_EQ(o.tolerance, 0.002);
  EXPECT_EQ(o.angularTolerance, 0.01);
  EXPECT_EQ(o.curvatureTolerance, 0.2);
  EXPECT_EQ(o.solver.maxControlPoints, 600);
  EXPECT_EQ(o.edgeContinuity, (std::map<int, Continuity>{{5, Continuity::G0}, {7, Continuity::G1}}));
  EXPECT_FALSE(o.edges.detectCreases);
  EXPECT_FALSE(o.modelAccuracy);
  EXPECT_EQ(o.parameterization.uvtranWeights, "/tmp/u.pt");
  EXPECT_TRUE(o.computeVolume);
  EXPECT_TRUE(o.checkModel);
  ASSERT_EQ(o.points.size(), 2u);
  EXPECT_EQ(o.points[1], Eigen::Vector3d(-0.5, 0, 1e-3));
  expectEveryOptionReadsBack(s, o, values);
  setOption(s, o, "edgeContinuity", "");
  EXPECT_TRUE(o.edgeContinuity.empty());
  setOption(s, o, "points", "");
  setOption(s, o, "points", " 1, 2 ,3 ; ");
  EXPECT_EQ(o.points, (std::vector<Eigen::Vector3d>{Eigen::Vector3d(1, 2, 3)}));
  for (const char* bad : {"1,2", "1,2,3,4", "1,x,3", "1,2,nan"}) EXPECT_THROW(setOption(s, o, "points", bad), Error) << bad;
}

TEST(HoleFillSchema, DefaultsAreTheStructsAndNamesAndFlagsAreUnique) {
  const auto& s = holeFillSchema();
  const HoleFillOptions d;
  expectWellFormedSchema(s);
  EXPECT_EQ(s[0].get(d), "auto");
  EXPECT_EQ(s[1].get(d), "G1");
  // The hidden test method is not a door's choice.
  HoleFillOptions o;
  EXPECT_THROW(setOption(s, o, "method", "support"), Error);
}
