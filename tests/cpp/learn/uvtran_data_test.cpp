#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "geometry/error.h"
#include "geometry/polygon2d.h"
#include "learn/uvtran_data.h"
#include "learn/voxel.h"

using namespace holefill;
using namespace holefill::learn;

TEST(UvtranData, SameSeedSameSample) {
  const UvtranSample a = makeUvtranSample(7), b = makeUvtranSample(7), c = makeUvtranSample(8);
  ASSERT_EQ(a.boundary.size(), 128u);
  for (size_t i = 0; i < a.boundary.size(); ++i) EXPECT_EQ(a.boundary[i], b.boundary[i]);
  EXPECT_EQ(a.surface.poles, b.surface.poles);
  EXPECT_NE(a.boundary[0], c.boundary[0]);
}

TEST(UvtranData, BoundaryLiesOnTheTargetSurfaceAtTheGroundTruthParameters) {
  for (uint64_t seed = 0; seed < 40; ++seed) {
    const UvtranSample x = makeUvtranSample(uvtranSeed(UvtranSplit::Validation, seed));
    ASSERT_EQ(x.params.size(), x.boundary.size());
    double worst = 0;
    for (size_t i = 0; i < x.params.size(); ++i)
      worst = std::max(worst, (x.surface.point(x.params[i].x(), x.params[i].y()) - x.boundary[i]).norm());
    // Linear interpolation between 2048 dense pcurve points: the chord error is tiny.
    EXPECT_LT(worst, 2e-4) << "seed " << seed << " " << x.family;
    // Poles in the unit cube, as voxelization needs; pcurve inside the domain, counter-clockwise.
    EXPECT_GE(x.surface.poles.minCoeff(), 0.0);
    EXPECT_LE(x.surface.poles.maxCoeff(), 1.0);
    Polygon2 uv(x.params.begin(), x.params.end());
    EXPECT_GT(signedArea(uv), 0) << "seed " << seed;
    EXPECT_FALSE(selfIntersects(uv));
    EXPECT_GE(x.sides, 3);
    EXPECT_LE(x.sides, 8);
    EXPECT_EQ(static_cast<int>(x.cornerSamples.size()), x.sides);
  }
}

TEST(UvtranData, SplitsAreDisjointAndFamiliesAllOccur) {
  EXPECT_NE(uvtranSeed(UvtranSplit::Train, 5), uvtranSeed(UvtranSplit::Validation, 5));
  EXPECT_GT(uvtranSeed(UvtranSplit::Test, 0), uvtranSeed(UvtranSplit::Validation, 1u << 30));
  std::map<std::string, int> families;
  const auto t = std::chrono::steady_clock::now();
  const int n = 200;
  double attempts = 0;
  for (int i = 0; i < n; ++i) {
    const UvtranSample x = makeUvtranSample(uvtranSeed(UvtranSplit::Train, i));
    ++families[x.family];
    attempts += x.attempts;
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count() / n;
  std::printf("data: %.2f ms per sample, %.2f attempts per sample\n", ms, attempts / n);
  for (const char* f : {"flat", "bumpy", "cylinder", "dome", "saddle"}) {
    std::printf("  %s: %d\n", f, families[f]);
    EXPECT_GT(families[f], 10) << f;
  }
}

TEST(Voxel, RoundTripWithinHalfACellPerAxis) {
  for (int classes : {10, 100}) {
    const double dv = 1.0 / classes;
    double worst = 0;
    for (int i = 0; i <= 1000; ++i)
      for (double y : {0.0, 0.37, 0.999999}) {
        const Eigen::Vector3d p(i / 1000.0, y, 1 - i / 1000.0);
        Eigen::Vector3d q;
        for (int c = 0; c < 3; ++c) q(c) = voxelCentre(voxelIndex(p(c), classes), classes);
        worst = std::max(worst, (p - q).norm());
      }
    EXPECT_LE(worst, std::sqrt(3.0) * dv / 2 + 1e-12);
    EXPECT_GT(worst, 0.8 * dv / 2);  // and the bound is not vacuous
  }
}
