#include <gtest/gtest.h>

#include <TopExp_Explorer.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <cmath>
#include <random>

#include "expect_error.h"
#include "fitting/point_cloud_fit.h"
#include "geometry/error.h"
#include "geometry/json_reader.h"

using namespace holefill;

namespace {

// A wavy height field over the unit square sampled at jittered grid points: bare x y z (no
// flags) unless `flagged`, then its square's edge points flagged with their (u, v).
FlaggedCloud wavyCloud(bool flagged, int n = 30) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> J(-0.3, 0.3);
  FlaggedCloud c;
  c.points.resize(n * n, 3);
  c.uv = Eigen::MatrixX2d::Zero(n * n, 2);
  c.boundary.assign(n * n, false);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const bool edge = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      const double u = (i + (edge ? 0 : J(rng))) / (n - 1), v = (j + (edge ? 0 : J(rng))) / (n - 1);
      const int k = i * n + j;
      c.points.row(k) << 4 * u, 4 * v, 0.3 * std::sin(2 * u) * std::cos(1.5 * v);
      if (edge) {
        c.boundary[k] = true;
        c.uv.row(k) << u, v;
      }
    }
  c.flagsGiven = flagged;
  c.boundaryUVGiven = flagged;
  if (!flagged) {
    c.boundary.clear();
    c.uv.setZero();
  }
  return c;
}

int faceCount(const TopoDS_Shape& s) {
  int n = 0;
  for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) ++n;
  return n;
}

}  // namespace

// A flagged cloud keeps its boundary and its parameters; the fit meets the tolerance and the
// report is one object with every stage's fields.
TEST(PointCloudFit, AFlaggedCloudIsFittedWithinTheTolerance) {
  const FlaggedCloud c = wavyCloud(true);
  PointCloudFitOptions o;
  o.fit.relativeTolerance = 1e-3;
  const PointCloudFitResult r = fitPointCloud(c, o);
  EXPECT_EQ(r.completion.found, -1);
  EXPECT_FALSE(r.completion.chord);
  EXPECT_EQ(r.cloud.boundary, c.boundary);
  EXPECT_TRUE(r.fit.metTolerance);
  EXPECT_LE(r.fit.errors.maxCoeff(), 1e-3);
  EXPECT_EQ(faceCount(r.shape), 1);
  EXPECT_EQ(r.fit.folds, 0);
  const JsonValue j = parseJson(r.toJson());
  ASSERT_NE(j.find("parameterization"), nullptr);
  EXPECT_EQ(j.find("parameterization")->find("method")->string, "shape");
  EXPECT_EQ(j.find("boundary_found")->number, -1);
  EXPECT_TRUE(j.find("met_tolerance")->boolean);
  EXPECT_EQ(j.find("iterations")->array.size(), r.fit.history.size());
  EXPECT_EQ(j.find("warnings")->type, JsonValue::Type::Array);
  EXPECT_EQ(j.find("status")->string, "ok");
  // A tolerance no fit of this cloud meets in one iteration: written, the goal missed.
  PointCloudFitOptions strict;
  strict.fit.relativeTolerance = 1e-9;
  strict.fit.maxIterations = 1;
  const Outcome missed = fitPointCloud(c, strict).outcome();
  EXPECT_EQ(missed.status, Status::Warned);
  EXPECT_NE(missed.message.find("tolerance NOT met"), std::string::npos) << missed.message;
}

// A tolerance in the cloud's units replaces the relative one: the fit aims at it, and reports
// both; a cloud scaled by 10 with its tolerance scaled alike fits to the same relative goal.
TEST(PointCloudFit, AToleranceInModelUnitsReplacesTheRelativeOne) {
  FlaggedCloud c = wavyCloud(true);
  const double diagonal = (c.points.colwise().maxCoeff() - c.points.colwise().minCoeff()).norm();
  PointCloudFitOptions o;
  o.tolerance = 2e-3 * diagonal;
  o.fit.relativeTolerance = 0.5;  // ignored where a tolerance is given
  const PointCloudFitResult r = fitPointCloud(c, o);
  EXPECT_NEAR(r.fit.relativeTolerance, 2e-3, 1e-15);
  EXPECT_TRUE(r.fit.metTolerance);
  EXPECT_LE(r.fit.errors.maxCoeff() * r.fit.diagonal, o.tolerance);
  const JsonValue j = parseJson(r.toJson());
  EXPECT_NEAR(j.find("tolerance")->number, o.tolerance, 1e-12);
  EXPECT_NEAR(j.find("relative_tolerance")->number, 2e-3, 1e-15);
  c.points *= 10;
  o.tolerance *= 10;
  EXPECT_NEAR(fitPointCloud(c, o).fit.relativeTolerance, 2e-3, 1e-15);
  // Not adaptive: one uniform level, whatever the tolerance.
  o.adaptive = false;
  o.tolerance = 1e-9;
  EXPECT_EQ(fitPointCloud(c, o).fit.space.levels(), 1);
}

