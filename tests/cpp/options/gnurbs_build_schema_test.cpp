#include <gtest/gtest.h>

#include "geometry/error.h"
#include "options/gnurbs_build_schema.h"
#include "schema_checks.h"

using namespace holefill;

// Each option set through the schema lands where the G-NURBS pipeline reads it, and reads back.
TEST(GnurbsBuildSchema, EachOptionReachesTheFieldThePipelineReads) {
  const auto& s = gnurbsBuildSchema();
  GnurbsBuildOptions o;
  const OptionValues values = {{"refine", "false"}, {"maxValence", "40"}, {"solve", "stepwise"}, {"mergeRegular", "true"}, {"fitRounds", "3"}};
  setEveryOption(s, o, values);
  EXPECT_FALSE(o.surface.refineWhenNeeded);
  EXPECT_EQ(o.surface.maxValence, 40);
  EXPECT_EQ(o.surface.solve, G2GnurbsOptions::Solve::Stepwise);
  EXPECT_TRUE(o.brep.mergeRegular);
  EXPECT_EQ(o.fit.iterations, 3);
  expectEveryOptionReadsBack(s, o, values);
}

TEST(GnurbsBuildSchema, DefaultsAreTheStructsAndNamesAndFlagsAreUnique) {
  const auto& s = gnurbsBuildSchema();
  expectWellFormedSchema(s);
  const GnurbsBuildOptions d;
  EXPECT_EQ(s[1].get(d), std::to_string(d.surface.maxValence));
  EXPECT_EQ(s[2].get(d), "fair");
  GnurbsBuildOptions o;
  EXPECT_THROW(setOption(s, o, "solve", "greedy"), Error);
  EXPECT_THROW(setOption(s, o, "maxValence", "-1"), Error);
}
