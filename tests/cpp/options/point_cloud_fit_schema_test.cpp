#include <gtest/gtest.h>

#include "geometry/error.h"
#include "options/point_cloud_fit_schema.h"
#include "schema_checks.h"

using namespace holefill;

// Each option set through the schema lands where the point-cloud fit reads it, and reads back.
TEST(PointCloudFitSchema, EachOptionReachesTheFieldTheFitReads) {
  const auto& s = pointCloudFitSchema();
  PointCloudFitOptions o;
  const OptionValues values = {
      {"method", "invdist"},      {"radius", "0.2"},      {"weights", "w.pt"},      {"degree", "2"},
      {"cells", "6"},             {"iterations", "3"},    {"tolerance", "0.05"},    {"relativeTolerance", "0.002"},
      {"smoothing", "1e-05"},     {"adaptive", "false"},  {"cellFaces", "true"}};
  setEveryOption(s, o, values);
  EXPECT_EQ(o.parameterization.weights, CloudWeights::InverseDistance);
  EXPECT_EQ(o.parameterization.radius, 0.2);
  EXPECT_EQ(o.parameterization.weightsFile, "w.pt");
  EXPECT_EQ(o.fit.degree, 2);
  EXPECT_EQ(o.fit.baseCells, 6);
  EXPECT_EQ(o.fit.maxIterations, 3);
  EXPECT_EQ(o.tolerance, 0.05);
  EXPECT_EQ(o.fit.relativeTolerance, 0.002);
  EXPECT_EQ(o.fit.smoothing, 1e-5);
  EXPECT_FALSE(o.adaptive);
  EXPECT_TRUE(o.cellFaces);
  expectEveryOptionReadsBack(s, o, values);
}

TEST(PointCloudFitSchema, DefaultsAreTheStructsAndNamesAndFlagsAreUnique) {
  const auto& s = pointCloudFitSchema();
  expectWellFormedSchema(s);
  const PointCloudFitOptions d;
  EXPECT_EQ(s[0].get(d), "shape");
  EXPECT_EQ(s[6].get(d), "0");  // no tolerance in model units: the relative one decides
  EXPECT_EQ(s[9].get(d), "true");
  PointCloudFitOptions o;
  EXPECT_THROW(setOption(s, o, "method", "support"), Error);
  EXPECT_THROW(setOption(s, o, "degree", "8"), Error);
  EXPECT_THROW(setOption(s, o, "relativeTolerance", "0"), Error);
  EXPECT_THROW(setOption(s, o, "tolerance", "-1"), Error);
}
