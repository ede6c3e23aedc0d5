#include <gtest/gtest.h>

#include "expect_error.h"

#include "fitting/labeled_fit.h"
#include "geometry/error.h"
#include "geometry/surface_projection.h"
#include "mesh/mesh_holes.h"
#include "test_regions.h"

#include <cmath>
#include <functional>
#include <random>

using namespace holefill;

TEST(LabeledFit, ParsesLabelsAndRunsEndToEndOnAFlatRectangle) {
  const auto labels = parseLabelsJson(R"({"segments": [{"label": "S", "vertices": [0, 1, 2]}, {"label": "North", "vertices": [8, 7, 6]}]})");
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_EQ(labels[0].side, Side::South);
  EXPECT_EQ(labels[1].side, Side::North);
  EXPECT_EQ(labels[1].vertices, (std::vector<int>{8, 7, 6}));
  EXPECT_THROW(parseLabelsJson(R"({"segments": [{"label": "S", "vertices": [0, 1.5]}]})"), Error);
  EXPECT_THROW(parseLabelsJson(R"({"segments": [{"vertices": [0, 1]}]})"), Error);
  EXPECT_THROW(parseLabelsJson(R"([1, 2])"), Error);

  // A flat 3×3-vertex square labeled S and N: parameterized, extended, fitted, trimmed.
  TriangleMesh m;
  m.vertices.resize(9, 3);
  for (int v = 0; v < 9; ++v) m.vertices.row(v) << v % 3, v / 3, 0;
  m.triangles.resize(8, 3);
  m.triangles << 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7;
  LabeledFitOptions o;
  o.fit.controlU = o.fit.controlV = 4;
  const LabeledFitResult r = fitLabeled(m, labels, o);
  EXPECT_NEAR(r.parameterization.width, 2, 1e-6);
  EXPECT_NEAR(r.parameterization.height, 2, 1e-6);
  EXPECT_LT(r.fit.dataMax, 1e-9);  // a plane is fitted exactly
  EXPECT_TRUE(r.fit.valid);
  EXPECT_NE(r.toJson().find("\"weak_control_points\""), std::string::npos);
}

// Issue 21, never a crash: random small regions (unions of random disks over a grid, lifted onto a
// random quadric, in either orientation) with their boundary split into four labeled runs at random
// corners. Each must give a face or a holefill::Error, never a crash and never another exception.
// One check of the options for every door: each range is refused with the option named, before
// any stage runs (the region here is never looked at).
TEST(LabeledFit, OptionsOutOfRangeAreRefusedByName) {
  const auto refused = [](const LabeledFitOptions& o, const char* word) { expectErrorNaming([&] { checkLabeledFitOptions(o); }, word); };
  EXPECT_NO_THROW(checkLabeledFitOptions({}));
  LabeledFitOptions o;
  o.relativeTolerance = 0;
  refused(o, "relative tolerance");
  o = {};
  o.tolerance = -1;
  refused(o, "tolerance");
  o = {};
  o.fit.controlU = 3;
  refused(o, "at least 4 control points");
  o = {};
  o.fit.controlU = 30;
  o.maxControl = 20;
  refused(o, "maxControl");
  o.maxControl = 0;  // exactly the start's
  EXPECT_NO_THROW(checkLabeledFitOptions(o));
  o = {};
  o.fit.smoothing = -1e-6;
  refused(o, "weights");
  o = {};
  o.extension.fairness = -1;
  refused(o, "weights");
  o = {};
  o.reach = 11;
  refused(o, "reach");
  o = {};
  o.extension.meshFairness = 1e-2;  // with the sampled extension, the default
  refused(o, "ask for extension G2 or G1");
  setExtensionByName(o, "G2");
  EXPECT_NO_THROW(checkLabeledFitOptions(o));
  const TriangleMesh nothing;
  EXPECT_THROW(fitLabeled(nothing, {}, [] { LabeledFitOptions b; b.tolerance = -1; return b; }()), Error);
}

TEST(LabeledFit, RandomRegionsAndLabelSplitsGiveAFaceOrAClearError) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int faces = 0, errors = 0;
  for (int round = 0; round < 40; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const int disks = 1 + static_cast<int>(unit(rng) * 3);
    std::vector<Eigen::Vector3d> d;  // centre x, y and radius, in [0, 1]
    for (int k = 0; k < disks; ++k) d.emplace_back(0.25 + 0.5 * unit(rng), 0.25 + 0.5 * unit(rng), 0.15 + 0.2 * unit(rng));
    const double a = unit(rng) - 0.5, b = unit(rng) - 0.5, c = unit(rng) - 0.5;
    Eigen::MatrixX2d uv;
    TriangleMesh region = testregions::gridRegion(
        16, 16, 1.0 / 16,
        [&](double x, double y) {
          for (const auto& q : d)
            if (std::hypot(x - q.x(), y - q.y()) < q.z()) return true;
          return false;
        },
        [&](double x, double y) { return Eigen::Vector3d(x, y, a * x * x + b * x * y + c * y * y); }, uv);
    if (region.triangles.rows() < 2) continue;
    if (round % 2) region.triangles.col(1).swap(region.triangles.col(2));
    try {
      const MeshHoleReport holes = findMeshHoles(region);
      if (holes.holes.empty()) continue;
      const std::vector<int>& loop = holes.holes[0].loop;
      const int n = static_cast<int>(loop.size());
      std::vector<int> cut;
      for (int k = 0; k < 4; ++k) cut.push_back(static_cast<int>(unit(rng) * n));
      std::sort(cut.begin(), cut.end());
      std::vector<LabeledSegment> labels;
      for (int k = 0; k < 4; ++k) {
        LabeledSegment seg{static_cast<Side>(k), {}};
        for (int i = cut[k];; i = (i + 1) % n) {
          seg.vertices.push_back(loop[i]);
          if (i == cut[(k + 1) % 4]) break;
        }
        labels.push_back(seg);
      }
      LabeledFitOptions o;
      o.fit.controlU = o.fit.controlV = 8;
      const LabeledFitResult r = fitLabeled(region, labels, o);
      EXPECT_TRUE(r.fit.surface.poles.allFinite());
      ++faces;
    } catch (const Error&) {
      ++errors;  // a clear refusal is an answer
    }
  }
  std::printf("random regions: %d faces, %d clear errors\n", faces, errors);
  EXPECT_GT(faces, 0);
}

