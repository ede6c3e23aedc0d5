// BIDGCN as the fitting uses it: parameterizeCloud(..., Bidgcn) through libholefill_learn.so and
// the shipped weights (Resources/models/bidgcn.pt), on the validation split of patch_cloud.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "fitting/cloud_parameterization.h"
#include "geometry/error.h"
#include "learn/learn_library.h"
#include "learn/patch_cloud.h"

using namespace holefill;
using namespace holefill::learn;

namespace {

double medianMse(CloudWeights w, int interior, double sigma, int clouds, int* failed = nullptr) {
  std::vector<double> mse;
  for (int c = 0; c < clouds; ++c) {
    PatchCloudOptions po;
    po.interior = interior;
    po.sigma = sigma;
    const PatchCloud cl = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Validation, 500 + c), po);
    CloudParameterizationOptions o;
    o.weights = w;
    try {
      const CloudParameterization p = parameterizeCloud(cl.points, cl.boundary, cl.uv, o);
      EXPECT_TRUE(p.uv.allFinite());
      mse.push_back(bezierFitMse(cl.points, p.uv));
    } catch (const Error&) {
      if (!failed) throw;
      ++*failed;
    }
  }
  if (mse.empty()) return std::nan("");
  std::sort(mse.begin(), mse.end());
  return mse[mse.size() / 2];
}

std::string errorOf(const Eigen::MatrixX3d& p, const std::vector<bool>& b, const Eigen::MatrixX2d& uv, const std::string& weights = "") {
  CloudParameterizationOptions o;
  o.weights = CloudWeights::Bidgcn;
  o.weightsFile = weights;
  try {
    parameterizeCloud(p, b, uv, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(BidgcnInference, ShippedWeightsBeatInverseDistanceAtEverySize) {
  ASSERT_FALSE(defaultBidgcnWeights().empty()) << "Resources/models/bidgcn.pt is missing";
  for (int interior : {200, 1000, 2000}) {
    const double net = medianMse(CloudWeights::Bidgcn, interior, 0, 16);
    const double invdist = medianMse(CloudWeights::InverseDistance, interior, 0, 16);
    EXPECT_LT(net, invdist) << interior << " interior points";
    std::printf("[bidgcn] %d interior points: median MSE %.3e (inverse distance %.3e)\n", interior, net, invdist);
  }
}

TEST(BidgcnInference, NoisyCloudsNeverFail) {
  // At σ = 0.05 the classical methods mostly find an interior point without neighbours.
  int failed = 0, failedClassical = 0;
  const double net = medianMse(CloudWeights::Bidgcn, 1000, 0.05, 8, &failed);
  medianMse(CloudWeights::InverseDistance, 1000, 0.05, 8, &failedClassical);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(failedClassical, 0);
  EXPECT_LT(net, 0.05);
}

TEST(BidgcnInference, BoundaryParametersAnywhereAreMappedThroughTheUnitSquare) {
  const PatchCloud cl = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Validation, 42));
  CloudParameterizationOptions o;
  o.weights = CloudWeights::Bidgcn;
  const Eigen::MatrixX2d a = parameterizeCloud(cl.points, cl.boundary, cl.uv, o).uv;
  Eigen::MatrixX2d shifted = cl.uv;
  shifted.col(0) = 3 * shifted.col(0).array() + 5;
  shifted.col(1) = 0.5 * shifted.col(1).array() - 2;
  const Eigen::MatrixX2d b = parameterizeCloud(cl.points, cl.boundary, shifted, o).uv;
  EXPECT_LT((3 * a.col(0).array() + 5 - b.col(0).array()).abs().maxCoeff(), 1e-5);
  EXPECT_LT((0.5 * a.col(1).array() - 2 - b.col(1).array()).abs().maxCoeff(), 1e-5);
}

TEST(BidgcnInference, BadInputAndWeightsGiveClearErrors) {
  const PatchCloud cl = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Validation, 43));
  EXPECT_NE(errorOf(cl.points, cl.boundary, cl.uv, ::testing::TempDir() + "/none.pt").find("weights not found"), std::string::npos);
  const std::string bad = ::testing::TempDir() + "/bad_bidgcn.pt";
  std::ofstream(bad) << "garbage";
  EXPECT_NE(errorOf(cl.points, cl.boundary, cl.uv, bad).find("truncated or corrupt"), std::string::npos);
  Eigen::MatrixX2d line = cl.uv;
  line.col(1).setZero();
  EXPECT_NE(errorOf(cl.points, cl.boundary, line).find("span no area"), std::string::npos);
  Eigen::MatrixX3d nan = cl.points;
  nan(100, 2) = std::nan("");
  EXPECT_NE(errorOf(nan, cl.boundary, cl.uv).find("non-finite"), std::string::npos);
  EXPECT_NE(errorOf(cl.points, std::vector<bool>(cl.points.rows(), false), cl.uv).find("boundary points"), std::string::npos);
  EXPECT_NE(errorOf(cl.points.topRows(8), std::vector<bool>(8, true), cl.uv.topRows(8)).find("at least 10"), std::string::npos);
  Eigen::MatrixX3d twice = cl.points;
  twice.row(200) = twice.row(201);
  EXPECT_NE(errorOf(twice, cl.boundary, cl.uv).find("coincide"), std::string::npos);
}
