#include "mesh/scan_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../fitting/test_regions.h"

using namespace holefill;

namespace {

// A 60 × 60 grid (valence 6 inside) over [0, 1]², placed by `place`, with normal noise `sigma`
// (along `normal(x, y)`) or, `isotropic`, noise of that deviation in every direction.
TriangleMesh noisyGrid(const std::function<Eigen::Vector3d(double, double)>& place,
                       const std::function<Eigen::Vector3d(double, double)>& normal, double sigma, bool isotropic, unsigned seed) {
  Eigen::MatrixX2d uv;
  TriangleMesh m = testregions::gridRegion(60, 60, 1.0 / 60, [](double, double) { return true; }, place, uv);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  for (Eigen::Index v = 0; v < m.vertices.rows(); ++v) {
    if (isotropic) m.vertices.row(v) += Eigen::RowVector3d(g(rng), g(rng), g(rng));
    else m.vertices.row(v) += g(rng) * normal(uv(v, 0), uv(v, 1)).transpose();
  }
  return m;
}

}  // namespace

TEST(ScanNoise, ACleanCurvedSurfaceHasNoNoise) {
  // A cylinder of radius 1 (curvature 1 against a grid step of 1/60): the umbrella offsets are
  // all curvature, alike between neighbours.
  const auto cylinder = [](double x, double y) { return Eigen::Vector3d(std::cos(2 * x), std::sin(2 * x), y); };
  const auto radial = [](double x, double) { return Eigen::Vector3d(std::cos(2 * x), std::sin(2 * x), 0); };
  const ScanNoise n = estimateScanNoise(noisyGrid(cylinder, radial, 0, false, 1));
  EXPECT_GT(n.samples, 3000);
  EXPECT_LT(n.sigma, 1e-3 * n.meanEdge);
}

TEST(ScanNoise, NormalNoiseOnAPlaneIsMeasuredToItsDeviation) {
  const auto plane = [](double x, double y) { return Eigen::Vector3d(x, y, 0); };
  const auto up = [](double, double) { return Eigen::Vector3d(0, 0, 1); };
  for (double sigma : {1e-4, 1e-3}) {
    const ScanNoise n = estimateScanNoise(noisyGrid(plane, up, sigma, false, 2));
    std::printf("plane, sigma %.1e: estimated %.3e\n", sigma, n.sigma);
    EXPECT_NEAR(n.sigma, sigma, 0.1 * sigma);
  }
}

TEST(ScanNoise, IsotropicNoiseOnACurvedSurfaceIsMeasuredToItsNormalPart) {
  // Scan noise in every direction: its normal part has the same deviation; the tangential part
  // moves vertices along the surface and hardly shows. A bump of height 0.2 over the square.
  const auto bump = [](double x, double y) { return Eigen::Vector3d(x, y, 0.2 * std::exp(-8 * ((x - .5) * (x - .5) + (y - .5) * (y - .5)))); };
  const auto up = [](double, double) { return Eigen::Vector3d(0, 0, 1); };
  const double sigma = 2e-3;
  const ScanNoise n = estimateScanNoise(noisyGrid(bump, up, sigma, true, 3));
  std::printf("bump, isotropic sigma %.1e: estimated %.3e\n", sigma, n.sigma);
  EXPECT_NEAR(n.sigma, sigma, 0.2 * sigma);
}

TEST(ScanNoise, TooFewInteriorVerticesGiveZero) {
  Eigen::MatrixX2d uv;
  const TriangleMesh m = testregions::gridRegion(2, 2, 1.0, [](double, double) { return true; },
                                                 [](double x, double y) { return Eigen::Vector3d(x, y, 0); }, uv);
  const ScanNoise n = estimateScanNoise(m);
  EXPECT_EQ(n.sigma, 0);
  EXPECT_LT(n.samples, 8);
}