namespace {

double fitDataMax(const TriangleMesh& region, const std::vector<LabeledSegment>& labels, double releaseDepth, LabeledFitResult* out = nullptr) {
  LabeledFitOptions o;
  o.maxControl = 0;  // 12 x 12 exactly: the map, not the control points, is under test
  o.relaxLabels = false;
  o.parameterization.releaseDepth = releaseDepth;
  LabeledFitResult r = fitLabeled(region, labels, o);
  if (out) *out = r;
  return r.fit.dataMax;
}

bool warns(const LabeledFitResult& r, const std::string& what) {
  for (const auto& w : r.allWarnings())
    if (w.find(what) != std::string::npos) return true;
  return false;
}

Eigen::Vector3d halfCylinder(double x, double y) { return {3 * std::cos(M_PI * x), 3 * std::sin(M_PI * x), 10 * y}; }

// The bitten half cylinder several tests share: 40 × 40 cells of 0.025, the corner within 0.55
// of (1, 1) cut away, labeled by the corpus's bounding-box rule.
TriangleMesh bittenHalfCylinder(std::vector<LabeledSegment>& labels) {
  Eigen::MatrixX2d truth;
  const TriangleMesh region =
      testregions::gridRegion(40, 40, 0.025, [](double x, double y) { return std::hypot(x - 1, y - 1) > 0.55; }, halfCylinder, truth);
  labels = testregions::boundingBoxLabels(region, truth);
  return region;
}

}  // namespace

// The corpus's failure classes (issue 21): labels by the bounding-box rule run round a notch, a
// slot or an L's missing quarter, which held on the rectangle's sides made the map singular there
// (data max 1.9e-2 on the corpus's bitten half cylinder). Left free, the map is the surface's own
// and a 12 x 12 fit meets the data far better. On the grid's staircase boundaries (a bite or a
// crescent cut from grid cells) every step turns 90°: what is left free there must at least not
// make the fit worse than holding every label.
TEST(LabeledFit, ConcaveLShapeUSlotBittenCornerAndCrescentAreLeftFreeAndFit) {
  struct Case {
    const char* name;
    std::function<bool(double, double)> inside;
    bool straightBoundary;
  };
  for (const Case& c : {Case{"L-shape", [](double x, double y) { return x < 0.5 || y < 0.5; }, true},
                        Case{"U-slot", [](double x, double y) { return !(x > 0.35 && x < 0.65 && y > 0.3); }, true},
                        Case{"bitten corner", [](double x, double y) { return std::hypot(x - 1, y - 1) > 0.55; }, false},
                        Case{"crescent", [](double x, double y) { return std::hypot(x - 0.5, y - 0.5) < 0.5 && std::hypot(x - 0.75, y - 0.5) > 0.35; },
                             false}}) {
    SCOPED_TRACE(c.name);
    Eigen::MatrixX2d truth;
    const TriangleMesh region = testregions::gridRegion(25, 25, 0.04, c.inside, halfCylinder, truth);
    const std::vector<LabeledSegment> labels = testregions::boundingBoxLabels(region, truth);
    LabeledFitResult freed;
    const double released = fitDataMax(region, labels, 0.05, &freed);
    const double held = fitDataMax(region, labels, -1);
    EXPECT_LE(released, held * (1 + 1e-9));
    if (!c.straightBoundary) continue;
    // Measured: L 3.2e-2 -> 4.1e-3, U-slot 1.3e-1 -> 2.5e-5.
    EXPECT_TRUE(warns(freed, "left free"));
    EXPECT_FALSE(warns(freed, "held again"));
    EXPECT_LT(released, 0.2 * held);
  }
}

// A bitten corner of a half cylinder with scan noise of 0.2% of the diagonal: the G2 extension
// of the noisy boundary into the thin strips the free arc leaves at the rectangle's rim swung far
// off (the fit then missed the data by 0.31 of the diagonal). The extension is tried at G1 then,
// or left out, and the fit never misses the data by more than twice the fit without extension.
TEST(LabeledFit, AnExtensionThatPullsTheFitOffNoisyDataIsLoweredOrLeftOut) {
  std::vector<LabeledSegment> labels;
  TriangleMesh region = bittenHalfCylinder(labels);
  testregions::addNoise(region, 0.002, 7);
  // The paper's continuation carries the noise out (a Cauchy problem), and the guard catches it.
  LabeledFitOptions o;
  o.extensionSource = LabeledFitOptions::ExtensionSource::Continuation;
  const LabeledFitResult r = fitLabeled(region, labels, o);
  o.extend = false;
  const LabeledFitResult bare = fitLabeled(region, labels, o);
  // The default extension, sampled from a thin-plate fit of the region, has nothing to carry out.
  const LabeledFitResult fitted = fitLabeled(region, labels, LabeledFitOptions{});
  std::printf("noisy bitten corner: data max %.2e (continuation), %.2e (fitted extension), %.2e without extension\n", r.fit.dataMax,
              fitted.fit.dataMax, bare.fit.dataMax);
  EXPECT_TRUE(warns(r, "pulled the fit off"));
  EXPECT_LT(r.fit.dataMax, 2 * bare.fit.dataMax);
  EXPECT_TRUE(r.fit.valid);
  EXPECT_FALSE(warns(fitted, "pulled the fit off"));
  EXPECT_GT(fitted.extension.mesh.vertices.rows(), region.vertices.rows());
  EXPECT_LT(fitted.fit.dataMax, 1.2 * bare.fit.dataMax);
  EXPECT_TRUE(fitted.fit.valid);
  // Mesh fairness shapes only the continuation: on the fitted extension it is refused.
  LabeledFitOptions withFairness;
  withFairness.extension.meshFairness = 1e-2;
  EXPECT_THROW(fitLabeled(region, labels, withFairness), Error);
}

