#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fitting/cloud_parameterization.h"
#include "geometry/error.h"

using namespace holefill;

namespace {

// An (m+1)² grid over the unit square lifted by `lift`, its frame the boundary with exact parameters.
struct Cloud {
  Eigen::MatrixX3d points;
  std::vector<bool> boundary;
  Eigen::MatrixX2d uv;  // the truth: the grid coordinates
};

Cloud grid(int m, const std::function<double(double, double)>& lift, double jitter = 0, unsigned seed = 1) {
  Cloud c;
  const int n = (m + 1) * (m + 1);
  c.points.resize(n, 3);
  c.uv.resize(n, 2);
  c.boundary.assign(n, false);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> J(-jitter, jitter);
  for (int j = 0, k = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i, ++k) {
      const bool rim = i == 0 || j == 0 || i == m || j == m;
      const double u = (i + (rim ? 0 : J(rng))) / m, v = (j + (rim ? 0 : J(rng))) / m;
      c.points.row(k) << u, v, lift(u, v);
      c.uv.row(k) << u, v;
      c.boundary[k] = rim;
    }
  return c;
}

double maxError(const CloudParameterization& p, const Cloud& c) { return (p.uv - c.uv).rowwise().norm().maxCoeff(); }

}  // namespace

TEST(CloudParameterization, EachMethodReproducesAPlanarGridsParameters) {
  // Uniform weights are exact where every neighbourhood is symmetric: the four grid neighbours
  // (radius just above the spacing); inverse distance also with the eight; shape-preserving
  // weights reproduce any planar star, so also with the default radius (about 2.9 spacings,
  // neighbourhoods cut by the boundary) and on a jittered grid.
  const Cloud flat = grid(20, [](double, double) { return 0.0; });
  const double h = 1.0 / 20;
  CloudParameterizationOptions o;
  o.weights = CloudWeights::Uniform;
  o.radius = 1.01 * h;
  const CloudParameterization uniform = parameterizeCloud(flat.points, flat.boundary, flat.uv, o);
  o.weights = CloudWeights::InverseDistance;
  o.radius = 1.5 * h;
  const CloudParameterization invdist = parameterizeCloud(flat.points, flat.boundary, flat.uv, o);
  o = {};
  const CloudParameterization shape = parameterizeCloud(flat.points, flat.boundary, flat.uv, o);
  const Cloud jittered = grid(20, [](double, double) { return 0.0; }, 0.3, 5);
  const CloudParameterization shapeJ = parameterizeCloud(jittered.points, jittered.boundary, jittered.uv, o);
  std::printf("planar grid: uniform %.1e (%d-%d neighbours), inverse distance %.1e, shape-preserving %.1e (radius %.3f, %d-%d neighbours, "
              "%d fallbacks), jittered %.1e\n",
              maxError(uniform, flat), uniform.minNeighbours, uniform.maxNeighbours, maxError(invdist, flat), maxError(shape, flat), shape.radius,
              shape.minNeighbours, shape.maxNeighbours, shape.fallbacks, maxError(shapeJ, jittered));
  EXPECT_LT(maxError(uniform, flat), 1e-12);
  EXPECT_LT(maxError(invdist, flat), 1e-12);
  EXPECT_LT(maxError(shape, flat), 1e-12);
  EXPECT_LT(maxError(shapeJ, jittered), 1e-12);
  EXPECT_EQ(shape.fallbacks, 0);
  // The default radius with uniform weights is not exact (the neighbourhoods next to the
  // boundary are lopsided): what the shape-preserving weights are for.
  o.weights = CloudWeights::Uniform;
  EXPECT_GT(maxError(parameterizeCloud(flat.points, flat.boundary, flat.uv, o), flat), 1e-3);
}