// A bare cloud gets its boundary found and parameterized by chord length: the square's edge
// points, and four corners at the unit square's corners.
TEST(PointCloudFit, ABareCloudGetsItsBoundaryFoundAndChordParameters) {
  PointCloudFitOptions o;
  o.fit.relativeTolerance = 2e-3;
  o.cellFaces = true;
  const PointCloudFitResult r = fitPointCloud(wavyCloud(false), o);
  EXPECT_GT(r.completion.found, 100);  // the 116 edge points of the 30 × 30 grid, give or take the alpha shape's
  EXPECT_GT(r.completion.spacing, 0);
  EXPECT_TRUE(r.completion.chord);
  int corners = 0;
  for (Eigen::Index k = 0; k < r.cloud.uv.rows(); ++k)
    if (r.cloud.boundary[k] && (r.cloud.uv.row(k) - r.cloud.uv.row(k).array().round().matrix()).norm() < 1e-12) ++corners;
  EXPECT_EQ(corners, 4);
  EXPECT_TRUE(r.fit.metTolerance);
  EXPECT_EQ(faceCount(r.shape), static_cast<int>(r.fit.space.leafCells().size()));
  EXPECT_GT(parseJson(r.toJson()).find("boundary_found")->number, 100);
}

// Options out of range are refused before any stage runs, with the option named.
TEST(PointCloudFit, OptionsOutOfRangeAreRefusedByName) {
  const FlaggedCloud c = wavyCloud(true, 12);
  const auto refused = [&](const PointCloudFitOptions& o, const char* word) { expectErrorNaming([&] { fitPointCloud(c, o); }, word); };
  PointCloudFitOptions o;
  o.fit.degree = 8;
  refused(o, "degree");
  o = {};
  o.fit.relativeTolerance = 0;
  refused(o, "relative tolerance");
  o = {};
  o.tolerance = -1;
  refused(o, "tolerance");
  o = {};
  o.fit.baseCells = 0;
  refused(o, "cell");
  o = {};
  o.fit.maxIterations = 0;
  refused(o, "iteration");
}

// completeCloudBoundary's `rechord` replaces given parameters (the CLI's --corners does): the
// square's edge points come back where they were, up to the square's symmetries (which corner
// goes first follows the best-fit plane) and the edges' waves (chord length is measured in 3D).
TEST(PointCloudFit, RechordReplacesGivenBoundaryParameters) {
  FlaggedCloud c = wavyCloud(true, 12);
  const Eigen::MatrixX2d truth = c.uv;
  c.uv *= 0.5;  // wrong on purpose
  const CloudBoundaryCompletion done = completeCloudBoundary(c, {0, 11, 143, 132}, true);
  EXPECT_TRUE(done.chord);
  EXPECT_EQ(done.found, -1);
  double best = 1e9;
  for (int swap = 0; swap < 2; ++swap)
    for (int fu = 0; fu < 2; ++fu)
      for (int fv = 0; fv < 2; ++fv) {
        double worst = 0;
        for (Eigen::Index k = 0; k < c.uv.rows(); ++k) {
          if (!c.boundary[k]) continue;
          double u = truth(k, swap), v = truth(k, 1 - swap);
          if (fu) u = 1 - u;
          if (fv) v = 1 - v;
          worst = std::max(worst, (c.uv.row(k) - Eigen::RowVector2d(u, v)).norm());
        }
        best = std::min(best, worst);
      }
  EXPECT_LT(best, 1e-2);  // given: off by 0.5 and more
}