// A side that bends smoothly away from its line (a disk's quarter arcs, meshed in rings so that
// the boundary is a smooth polygon) is held as labeled: the labels say where the sides run, and
// only a sharp turn marks a notch.
TEST(LabeledFit, SmoothlyRoundedSidesAreHeldAsLabeled) {
  const int rings = 12, sectors = 96;
  TriangleMesh region;
  Eigen::MatrixX2d truth(1 + rings * sectors, 2);
  truth.row(0) << 0.5, 0.5;
  for (int r = 1; r <= rings; ++r)
    for (int k = 0; k < sectors; ++k) {
      const double a = 2 * M_PI * k / sectors, rad = 0.45 * r / rings;
      truth.row(1 + (r - 1) * sectors + k) << 0.5 + rad * std::cos(a), 0.5 + rad * std::sin(a);
    }
  std::vector<Eigen::Vector3i> tris;
  for (int k = 0; k < sectors; ++k) tris.emplace_back(0, 1 + k, 1 + (k + 1) % sectors);
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < sectors; ++k) {
      const int a = 1 + (r - 1) * sectors + k, b = 1 + (r - 1) * sectors + (k + 1) % sectors, c = a + sectors, d = b + sectors;
      tris.emplace_back(a, c, d);
      tris.emplace_back(a, d, b);
    }
  region.vertices.resize(truth.rows(), 3);
  for (Eigen::Index v = 0; v < truth.rows(); ++v) region.vertices.row(v) = halfCylinder(truth(v, 0), truth(v, 1)).transpose();
  region.triangles.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (size_t t = 0; t < tris.size(); ++t) region.triangles.row(static_cast<Eigen::Index>(t)) = tris[t].transpose();
  LabeledFitResult r;
  fitDataMax(region, testregions::boundingBoxLabels(region, truth), 0.05, &r);
  EXPECT_FALSE(warns(r, "left free"));
  EXPECT_EQ(r.parameterization.flippedTriangles, 0);
}

namespace {

// A unit square of a wavy field (0.15 sin 9x cos 7y) on a 30 × 30 grid, labeled by its box: more
// than 5 × 5 control points can follow, and 1e-3 takes more than 12 × 12.
TriangleMesh wavySquare(std::vector<LabeledSegment>& labels) {
  Eigen::MatrixX2d truth;
  TriangleMesh region = testregions::gridRegion(
      30, 30, 1.0 / 30, [](double, double) { return true; },
      [](double x, double y) { return Eigen::Vector3d(x, y, 0.15 * std::sin(9 * x) * std::cos(7 * y)); }, truth);
  labels = testregions::boundingBoxLabels(region, truth);
  return region;
}

}  // namespace

// Control points chosen by the data: refined while the data max is above the tolerance, each try
// reported; --ctrl-style exact counts when maxControl is 0.
TEST(LabeledFit, ControlPointsAreRefinedUntilTheDataIsMet) {
  std::vector<LabeledSegment> labels;
  const TriangleMesh region = wavySquare(labels);
  LabeledFitOptions o;
  o.fit.controlU = o.fit.controlV = 5;
  o.maxControl = 0;
  const LabeledFitResult exact = fitLabeled(region, labels, o);
  EXPECT_EQ(exact.fit.surface.numU(), 5);
  EXPECT_EQ(exact.refinements.size(), 1u);
  EXPECT_GT(exact.fit.dataMax, 1e-3);
  o.maxControl = 40;
  const LabeledFitResult refined = fitLabeled(region, labels, o);
  EXPECT_GT(refined.fit.surface.numU(), 5);
  EXPECT_GT(refined.refinements.size(), 1u);
  EXPECT_LT(refined.fit.dataMax, 1e-3);
  EXPECT_EQ(refined.fit.weakControlPoints, 0);
  EXPECT_LT(refined.fit.log10Condition, 8);
  // The same goal in the region's own units refines alike; the relative one is then ignored.
  const double diagonal = (region.vertices.colwise().maxCoeff() - region.vertices.colwise().minCoeff()).norm();
  o.tolerance = 1e-3 * diagonal;
  o.relativeTolerance = 0.5;
  const LabeledFitResult units = fitLabeled(region, labels, o);
  EXPECT_EQ(units.fit.surface.numU(), refined.fit.surface.numU());
  EXPECT_EQ(units.refinements, refined.refinements);
}

