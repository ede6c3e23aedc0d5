#include <gtest/gtest.h>

#include <random>

#include "expect_error.h"
#include "geometry/error.h"
#include "geometry/json_reader.h"
#include "gnurbs/gnurbs_build.h"
#include "test_cages.h"

using namespace holefill;
using namespace holefill::testcages;

// The pipeline is the stages it chains, nothing more: the same patches, faces and continuity as
// building and exporting by hand, and one report that says so.
TEST(GnurbsBuild, IsTheBuildTheExportAndTheMeasurementInOneCall) {
  const QuadCage cage = polarCage(5, 3);
  GnurbsBuildOptions o;
  o.brep.mergeRegular = true;
  const GnurbsBuildResult r = buildGnurbs(cage, o);
  const G2GnurbsResult byHand = buildG2Gnurbs(cage);
  GnurbsBrepOptions bo;
  bo.mergeRegular = true;
  const GnurbsBrep brep = gnurbsToBrep(byHand, bo);
  EXPECT_EQ(r.surface.patches.size(), byHand.patches.size());
  EXPECT_EQ(r.brep.faces, brep.faces);
  EXPECT_EQ(r.brep.mergedFaces, brep.mergedFaces);
  EXPECT_TRUE(r.brep.valid);
  EXPECT_TRUE(r.sound());
  EXPECT_TRUE(r.warnings().empty());
  EXPECT_EQ(r.outcome().status, Status::Ok);
  EXPECT_FALSE(r.fit);
  EXPECT_TRUE(r.cage.vertices.isApprox(cage.vertices));
  const GnurbsContinuity c = measureGnurbsContinuity(byHand);
  EXPECT_EQ(r.continuity.edges, c.edges);
  EXPECT_NEAR(r.continuity.g1Spokes, c.g1Spokes, 1e-12);
  const JsonValue j = parseJson(r.toJson());
  ASSERT_NE(j.find("brep"), nullptr);
  EXPECT_TRUE(j.find("brep")->find("valid")->boolean);
  EXPECT_EQ(j.find("fit"), nullptr);  // no target, no fit
  EXPECT_EQ(j.find("status")->string, "ok");
  EXPECT_EQ(static_cast<int>(j.find("patches")->number), static_cast<int>(byHand.patches.size()));
}

// With a target the cage moves to it: the points sampled from a cage the start was perturbed
// from are met again, and the report carries the fit's distances and the moved cage.
TEST(GnurbsBuild, AFitToATargetMovesTheCageAndReportsTheDistances) {
  const QuadCage truth = polarCage(5, 3);
  const G2GnurbsResult t = buildG2Gnurbs(truth);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  Eigen::MatrixX3d target(static_cast<Eigen::Index>(t.patches.size()) * 10, 3);
  Eigen::Index k = 0;
  for (const auto& p : t.patches)
    for (int i = 0; i < 10; ++i) target.row(k++) = p.surface.point(U(rng), U(rng)).transpose();
  QuadCage start = truth;
  std::normal_distribution<double> N(0, 0.04);
  for (Eigen::Index v = 0; v < start.vertices.rows(); ++v) start.vertices(v, 2) += N(rng);
  GnurbsBuildOptions o;
  o.fit.iterations = 4;
  const GnurbsBuildResult r = buildGnurbs(start, o, &target);
  ASSERT_TRUE(r.fit);
  EXPECT_EQ(r.fit->points, target.rows());
  EXPECT_LT(r.fit->dMax, 1e-3);
  EXPECT_FALSE(r.cage.vertices.isApprox(start.vertices));              // moved
  EXPECT_LT((r.cage.vertices - truth.vertices).cwiseAbs().maxCoeff(), 0.02 * diagonal(truth));
  EXPECT_TRUE(r.brep.valid);
  const JsonValue j = parseJson(r.toJson());
  ASSERT_NE(j.find("fit"), nullptr);
  EXPECT_EQ(static_cast<int>(j.find("fit")->find("points")->number), target.rows());
  EXPECT_NEAR(j.find("fit")->find("d_max_percent")->number, 100 * r.fit->dMax, 1e-9);
}

TEST(GnurbsBuild, BadTargetsAndRoundsAreRefusedByName) {
  const QuadCage cage = polarCage(5, 2);
  const Eigen::MatrixX3d none(0, 3);
  EXPECT_THROW(buildGnurbs(cage, {}, &none), Error);
  Eigen::MatrixX3d bad = Eigen::MatrixX3d::Random(20, 3);
  bad(4, 1) = std::nan("");
  EXPECT_THROW(buildGnurbs(cage, {}, &bad), Error);
  GnurbsBuildOptions o;
  o.fit.iterations = -1;
  const Eigen::MatrixX3d fine = Eigen::MatrixX3d::Random(20, 3);
  expectErrorNaming([&] { buildGnurbs(cage, o, &fine); }, "rounds");
}