TEST(CloudParameterization, ACurvedCloudGetsParametersInsideTheSquareCloseToItsOwn) {
  const Cloud c = grid(24, [](double u, double v) { return 0.3 * std::sin(3 * u) * std::cos(2 * v); }, 0.25, 9);
  for (CloudWeights w : {CloudWeights::Uniform, CloudWeights::InverseDistance, CloudWeights::ShapePreserving}) {
    CloudParameterizationOptions o;
    o.weights = w;
    const CloudParameterization p = parameterizeCloud(c.points, c.boundary, c.uv, o);
    const double err = maxError(p, c);
    std::printf("curved cloud, method %d: max distance to the generating parameters %.3f, %.1f ms\n", static_cast<int>(w), err, 1e3 * p.seconds);
    EXPECT_GE(p.uv.minCoeff(), -1e-12);
    EXPECT_LE(p.uv.maxCoeff(), 1 + 1e-12);
    EXPECT_LT(err, 0.1);
  }
}

TEST(CloudParameterization, RefusesBadClouds) {
  Cloud c = grid(6, [](double, double) { return 0.0; });
  EXPECT_THROW(parameterizeCloud(c.points.topRows(9), std::vector<bool>(9, true), c.uv.topRows(9)), Error);  // < 10 points
  Eigen::MatrixX3d nan = c.points;
  nan(10, 1) = std::nan("");
  EXPECT_THROW(parameterizeCloud(nan, c.boundary, c.uv), Error);
  EXPECT_THROW(parameterizeCloud(c.points, std::vector<bool>(c.points.rows(), false), c.uv), Error);  // no boundary
  Eigen::MatrixX3d dup = c.points;
  dup.row(9) = dup.row(8);
  EXPECT_THROW(parameterizeCloud(dup, c.boundary, c.uv), Error);
  CloudParameterizationOptions tiny;
  tiny.radius = 1e-3;  // no neighbours at all
  try {
    parameterizeCloud(c.points, c.boundary, c.uv, tiny);
    ADD_FAILURE() << "a radius without neighbours was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no neighbour"), std::string::npos) << e.what();
  }
  EXPECT_THROW(cloudWeightsByName("bidgcn2"), Error);
}

TEST(CloudParameterization, BoundaryParametersByChordLengthFromFourCorners) {
  // A planar grid's frame, its points not in loop order: the corners are found, the sides get chord
  // length, which on an evenly sampled straight frame is the grid's own parameters (up to the
  // square's symmetries: which corner comes first depends on the plane's axes); then the interior
  // follows exactly.
  Cloud c = grid(12, [](double, double) { return 0.0; }, 0.2, 4);
  const Eigen::MatrixX2d uv = boundaryChordParameters(c.points, c.boundary);
  double best = 1e9;
  for (int sym = 0; sym < 8; ++sym) {
    double worst = 0;
    for (Eigen::Index k = 0; k < c.uv.rows(); ++k) {
      if (!c.boundary[k]) continue;
      double u = c.uv(k, 0), v = c.uv(k, 1);
      if (sym & 1) u = 1 - u;
      if (sym & 2) v = 1 - v;
      if (sym & 4) std::swap(u, v);
      worst = std::max(worst, (uv.row(k) - Eigen::RowVector2d(u, v)).norm());
    }
    best = std::min(best, worst);
  }
  EXPECT_LT(best, 1e-12);
  const CloudParameterization p = parameterizeCloud(c.points, c.boundary, uv);
  for (Eigen::Index k = 0; k < uv.rows(); ++k)
    if (c.boundary[k]) EXPECT_EQ(p.uv.row(k), uv.row(k));
  // Given corners land on the square's corners; a curved sheet's sides get monotone parameters.
  const Cloud wavy = grid(12, [](double u, double v) { return 0.3 * std::sin(3 * u) * std::cos(2 * v); });
  const std::vector<int> corners = {0, 12, 12 * 13 + 12, 12 * 13};
  const Eigen::MatrixX2d w = boundaryChordParameters(wavy.points, wavy.boundary, corners);
  for (int cidx : corners) {
    EXPECT_NEAR(std::min(w(cidx, 0), 1 - w(cidx, 0)), 0, 1e-15);
    EXPECT_NEAR(std::min(w(cidx, 1), 1 - w(cidx, 1)), 0, 1e-15);
  }
  EXPECT_THROW(boundaryChordParameters(wavy.points, wavy.boundary, {0, 12, 12}), Error);
  EXPECT_THROW(boundaryChordParameters(wavy.points, wavy.boundary, {0, 12, 13, 14}), Error);  // 14 is interior
}