// Where the control net stops at its cap with the data still missed, knots go where the fit
// misses: a narrow bump in one corner of a flat square, which 8 × 8 uniform control points cut
// off, is followed by knots inserted around it, the spans there narrower than elsewhere.
TEST(LabeledFit, KnotsAreInsertedWhereTheFitStillMissesAtItsCap) {
  Eigen::MatrixX2d truth;
  const TriangleMesh region = testregions::gridRegion(
      40, 40, 1.0 / 40, [](double, double) { return true; },
      [](double x, double y) { return Eigen::Vector3d(x, y, 0.05 * std::exp(-(std::pow(x - 0.75, 2) + std::pow(y - 0.3, 2)) / 0.004)); }, truth);
  const std::vector<LabeledSegment> labels = testregions::boundingBoxLabels(region, truth);
  LabeledFitOptions o;
  o.fit.controlU = o.fit.controlV = 6;
  o.maxControl = 8;
  o.localRefinements = 0;
  const LabeledFitResult capped = fitLabeled(region, labels, o);
  o.localRefinements = 8;
  const LabeledFitResult local = fitLabeled(region, labels, o);
  EXPECT_GT(capped.fit.dataMax, 1e-3);
  EXPECT_LT(local.fit.dataMax, 0.5 * capped.fit.dataMax) << local.refinements.back();
  EXPECT_GT(local.refinementsKept, capped.refinementsKept);
  EXPECT_EQ(local.fit.weakControlPoints, 0);
  const auto spans = [](const std::vector<double>& k) {
    double lo = 1e300, hi = 0;
    for (size_t i = 4; i + 4 < k.size() + 1; ++i)
      if (k[i] > k[i - 1]) lo = std::min(lo, k[i] - k[i - 1]), hi = std::max(hi, k[i] - k[i - 1]);
    return hi / lo;
  };
  EXPECT_GT(spans(local.fit.surface.knotsU), 1.5);  // not uniform: split where the bump is
}

// Control points stop being added where what the fit leaves is the scan noise (the discrepancy
// principle): the region's noise is estimated from the mesh alone, and a fit whose data rms is
// within 1.5 times it is kept. The same region clean is refined further, while its max falls.
TEST(LabeledFit, RefinementStopsWhereWhatIsLeftIsScanNoise) {
  std::vector<LabeledSegment> labels;
  TriangleMesh region = bittenHalfCylinder(labels);
  LabeledFitOptions o;
  o.fit.controlU = o.fit.controlV = 5;
  const LabeledFitResult clean = fitLabeled(region, labels, o);
  testregions::addNoise(region, 0.002, 11);
  const LabeledFitResult noisy = fitLabeled(region, labels, o);
  std::printf("bitten half cylinder from 5x5: clean %dx%d (noise %.1e), 0.2%% noise %dx%d (noise estimated %.2e), data rms %.2e\n",
              clean.fit.surface.numU(), clean.fit.surface.numV(), clean.noise, noisy.fit.surface.numU(), noisy.fit.surface.numV(), noisy.noise,
              noisy.fit.dataRms);
  EXPECT_LT(clean.noise, 1e-5);
  EXPECT_NEAR(noisy.noise, 0.002, 0.0003);
  EXPECT_NE(noisy.refinements.back().find("scan noise"), std::string::npos) << noisy.refinements.back();
  EXPECT_LE(noisy.fit.dataRms, 1.5 * noisy.noise);
  EXPECT_LE(noisy.dataBias, noisy.noise);
  for (const std::string& line : clean.refinements) std::printf("  clean: %s\n", line.c_str());
  // Clean, the misses are local (the bite's ends) and hardly move the rms, where an earlier rule
  // stopped, reading them as noise: refined on while the max falls (5x5 → 8x8 reaches 9.3e-4 since
  // the extension is sampled at each refinement's control points; 12x12 was needed before).
  EXPECT_GT(clean.fit.surface.numU(), 5);
  EXPECT_LT(clean.fit.dataMax, 1e-3);
  EXPECT_GT(clean.fit.surface.numU() * clean.fit.surface.numV(), noisy.fit.surface.numU() * noisy.fit.surface.numV());
}

// Refinement past noisyMaxControl is for clean regions only: where scan noise could be what the
// fit misses, more control points follow it (bspline_notch_n0p05: 1.78e-3 off the truth at 40 × 40,
// 3.05e-3 at 48 × 48). The same wavy field, clean and under 0.2% noise, asked for more than
// either can give at the default tolerance: the clean one is refined to maxControl, the noisy one
// stops at noisyMaxControl.
TEST(LabeledFit, UnderNoiseRefinementStopsAtNoisyMaxControlAndCleanGoesOn) {
  std::vector<LabeledSegment> labels;
  TriangleMesh region = wavySquare(labels);
  LabeledFitOptions o;
  o.fit.controlU = o.fit.controlV = 5;
  o.noisyMaxControl = 8;
  o.maxControl = 12;
  o.localRefinements = 0;  // the clean one would go on with knots where it misses (the next tests)
  const LabeledFitResult clean = fitLabeled(region, labels, o);
  testregions::addNoise(region, 0.002, 3);
  const LabeledFitResult noisy = fitLabeled(region, labels, o);
  for (const std::string& line : clean.refinements) std::printf("  clean: %s (noise %.2e)\n", line.c_str(), clean.noise);
  for (const std::string& line : noisy.refinements) std::printf("  noisy: %s\n", line.c_str());
  EXPECT_EQ(std::max(clean.fit.surface.numU(), clean.fit.surface.numV()), 12);
  EXPECT_LE(std::max(noisy.fit.surface.numU(), noisy.fit.surface.numV()), 8);
  EXPECT_NE(noisy.refinements.back().find("8 control points per direction at most under scan noise"), std::string::npos)
      << noisy.refinements.back();
}

