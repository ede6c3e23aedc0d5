#include <gtest/gtest.h>

#include "geometry/json_reader.h"
#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/gnurbs_report.h"
#include "gnurbs/sample_cages.h"
#include "test_cages.h"

using namespace holefill;
using namespace holefill::testcages;

// The continuity measure sees what the surface does: ours is G² across every cage edge, and the
// same surface with one face lifted by δ shows a G0 gap of δ over the cage's diagonal there.
TEST(GnurbsReport, ContinuityMeasuresOursAsG2AndALiftedFaceAsItsGap) {
  const G2GnurbsResult r = buildG2Gnurbs(cages::polarCage(5, 2));
  const FaceJetFunction exact = faceJets(r);
  const GnurbsContinuity ours = measureCageContinuity(r.cage, exact);
  EXPECT_GT(ours.edges, 0);
  EXPECT_GT(ours.spokeEdges, 0);
  EXPECT_LT(ours.g0, 1e-10);
  EXPECT_LT(ours.g1Spokes, 1e-8);
  EXPECT_LT(ours.g2Spokes, 1e-6);
  const double delta = 0.01;
  const GnurbsContinuity lifted = measureCageContinuity(r.cage, [&](int f, double u, double v) {
    SurfaceJet j = exact(f, u, v);
    if (f == 0) j.p.z() += delta;
    return j;
  });
  EXPECT_NEAR(lifted.g0, delta / diagonal(r.cage), 1e-9);
}

// The report holds the construction, the continuity, the B-rep checks, a fit's distances and the
// outcome when given, as one JSON object.
TEST(GnurbsReport, TheReportCarriesEachPartWhenGiven) {
  const G2GnurbsResult r = buildG2Gnurbs(cages::polarCage(3, 2));
  const GnurbsContinuity c = measureGnurbsContinuity(r);
  const JsonValue bare = parseJson(gnurbsReportJson(r, c, nullptr, 0.5));
  EXPECT_EQ(bare.find("extraordinary_points")->array.size(), 1u);
  EXPECT_EQ(bare.find("brep"), nullptr);
  EXPECT_EQ(bare.find("fit"), nullptr);
  EXPECT_EQ(bare.find("status"), nullptr);
  EXPECT_EQ(bare.find("continuity")->find("edges")->number, c.edges);
  GnurbsFitResult fit;
  fit.points = 40;
  fit.dMax = 0.002;
  Outcome warned;
  warned.status = Status::Warned;
  const JsonValue full = parseJson(gnurbsReportJson(r, c, nullptr, 0.5, &fit, &warned));
  EXPECT_EQ(full.find("fit")->find("points")->number, 40);
  EXPECT_NEAR(full.find("fit")->find("d_max_percent")->number, 0.2, 1e-12);
  EXPECT_EQ(full.find("status")->string, "warned");
}
