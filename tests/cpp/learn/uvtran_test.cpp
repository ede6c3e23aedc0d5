// UVTran as the fill uses it: through libholefill_learn.so and the shipped weights.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "brep/sample_models.h"
#include "fill/hole_fill.h"
#include "geometry/error.h"
#include "geometry/polygon2d.h"
#include "learn/learn_library.h"
#include "learn/parameter_error.h"
#include "learn/uvtran.h"
#include "learn/uvtran_data.h"

using namespace holefill;
using namespace holefill::learn;

namespace {
std::string tmp(const std::string& name) { return ::testing::TempDir() + "/" + name; }

std::string errorOf(const std::vector<Eigen::Vector3d>& loop, const UvtranOptions& o = {}) {
  try {
    predictUvtran(loop, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(UvtranInference, ShippedWeightsExistAndLoad) {
  const std::string w = defaultUvtranWeights();
  ASSERT_FALSE(w.empty()) << "Resources/models/uvtran.pt is missing";
  EXPECT_NE(std::string(learnLibrary().info()).find("libtorch"), std::string::npos);
  const UvtranSample x = makeUvtranSample(uvtranSeed(UvtranSplit::Validation, 0));
  const UvtranPrediction p = predictUvtran(x.boundary);
  EXPECT_EQ(p.uv.size(), x.boundary.size());
  EXPECT_EQ(p.surface.poles.rows(), 64);
  // The predicted surface passes near the boundary it was predicted from.
  EXPECT_LT(p.maxDistance, 0.05);
}

TEST(UvtranInference, ShippedWeightsBeatMvcOnAFixedValidationSet) {
  double uvtran = 0, mvc = 0;
  const int n = 48;
  for (int i = 0; i < n; ++i) {
    const UvtranSample x = makeUvtranSample(uvtranSeed(UvtranSplit::Validation, 100 + i));
    uvtran += parameterError(predictUvtran(x.boundary).uv, x.params);
    mvc += alignedParameterError(classicalParameters(x, ParamMethod::MeanValue), x.params);  // MVC's best placement
  }
  std::printf("parameter error on %d validation holes: uvtran %.4g, mvc (aligned) %.4g\n", n, uvtran / n, mvc / n);
  EXPECT_LT(uvtran, mvc);
  EXPECT_LT(uvtran / n, 0.01);
}

TEST(UvtranInference, StartPointAndDirectionDoNotChangeThePcurve) {
  const UvtranSample x = makeUvtranSample(uvtranSeed(UvtranSplit::Validation, 7));
  const int n = static_cast<int>(x.boundary.size());
  std::vector<Eigen::Vector3d> shifted, reversed;
  for (int k = 0; k < n; ++k) shifted.push_back(3.0 * x.boundary[(k + 41) % n] + Eigen::Vector3d(1, 2, 3));
  for (int k = 0; k < n; ++k) reversed.push_back(x.boundary[(n - k) % n]);
  for (bool augment : {true, false}) {
    UvtranOptions o;
    o.augment = augment;
    const UvtranPrediction a = predictUvtran(x.boundary, o), b = predictUvtran(shifted, o), c = predictUvtran(reversed, o);
    double shiftErr = 0, revErr = 0;
    for (int k = 0; k < n; ++k) {
      shiftErr = std::max(shiftErr, (b.uv[k] - a.uv[(k + 41) % n]).norm());
      // The reversed loop is seen in a frame half-turned about x: the same pcurve, mirrored in v.
      const Eigen::Vector2d m = c.uv[k];
      revErr = std::max(revErr, (Eigen::Vector2d(m.x(), 1 - m.y()) - a.uv[(n - k) % n]).norm());
    }
    std::printf("augment %d: start shift changes uv by %.2g, reversal by %.2g\n", augment, shiftErr, revErr);
    EXPECT_LT(shiftErr, 1e-5);  // exact: canonicalization removes start, placement and scale
    // With augmentation both directions are averaged, so reversal is exact too; one pass alone
    // relies on what the network learned from reversed training loops.
    EXPECT_LT(revErr, augment ? 1e-5 : 0.03);
  }
}

TEST(UvtranInference, BadInputsAndBadWeightsAreClearErrors) {
  std::vector<Eigen::Vector3d> few = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_NE(errorOf(few).find("at least 6"), std::string::npos);
  std::vector<Eigen::Vector3d> loop;
  for (int i = 0; i < 40; ++i) loop.emplace_back(std::cos(i * 0.157), std::sin(i * 0.157), 0.1 * std::cos(2 * i * 0.157));
  std::vector<Eigen::Vector3d> nan = loop;
  nan[3].y() = std::nan("");
  EXPECT_NE(errorOf(nan).find("NaN"), std::string::npos);
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 40; ++i) line.emplace_back(i, i, i);
  EXPECT_NE(errorOf(line).find("degenerate"), std::string::npos);
  UvtranOptions o;
  o.weights = tmp("nowhere.pt");
  EXPECT_NE(errorOf(loop, o).find("not found"), std::string::npos);
  std::string bytes;
  {
    std::ifstream in(defaultUvtranWeights(), std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(tmp("half.pt"), std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  o.weights = tmp("half.pt");
  EXPECT_NE(errorOf(loop, o).find("truncated or corrupt"), std::string::npos) << errorOf(loop, o);
}

TEST(UvtranInference, FillWithBrokenWeightsFallsBackToMvcAndSaysSo) {
  std::ofstream(tmp("broken.pt")) << "garbage";
  HoleFillOptions o;
  o.method = ParamMethod::Uvtran;
  o.parameterization.uvtranWeights = tmp("broken.pt");
  const HoleFillResult r = fillHole(samples::ccExtraordinaryHole(5), 0, o);
  EXPECT_EQ(r.status, FillStatus::Ok) << r.message;
  EXPECT_EQ(r.methodName, "uvtran:mvc");
  bool said = false;
  for (const auto& w : r.warnings) said = said || (w.find("uvtran failed") != std::string::npos &&
                                                   w.find("corrupt") != std::string::npos);
  EXPECT_TRUE(said);
  EXPECT_EQ(r.projectionSurface.poles.rows(), 0);
}

TEST(UvtranInference, FillWithShippedWeightsReachesG1OnAnExtraordinaryPointHole) {
  HoleFillOptions o;
  o.method = ParamMethod::Uvtran;
  const HoleFillResult r = fillHole(samples::ccExtraordinaryHole(6), 0, o);
  EXPECT_EQ(r.status, FillStatus::Ok) << r.message;
  EXPECT_EQ(r.methodName, "uvtran");
  EXPECT_TRUE(r.faceValid);
  EXPECT_LE(r.report.g1, 1e-3);
  EXPECT_EQ(r.projectionSurface.poles.rows(), 64);
}