namespace {

// A 4 × 2 plate (80 × 40 grid cells) with a Gaussian bump of `height` and width `width` at
// (2.7, 1.1), under 0.05% scan noise, labeled by the bounding-box rule; truthMiss: the fit's
// largest distance to the noise-free vertices, of the diagonal.
struct BumpedPlate {
  TriangleMesh truth, region;
  std::vector<LabeledSegment> labels;
  BumpedPlate(double height, double width) {
    Eigen::MatrixX2d uv;
    const auto z = [=](double u, double v) { return height * std::exp(-(std::pow(u - 2.7, 2) + std::pow(v - 1.1, 2)) / (2 * width * width)); };
    truth = testregions::gridRegion(80, 40, 0.05, [](double, double) { return true; },
                                    [&](double u, double v) { return Eigen::Vector3d(u, v, z(u, v)); }, uv);
    region = truth;
    testregions::addNoise(region, 0.0005, 5);
    labels = testregions::boundingBoxLabels(region, uv);
  }
  double truthMiss(const LabeledFitResult& r) const {
    const double diagonal = boundingDiagonal(truth.vertices);
    double worst = 0;
    for (Eigen::Index i = 0; i < truth.vertices.rows(); ++i) {
      Eigen::Vector2d at = r.fit.regionUV.row(i).transpose();
      worst = std::max(worst, projectPointFrom(r.fit.surface, truth.vertices.row(i).transpose(), at) / diagonal);
    }
    return worst;
  }
};

}  // namespace

// A local miss under noise is not noise: a plane with a narrow bump (0.05 high, σ 0.1 wide, about
// 1% of the region's area) and 0.05% scan noise. At 12 × 12 the data RMS is 1.2 σ, where the
// discrepancy principle alone stopped, while the surface cuts the bump off by 10 σ; the
// residual's bias over neighbourhoods (fitting/residual_bias.h) sees the miss and refines on
// until the fit is within 3 σ of the noise-free truth.
TEST(LabeledFit, ALocalMissUnderNoiseIsRefinedPastTheDataRms) {
  const BumpedPlate plate(0.05, 0.1);
  LabeledFitOptions o;
  o.maxControl = 0;
  const LabeledFitResult fixed = fitLabeled(plate.region, plate.labels, o);
  o.maxControl = 40;
  const LabeledFitResult refined = fitLabeled(plate.region, plate.labels, o);
  std::printf("bump under 0.05%% noise: %dx%d rms %.2e bias %.2e truth %.2e; refined %dx%d rms %.2e bias %.2e truth %.2e (σ %.2e)\n",
              fixed.fit.surface.numU(), fixed.fit.surface.numV(), fixed.fit.dataRms, fixed.dataBias, plate.truthMiss(fixed), refined.fit.surface.numU(), refined.fit.surface.numV(), refined.fit.dataRms,
              refined.dataBias, plate.truthMiss(refined), refined.noise);
  EXPECT_LE(fixed.fit.dataRms, 1.5 * fixed.noise);
  EXPECT_GT(fixed.dataBias, 2 * fixed.noise);
  EXPECT_GT(plate.truthMiss(fixed), 3 * 0.0005);
  EXPECT_GT(refined.fit.surface.numU(), 12);
  EXPECT_LE(refined.dataBias, refined.noise);
  EXPECT_LT(plate.truthMiss(refined), 3 * 0.0005);
}

// Under scan noise a miss of a few vertices is refined where it is, not by a finer net everywhere,
// which follows the noise everywhere: a plane with a small sharp bump (0.02 high, 0.04 wide, about
// 20 of 3,321 vertices) under 0.05% noise. Refining cells around the vertices that miss meets the
// data with 181 unknowns, within 3 σ of the noise-free truth; refining the whole net takes 40 × 27
// (1,080) and strays 3.4 σ from the truth.
TEST(LabeledFit, ASmallMissUnderNoiseIsRefinedWhereItIs) {
  const BumpedPlate plate(0.02, 0.04);
  LabeledFitOptions o;
  const LabeledFitResult local = fitLabeled(plate.region, plate.labels, o);
  o.localRefinements = 0;
  const LabeledFitResult whole = fitLabeled(plate.region, plate.labels, o);
  for (const auto& l : local.refinements) std::printf("local: %s\n", l.c_str());
  std::printf("local %d unknowns truth %.2e; whole %d truth %.2e (sigma %.2e)\n", local.fit.unknowns, plate.truthMiss(local), whole.fit.unknowns, plate.truthMiss(whole), local.noise);
  EXPECT_LT(local.fit.unknowns, local.fit.surface.numU() * local.fit.surface.numV());  // cells refined
  EXPECT_LT(local.fit.unknowns, whole.fit.unknowns / 3);
  EXPECT_LT(plate.truthMiss(local), 3 * 0.0005);
  EXPECT_GT(plate.truthMiss(whole), plate.truthMiss(local));
  EXPECT_TRUE(local.metTolerance);
  EXPECT_EQ(local.fit.weakControlPoints, 0);
  EXPECT_LT(local.fit.log10Condition, 8);
  EXPECT_TRUE(local.fit.valid);
  EXPECT_NE(local.toJson().find("\"unknowns\""), std::string::npos);
}

// A fit that misses the data says so (the CLI exits 3 on it): 5x5 control points, no refinement,
// leave 4.6e-3 on the clean bitten half cylinder, above the tolerance 1e-3 and any noise; refined,
// the verdict follows the data max.
TEST(LabeledFit, AFitThatMissesTheDataSaysSo) {
  std::vector<LabeledSegment> labels;
  const TriangleMesh region = bittenHalfCylinder(labels);
  LabeledFitOptions o;
  o.fit.controlU = o.fit.controlV = 5;
  o.maxControl = 0;
  const LabeledFitResult clean = fitLabeled(region, labels, o);
  EXPECT_GT(clean.fit.dataMax, 1e-3);
  EXPECT_FALSE(clean.metTolerance);
  EXPECT_EQ(clean.outcome().status, Status::Warned);  // written, the data missed: the CLI exits 3
  EXPECT_NE(clean.outcome().message.find("the data is missed"), std::string::npos) << clean.outcome().message;
  EXPECT_NE(clean.toJson().find("\"status\":\"warned\""), std::string::npos);
  EXPECT_TRUE(warns(clean, "misses the region's data"));
  EXPECT_NE(clean.toJson().find("\"met_tolerance\":false"), std::string::npos);
  o.fit.controlU = o.fit.controlV = 12;
  o.maxControl = 40;
  const LabeledFitResult refined = fitLabeled(region, labels, o);
  EXPECT_EQ(refined.metTolerance, refined.fit.dataMax <= 1e-3);
}

