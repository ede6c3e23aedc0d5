#include <gtest/gtest.h>

#include "geometry/error.h"
#include "options/mesh_fill_schema.h"
#include "schema_checks.h"

using namespace holefill;

// Each option set through the schema lands where the mesh fill reads it, and reads back.
TEST(MeshFillSchema, EachOptionReachesTheFieldTheFillReads) {
  const auto& s = meshFillSchema();
  MeshFillOptions o;
  const OptionValues values = {
      {"mode", "ours"},         {"maxBoundary", "300"},    {"triangulation", "dihedral"}, {"refine", "false"},        {"densityFactor", "2"},
      {"shapeOrder", "3"},       {"shapePasses", "2"},          {"alongNormals", "false"},  {"smoothIterations", "0"},
      {"fairIterations", "0"},   {"closenessScale", "1.5"},     {"featureScale", "0.25"},
      {"checkCrossings", "false"}, {"weld", "1e-06"}};
  setEveryOption(s, o, values);
  EXPECT_EQ(o.maxBoundary, 300);
  EXPECT_EQ(o.initial, MeshFillOptions::Triangulation::MinDihedral);
  EXPECT_FALSE(o.refine);
  EXPECT_EQ(o.refinement.densityFactor, 2);
  EXPECT_EQ(o.shape.order, 3);
  EXPECT_EQ(o.shape.passes, 2);
  EXPECT_FALSE(o.shape.alongNormals);
  EXPECT_EQ(o.quality.smoothing.iterations, 0);
  EXPECT_EQ(o.fairing.iterations, 0);
  EXPECT_EQ(o.fairing.closenessScale, 1.5);
  EXPECT_EQ(o.fairing.featureScale, 0.25);
  EXPECT_EQ(o.weld, 1e-6);
  EXPECT_FALSE(o.checkCrossings);
  expectEveryOptionReadsBack(s, o, values);
}

TEST(MeshFillSchema, DefaultsAreTheStructsAndNamesAndFlagsAreUnique) {
  const auto& s = meshFillSchema();
  expectWellFormedSchema(s);
  const MeshFillOptions d;
  EXPECT_EQ(s[0].get(d), "ours");
  EXPECT_EQ(s[1].get(d), std::to_string(d.maxBoundary));
  EXPECT_EQ(s[2].get(d), "angle");
  // The paper's preset, and back; the holes and limits stay.
  MeshFillOptions p;
  p.maxBoundary = 77;
  setOption(s, p, "mode", "paper");
  EXPECT_TRUE(isPaperPipeline(p));
  EXPECT_EQ(p.fairing.closenessScale, 0.1);
  EXPECT_EQ(p.shape.order, 0);
  EXPECT_FALSE(p.checkCrossings);
  EXPECT_EQ(p.maxBoundary, 77);
  EXPECT_EQ(s[0].get(p), "paper");
  setOption(s, p, "fairIterations", "5");
  EXPECT_EQ(s[0].get(p), "ours");  // changed past the paper's: not the paper's any more
  setOption(s, p, "mode", "ours");
  EXPECT_EQ(p.fairing.closenessScale, d.fairing.closenessScale);
  EXPECT_EQ(p.maxBoundary, 77);
  MeshFillOptions o;
  EXPECT_THROW(setOption(s, o, "shapeOrder", "4"), Error);
  EXPECT_THROW(setOption(s, o, "triangulation", "delaunay"), Error);
  EXPECT_THROW(setOption(s, o, "weld", "-1e-6"), Error);
}
