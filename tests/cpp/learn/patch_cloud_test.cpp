// The synthetic clouds BIDGCN is trained, validated and benchmarked on.
#include <gtest/gtest.h>

#include "geometry/error.h"
#include "learn/patch_cloud.h"

using namespace holefill;
using namespace holefill::learn;

TEST(PatchCloud, SameSeedSameCloudAndSplitsDiffer) {
  const PatchCloud a = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Train, 7));
  const PatchCloud b = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Train, 7));
  const PatchCloud c = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Validation, 7));
  EXPECT_EQ((a.points - b.points).norm(), 0.0);
  EXPECT_GT((a.points - c.points).norm(), 1.0);
}

TEST(PatchCloud, BoundaryOnTheSidesInteriorInsideAndInTheUnitCube) {
  PatchCloudOptions o;
  o.interior = 500;
  const PatchCloud c = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Test, 3), o);
  ASSERT_EQ(c.points.rows(), 534);
  EXPECT_NEAR(c.points.minCoeff(), 0.0, 1e-15);
  EXPECT_NEAR(c.points.colwise().maxCoeff().maxCoeff(), 1.0, 1e-12);
  for (int k = 0; k < 534; ++k) {
    const double u = c.uv(k, 0), v = c.uv(k, 1);
    const double side = std::min({u, v, 1 - u, 1 - v});
    EXPECT_EQ(c.boundary[k], k < 34);
    if (k < 34) EXPECT_EQ(side, 0.0) << k;
    else EXPECT_GT(side, 0.0) << k;
  }
  // The four corners come first.
  EXPECT_EQ(c.uv.row(0), Eigen::RowVector2d(0, 0));
  EXPECT_EQ(c.uv.row(2), Eigen::RowVector2d(1, 1));
}

TEST(PatchCloud, ExactParametersFitExactlyAtTheirDegreeAndNoiseShows) {
  for (int degree : {2, 3, 5}) {
    PatchCloudOptions o;
    o.degree = degree;
    const PatchCloud c = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Test, degree), o);
    EXPECT_LT(bezierFitMse(c.points, c.uv, degree), 1e-26) << degree;
    if (degree > 2) EXPECT_GT(bezierFitMse(c.points, c.uv, 2), 1e-8) << degree;  // not biquadratic
  }
  PatchCloudOptions o;
  o.sigma = 0.01;
  const PatchCloud c = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Test, 0), o);
  // Residual of 3 noisy coordinates after fitting 27 numbers to 1034 points: about 3σ².
  EXPECT_NEAR(bezierFitMse(c.points, c.uv), 3e-4, 0.4e-4);
}

TEST(PatchCloud, BadOptionsAreRefused) {
  PatchCloudOptions o;
  o.boundary = 3;
  EXPECT_THROW(randomPatchCloud(1, o), Error);
  o = {};
  o.degree = 0;
  EXPECT_THROW(randomPatchCloud(1, o), Error);
  EXPECT_THROW(bezierFitMse(Eigen::MatrixX3d(3, 3), Eigen::MatrixX2d(2, 2)), Error);
}