// The L labeled by its corner angles (test_regions.h), on a saddle as in the corpus
// (saddle_lshape_clean_corners: data max 8.6e-3 before one leg of the reflex side was held; then
// 6.5e-4 with 8 weak control points, the control cells sized by the rectangle alone while the
// other arm lay past it). The fit meets the tolerance with the extension and no weak control point.
TEST(LabeledFit, AnLLabeledByCornerAnglesMeetsTheTolerance) {
  Eigen::MatrixX2d truth;
  const TriangleMesh region = testregions::gridRegion(
      40, 40, 0.025, [](double x, double y) { return x < 0.5 || y < 0.5; },
      [](double x, double y) { return Eigen::Vector3d(10 * x, 10 * y, 2 * (x - 0.5) * (y - 0.5) * 4); }, truth);
  const LabeledFitResult r = fitLabeled(region, testregions::lShapeCornerLabels(region, truth));
  EXPECT_TRUE(r.metTolerance) << r.fit.dataMax;
  EXPECT_LE(r.fit.dataMax, 1e-3);
  EXPECT_EQ(r.fit.weakControlPoints, 0);
  EXPECT_GT(r.extension.mesh.vertices.rows(), region.vertices.rows());
  EXPECT_TRUE(r.fit.valid);
}

// A wavy height field (cosines of random amplitudes, about one period across) with its corner
// bitten off by an arc of half the side, clean: the extension fills the bite from a thin-plate fit
// of the region. Sampled once, at the starting 12 × 12, that fit's bias stayed in the extension
// while refinement bent the surface finer; the extension pulled the fit off the data and was
// given up (11 weak control points, data max 6.0e-3, as the corpus's bspline_corner_clean did).
// Sampled at each refinement's control points, it is kept and the data is met.
TEST(LabeledFit, TheExtensionIsSampledAtEachRefinementsControlPoints) {
  std::mt19937 rng(8);
  std::normal_distribution<double> normal(0, 1);
  double a[4][4];
  for (auto& row : a)
    for (double& x : row) x = normal(rng);
  const auto height = [&](double u, double v) {
    double z = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) z += 0.12 * a[i][j] * std::cos(2.2 * i * u + 0.3 * i) * std::cos(2.2 * j * v + 0.5 * j);
    return z;
  };
  Eigen::MatrixX2d uv;
  const TriangleMesh region = testregions::gridRegion(
      60, 60, 1.0 / 60, [](double u, double v) { return std::hypot(u - 1, v - 1) > 0.5; },
      [&](double u, double v) { return Eigen::Vector3d(u, v, height(u, v)); }, uv);
  const std::vector<LabeledSegment> labels = testregions::boundingBoxLabels(region, uv);
  LabeledFitOptions o;
  o.maxControl = 40;
  const LabeledFitResult r = fitLabeled(region, labels, o);
  for (const std::string& w : r.warnings) std::printf("  warning: %s\n", w.c_str());
  for (const std::string& line : r.refinements) std::printf("  %s\n", line.c_str());
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_GT(r.extension.mesh.vertices.rows(), region.vertices.rows());
  EXPECT_LT(r.fit.dataMax, 1e-3);
  EXPECT_EQ(r.fit.weakControlPoints, 0);
  EXPECT_LT(r.fit.log10Condition, 8);
}

// A coarse region (a 16 × 16 grid, a corner bitten off) of a field that wants more control points:
// the extension's grid starts as coarse as the region's edges, and refined past it, the cells at
// the rim held few samples, on the grid's lines, and the data's normal matrix was singular there
// (the corpus's bspline_notch_n0p05 at 27 × 27). The extension is rebuilt finer with the control net.
TEST(LabeledFit, TheExtensionsGridIsRefinedWithTheControlNet) {
  Eigen::MatrixX2d uv;
  const TriangleMesh region = testregions::gridRegion(
      16, 16, 1.0 / 16, [](double u, double v) { return std::hypot(u - 1, v - 1) > 0.45; },
      [](double u, double v) { return Eigen::Vector3d(u, v, 0.15 * std::sin(5 * u) * std::cos(4 * v) + 0.1 * std::sin(7 * v + u)); }, uv);
  const std::vector<LabeledSegment> labels = testregions::boundingBoxLabels(region, uv);
  LabeledFitOptions o;
  o.maxControl = 40;
  o.relaxLabels = false;  // the labeled map's extension is under test (relaxed, this region meets the data at 12 x 12)
  o.reach = 0;            // over the rectangle alone, as measured (with the default reach this small field's extension is given up)
  const LabeledFitResult r = fitLabeled(region, labels, o);
  for (const std::string& line : r.refinements) std::printf("  %s\n", line.c_str());
  ASSERT_GT(r.extension.mesh.vertices.rows(), region.vertices.rows());
  const BSplineSurface& s = r.fit.surface;
  const double span = std::min((s.knotsU.back() - s.knotsU.front()) / (s.numU() - 3), (s.knotsV.back() - s.knotsV.front()) / (s.numV() - 3));
  std::printf("%dx%d, knot span %.4f, extension spacing %.4f, %lld new samples\n", s.numU(), s.numV(), span, r.extension.spacing,
              static_cast<long long>(r.extension.mesh.vertices.rows() - region.vertices.rows()));
  EXPECT_GT(r.refinements.size(), 1u);
  EXPECT_LT(r.extension.spacing, 0.5 / 16);  // the region's edges are 1/16
  EXPECT_LE(r.extension.spacing, 0.5 * span);
  EXPECT_EQ(r.fit.weakControlPoints, 0);
  EXPECT_LT(r.fit.log10Condition, 8);
}

