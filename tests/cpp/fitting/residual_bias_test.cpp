#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fitting/residual_bias.h"
#include "geometry/error.h"
#include "test_regions.h"

using namespace holefill;

namespace {

// A 60 × 60 grid of [0, 6]², 3,721 vertices, flat (the residual is given, not measured).
TriangleMesh square(Eigen::MatrixX2d& uv) {
  return testregions::gridRegion(60, 60, 0.1, [](double, double) { return true; }, [](double u, double v) { return Eigen::Vector3d(u, v, 0); }, uv);
}

Eigen::VectorXd noise(Eigen::Index n, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  Eigen::VectorXd r(n);
  for (Eigen::Index i = 0; i < n; ++i) r(i) = g(rng);
  return r;
}

}  // namespace

// What a stopping rule must not read as model error: independent noise averages out over a
// neighbourhood of 25 vertices or more (three whole rings, 37 on the grid: its mean's spread is σ/6), and the largest of 3,721 such means
// stays under σ, the rule's threshold, for every seed tried.
TEST(ResidualBias, IndependentNoiseAveragesBelowItsSigma) {
  Eigen::MatrixX2d uv;
  const TriangleMesh m = square(uv);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const ResidualBias b = residualBias(m, noise(m.vertices.rows(), 1.0, seed));
    EXPECT_LT(b.max, 1.0) << "seed " << seed;
    EXPECT_GT(b.max, 0.2) << "seed " << seed;  // the spread of one mean: the largest is above it
  }
}

// What the data RMS cannot see: a bump of 3 σ over a disc of radius 0.4 (about 50 of 3,721
// vertices) moves the RMS by under 15% and stands out of the noise in its neighbourhood's mean, found
// where it is.
TEST(ResidualBias, ALocalMissStandsOutOfTheNoiseWhereItIs) {
  Eigen::MatrixX2d uv;
  const TriangleMesh m = square(uv);
  Eigen::VectorXd r = noise(m.vertices.rows(), 1.0, 7);
  const double rmsBefore = std::sqrt(r.squaredNorm() / r.size());
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const double d = (uv.row(i) - Eigen::RowVector2d(4.2, 1.7)).norm();
    if (d < 0.4) r(i) += 3.0 * std::cos(M_PI / 2 * d / 0.4);
  }
  const double rmsAfter = std::sqrt(r.squaredNorm() / r.size());
  EXPECT_LT(rmsAfter / rmsBefore, 1.15);
  const ResidualBias b = residualBias(m, r);
  EXPECT_GT(b.max, 1.5);  // past the stopping rule's σ by half
  EXPECT_LT((uv.row(b.at) - Eigen::RowVector2d(4.2, 1.7)).norm(), 0.2);
}

// A neighbourhood takes whole rings: on the grid the first ring holds 6 vertices and the second
// 12 more, so a window of 8 takes both rings (19 vertices) and the mean of a residual that is 1
// at one vertex only is 1/19 there.
TEST(ResidualBias, ANeighbourhoodTakesWholeRings) {
  Eigen::MatrixX2d uv;
  const TriangleMesh m = square(uv);
  Eigen::Index centre = 0;
  (uv.rowwise() - Eigen::RowVector2d(3, 3)).rowwise().norm().minCoeff(&centre);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(m.vertices.rows());
  r(centre) = 1;
  EXPECT_NEAR(residualBias(m, r, 8).max, 1.0 / 19, 1e-12);
  EXPECT_NEAR(residualBias(m, r, 1).max, 1.0, 1e-12);
  // Per vertex: the centre's own mean and count, and a neighbour two rings out sees it too.
  const NeighbourhoodMeans means = neighbourhoodMeans(m, r, 8);
  EXPECT_EQ(means.count(centre), 19);
  EXPECT_NEAR(means.mean(centre), 1.0 / 19, 1e-12);
  int seeing = 0;
  for (Eigen::Index v = 0; v < r.size(); ++v) seeing += means.mean(v) > 0;
  EXPECT_EQ(seeing, 19);  // the vertices within two rings of it (the grid's rings are symmetric)
}

// The χ² test of verticesMissedPastNoise: pure noise passes on every seed tried; a miss that runs
// along the boundary with its inner neighbours off the other way (a fit too stiff at a corner)
// is found there, though the signed means cancel.
TEST(ResidualBias, AMissAlongTheBoundaryIsFoundWhereTheSignedMeanCancels) {
  Eigen::MatrixX2d uv;
  const TriangleMesh m = square(uv);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const std::vector<char> missed = verticesMissedPastNoise(m, findMeshHoles(m).holes, noise(m.vertices.rows(), 1.0, seed), 1.0);
    EXPECT_EQ(std::count(missed.begin(), missed.end(), 1), 0) << "seed " << seed;
  }
  Eigen::VectorXd r = noise(m.vertices.rows(), 1.0, 11);
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    if (std::abs(uv(i, 0) - 3) > 0.35) continue;
    if (uv(i, 1) < 1e-9) r(i) += 3.5;                       // on the bottom side, seven vertices
    else if (std::abs(uv(i, 1) - 0.1) < 1e-9) r(i) -= 3.5;  // and their inner neighbours
  }
  const std::vector<char> missed = verticesMissedPastNoise(m, findMeshHoles(m).holes, r, 1.0);
  // Found on the run itself, and nowhere past the reach of the neighbourhoods that hold part of it:
  // three rings (0.3) around it, and along the boundary a run of 9 (all of whose vertices are
  // flagged: 0.8 past either end).
  int onRun = 0, far = 0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    if (!missed[i]) continue;
    if (std::abs(uv(i, 0) - 3) <= 0.35 && uv(i, 1) < 1e-9) ++onRun;
    const bool alongRun = uv(i, 1) < 1e-9 && std::abs(uv(i, 0) - 3) <= 0.35 + 0.8 + 1e-9;
    if (!alongRun && (std::abs(uv(i, 0) - 3) > 0.7 || uv(i, 1) > 0.45)) ++far;
  }
  EXPECT_GE(onRun, 5);
  EXPECT_EQ(far, 0);
  EXPECT_LT(residualBias(m, r).max, 1.0);  // the bias rule would call it noise
  EXPECT_THROW(verticesMissedPastNoise(m, {}, r, 0), Error);
}

TEST(ResidualBias, SizesThatDisagreeAreAClearError) {
  Eigen::MatrixX2d uv;
  const TriangleMesh m = square(uv);
  EXPECT_THROW(residualBias(m, Eigen::VectorXd::Zero(5)), Error);
  EXPECT_THROW(residualBias(m, Eigen::VectorXd::Zero(m.vertices.rows()), 0), Error);
}
