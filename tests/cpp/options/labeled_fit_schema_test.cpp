#include <gtest/gtest.h>

#include "geometry/error.h"
#include "schema_checks.h"
#include "options/labeled_fit_schema.h"

using namespace holefill;

// Each option set through the schema lands where labeled fitting reads it, and reads back.
TEST(LabeledFitSchema, EachOptionReachesTheFieldTheFitReads) {
  const auto& s = labeledFitSchema();
  LabeledFitOptions o;
  const OptionValues values = {
      {"controlU", "10"},   {"controlV", "8"},         {"maxControl", "30"},       {"tolerance", "0.5"}, {"relativeTolerance", "0.002"},
      {"extension", "G1"},  {"margin", "2"},           {"reach", "0.1"},           {"fairness", "0.5"},
      {"isocurves", "paper"}, {"meshFairness", "0.01"}, {"smoothing", "1e-05"},   {"framePlacement", "2"},
      {"releaseDepth", "-1"}, {"relaxLabels", "false"}};
  setEveryOption(s, o, values);
  EXPECT_EQ(o.fit.controlU, 10);
  EXPECT_EQ(o.fit.controlV, 8);
  EXPECT_EQ(o.maxControl, 30);
  EXPECT_EQ(o.tolerance, 0.5);
  EXPECT_EQ(o.relativeTolerance, 0.002);
  EXPECT_TRUE(o.extend);
  EXPECT_EQ(o.extensionSource, LabeledFitOptions::ExtensionSource::Continuation);
  EXPECT_EQ(o.extension.order, 2);
  EXPECT_EQ(o.extension.marginLayers, 2);
  EXPECT_EQ(o.reach, 0.1);
  EXPECT_EQ(o.extension.fairness, 0.5);
  EXPECT_TRUE(o.extension.paperIsocurves);
  EXPECT_EQ(o.extension.meshFairness, 0.01);
  EXPECT_EQ(o.fit.smoothing, 1e-5);
  EXPECT_EQ(o.parameterization.framePlacement, 2);
  EXPECT_EQ(o.parameterization.releaseDepth, -1);
  EXPECT_FALSE(o.relaxLabels);
  expectEveryOptionReadsBack(s, o, values);
  EXPECT_NO_THROW(checkLabeledFitOptions(o));  // a continuation may carry the paper's fairness terms
  setOption(s, o, "extension", "none");
  EXPECT_FALSE(o.extend);
  EXPECT_EQ(s[5].get(o), "none");
}

TEST(LabeledFitSchema, DefaultsAreTheStructsAndNamesAndFlagsAreUnique) {
  const auto& s = labeledFitSchema();
  const LabeledFitOptions d;
  expectWellFormedSchema(s);
  LabeledFitOptions o;
  EXPECT_EQ(s[2].get(o), std::to_string(d.maxControl));
  EXPECT_EQ(s[5].get(o), "fit");
  EXPECT_THROW(setOption(s, o, "extension", "G3"), Error);
  EXPECT_THROW(setOption(s, o, "controlU", "3"), Error);
  EXPECT_THROW(setOption(s, o, "reach", "10.5"), Error);
}