namespace {

Eigen::Vector3d cone(double x, double y) {
  return {(1 + 3 * y) * std::cos(1.2 * M_PI * x), (1 + 3 * y) * std::sin(1.2 * M_PI * x), 8 * y};
}

}  // namespace

// An L of the corpus's cone labeled by the bounding-box rule: the inner corner is held on a side
// (leaving it free did not lower the distortion), the map is singular there and the fit misses
// it (measured: 2.1e-3 of the diagonal; cone_lshape_clean_cw of the corpus 3.0e-3). With the
// labels relaxed (the free flattening, turned as the labels say) it meets the tolerance (4.7e-4)
// without weak control points. A bitten corner of the same cone at 40 × 40 cells met the data
// held, but with 5 weak control points (the rectangle's corner beyond the bite): relaxed, none.
TEST(LabeledFit, AnLWhoseLabeledMapIsSingularIsFittedWithTheLabelsRelaxed) {
  for (const bool bite : {false, true}) {
    SCOPED_TRACE(bite ? "bitten corner" : "L-shape");
    Eigen::MatrixX2d truth;
    const TriangleMesh region = testregions::gridRegion(
        40, 40, 1.0 / 40, [&](double x, double y) { return bite ? std::hypot(x - 1, y - 1) > 0.55 : x < 0.5 || y < 0.5; }, cone, truth);
    const std::vector<LabeledSegment> labels = testregions::boundingBoxLabels(region, truth);
    LabeledFitOptions o;
    o.relaxLabels = false;
    // Knots inserted where the held map's fit misses make it meet the L (5.1e-4, no weak control
    // point): without them, the relaxed map is what repairs it.
    o.localRefinements = 0;
    const LabeledFitResult held = fitLabeled(region, labels, o);
    EXPECT_TRUE(!held.metTolerance || held.fit.weakControlPoints > 0);
    EXPECT_FALSE(held.labelsRelaxed);
    o.relaxLabels = true;
    const LabeledFitResult r = fitLabeled(region, labels, o);
    EXPECT_TRUE(r.labelsRelaxed);
    EXPECT_TRUE(r.metTolerance);
    EXPECT_LE(r.fit.dataMax, 1e-3);
    EXPECT_EQ(r.fit.weakControlPoints, 0);
    EXPECT_LT(r.fit.log10Condition, 8);
    EXPECT_TRUE(r.fit.valid);
    EXPECT_TRUE(warns(r, "the relaxed fit is kept"));
    EXPECT_NE(r.toJson().find("\"labels_relaxed\":true"), std::string::npos);
    std::printf("%s: held %.2e (%d weak), relaxed %.2e\n", bite ? "bite" : "L", held.fit.dataMax, held.fit.weakControlPoints, r.fit.dataMax);
  }
}

// The untrimmed surface reaches past the domain as asked (LabeledFitOptions::reach), the same
// margin whatever the refinement (in grid layers it shrank when a finer control net rebuilt the
// grid): a bitten corner fitted with a reach of 0.2 of the rectangle's larger side has its knots
// that far past the rectangle on every side, also when refined past its start (a wavy field at a
// tolerance of 1e-4), with the region met and no weak control point; the control counts grow with
// the domain (at 12 x 12 over it, the extension was given up). On a gentle quadric the margin
// continues the surface (within 1% of the diagonal at the domain's far corner). A negative reach
// is refused.
TEST(LabeledFit, TheUntrimmedSurfaceReachesPastTheDomainAsAsked) {
  const std::function<Eigen::Vector3d(double, double)> wavy = [](double u, double v) {
    return Eigen::Vector3d(u, v, 0.15 * std::sin(5 * u) * std::cos(4 * v) + 0.1 * std::sin(7 * v + u));
  };
  const std::function<Eigen::Vector3d(double, double)> quadric = [](double u, double v) {
    return Eigen::Vector3d(u, v, 0.2 * u * v + 0.1 * u * u);
  };
  for (const bool gentle : {false, true}) {
    SCOPED_TRACE(gentle ? "quadric" : "wavy");
    const auto& field = gentle ? quadric : wavy;
    Eigen::MatrixX2d uv;
    const TriangleMesh region =
        testregions::gridRegion(24, 24, 1.0 / 24, [](double u, double v) { return std::hypot(u - 1, v - 1) > 0.45; }, field, uv);
    const std::vector<LabeledSegment> labels = testregions::boundingBoxLabels(region, uv);
    LabeledFitOptions o;
    o.relaxLabels = false;
    o.reach = 0.2;
    o.fit.controlU = o.fit.controlV = gentle ? 12 : 6;  // the wavy field from a coarse start: refined
    const LabeledFitResult r = fitLabeled(region, labels, o);
    ASSERT_GT(r.extension.mesh.vertices.rows(), region.vertices.rows());
    const BSplineSurface& s = r.fit.surface;
    const double W = r.parameterization.width, H = r.parameterization.height, m = 0.2 * std::max(W, H);
    std::printf("%dx%d over [%.3f, %.3f] x [%.3f, %.3f], rectangle %.3f x %.3f, data max %.2e, %zu tries\n", s.numU(), s.numV(),
                s.knotsU.front(), s.knotsU.back(), s.knotsV.front(), s.knotsV.back(), W, H, r.fit.dataMax, r.refinements.size());
    if (!gentle) EXPECT_GE(r.refinements.size(), 2u);  // refined past the start
    EXPECT_NEAR(s.knotsU.front(), -m, 1e-6 * m);
    EXPECT_NEAR(s.knotsU.back(), W + m, 1e-6 * m);
    EXPECT_NEAR(s.knotsV.front(), -m, 1e-6 * m);
    EXPECT_NEAR(s.knotsV.back(), H + m, 1e-6 * m);
    EXPECT_TRUE(r.metTolerance);
    EXPECT_EQ(r.fit.weakControlPoints, 0);
    if (gentle) {
      const Eigen::Vector3d corner = s.point(-m, -m);
      EXPECT_LT(std::abs(corner.z() - field(corner.x(), corner.y()).z()), 0.01 * std::sqrt(2.0)) << corner.transpose();
    }
    o.reach = -0.1;
    EXPECT_THROW(fitLabeled(region, labels, o), Error);
  }
}

namespace {

// The largest distance of the noise-free vertices `truth` to the fit, from each vertex's own
// fitted parameters, relative to the region's diagonal.
double truthMax(const LabeledFitResult& r, const TriangleMesh& region, const Eigen::MatrixX3d& truth) {
  const double diagonal = (region.vertices.colwise().maxCoeff() - region.vertices.colwise().minCoeff()).norm();
  double most = 0;
  for (Eigen::Index v = 0; v < truth.rows(); ++v) {
    Eigen::Vector2d uv = r.fit.regionUV.row(v).transpose();
    most = std::max(most, projectPointFrom(r.fit.surface, truth.row(v).transpose(), uv));
  }
  return most / diagonal;
}

// A region of the cone cut by `inside` on a 40 × 40 grid of the unit square, labeled by the
// bounding-box rule, its noise-free vertices in `truth`, then normal noise of `sigma` of its diagonal.
TriangleMesh noisyConeRegion(const std::function<bool(double, double)>& inside, double sigma, Eigen::MatrixX3d& truth,
                             std::vector<LabeledSegment>& labels) {
  Eigen::MatrixX2d uv;
  TriangleMesh region = testregions::gridRegion(40, 40, 1.0 / 40, inside, cone, uv);
  truth = region.vertices;
  labels = testregions::boundingBoxLabels(region, uv);
  testregions::addNoise(region, sigma, 7);
  return region;
}

}  // namespace

// Under scan noise the labeled map of a U-slot on the corpus's cone needs refining (the slot's
// walls pressed onto the sides) and the finer net follows the noise: held, 672 control points and
// 3.9 σ off the noise-free vertices, though the data is met within the noise. Its relaxed map
// meets the data within the noise with 196 control points and stays within 1.3 σ of the truth
// (bspline_ring_n0p2 of the corpus: 1,600 against 441, 3.4 σ against 2.5 σ).
TEST(LabeledFit, ANoisySlotIsFittedOnTheMapThatFollowsLessOfTheNoise) {
  const double sigma = 5e-4;
  Eigen::MatrixX3d truth;
  std::vector<LabeledSegment> labels;
  const TriangleMesh region =
      noisyConeRegion([](double x, double y) { return !(std::abs(x - 0.5) < 0.12 && y > 0.35); }, sigma, truth, labels);
  LabeledFitOptions o;
  o.relaxLabels = false;
  const LabeledFitResult held = fitLabeled(region, labels, o);
  o.relaxLabels = true;
  const LabeledFitResult r = fitLabeled(region, labels, o);
  const auto controlPoints = [](const LabeledFitResult& f) { return static_cast<long>(f.fit.surface.poles.rows()); };
  std::printf("held: %ld control points, %.2f sigma off the truth; relaxed: %ld, %.2f sigma\n", controlPoints(held),
              truthMax(held, region, truth) / sigma, controlPoints(r), truthMax(r, region, truth) / sigma);
  EXPECT_TRUE(held.metTolerance);
  EXPECT_GT(held.refinementsKept, 0);
  EXPECT_GT(truthMax(held, region, truth), 3 * sigma);
  EXPECT_TRUE(r.labelsRelaxed);
  EXPECT_TRUE(r.metTolerance);
  EXPECT_LT(controlPoints(r), controlPoints(held));
  EXPECT_LT(truthMax(r, region, truth), 2 * sigma);
  EXPECT_EQ(r.fit.weakControlPoints, 0);
  EXPECT_TRUE(r.fit.valid);
  EXPECT_TRUE(warns(r, "following less of the noise"));
}

// A ring (a square with a round inner hole) on the cone under 0.2% noise: its labeled map's
// inner loop crosses itself in the domain, so no extension can be built and the labeled fit is
// refused. With the labels relaxed (the default) the free flattening is the repair: a valid face,
// no weak control points, within 1.5 σ of the noise-free vertices.
TEST(LabeledFit, ANoisyRingWhoseLabeledMapFoldsIsFittedWithTheLabelsRelaxed) {
  const double sigma = 2e-3;
  Eigen::MatrixX3d truth;
  std::vector<LabeledSegment> labels;
  const TriangleMesh region = noisyConeRegion([](double x, double y) { return std::hypot(x - 0.5, y - 0.5) > 0.2; }, sigma, truth, labels);
  LabeledFitOptions o;
  o.relaxLabels = false;
  try {
    fitLabeled(region, labels, o);
    ADD_FAILURE() << "the labeled map's fit was expected to be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("folds at its boundary"), std::string::npos) << e.what();
  }
  o.relaxLabels = true;
  const LabeledFitResult r = fitLabeled(region, labels, o);
  std::printf("relaxed: %.2f sigma off the truth\n", truthMax(r, region, truth) / sigma);
  EXPECT_TRUE(r.labelsRelaxed);
  EXPECT_TRUE(warns(r, "the labeled map could not be fitted"));
  EXPECT_TRUE(r.metTolerance);
  EXPECT_LT(truthMax(r, region, truth), 3 * sigma);
  EXPECT_EQ(r.fit.weakControlPoints, 0);
  EXPECT_TRUE(r.fit.valid);
}
