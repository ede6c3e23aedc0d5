#include "learn/parameter_error.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/error.h"

using namespace holefill;
using namespace holefill::learn;

namespace {

std::vector<Eigen::Vector2d> ring(int n) {
  std::vector<Eigen::Vector2d> p;
  for (int k = 0; k < n; ++k) p.emplace_back(0.5 + 0.4 * std::cos(2 * M_PI * k / n), 0.5 + 0.25 * std::sin(2 * M_PI * k / n) + 0.05 * std::cos(6 * M_PI * k / n));
  return p;
}

}  // namespace

TEST(ParameterError, IsTheMeanDistanceAndRefusesListsThatDoNotMatch) {
  const std::vector<Eigen::Vector2d> truth = ring(40);
  std::vector<Eigen::Vector2d> shifted = truth;
  for (auto& p : shifted) p += Eigen::Vector2d(0.03, -0.04);
  EXPECT_NEAR(parameterError(truth, truth), 0.0, 1e-15);
  EXPECT_NEAR(parameterError(shifted, truth), 0.05, 1e-12);
  EXPECT_THROW(parameterError(std::vector<Eigen::Vector2d>(3), truth), Error);
  EXPECT_THROW(alignedParameterError({}, {}), Error);
}

TEST(ParameterError, TheAlignedErrorForgivesASimilarityAndNothingElse) {
  // NP and MVC place their parameters in a frame of their own: rotated, mirrored, scaled and
  // moved, they are the truth.
  const std::vector<Eigen::Vector2d> truth = ring(60);
  std::vector<Eigen::Vector2d> placed;
  const Eigen::Matrix2d R = 3.5 * Eigen::Rotation2Dd(2.1).toRotationMatrix();
  for (const auto& p : truth) placed.push_back(R * Eigen::Vector2d(-p.x(), p.y()) + Eigen::Vector2d(7, -2));
  EXPECT_GT(parameterError(placed, truth), 1.0);
  EXPECT_NEAR(alignedParameterError(placed, truth), 0.0, 1e-12);
  // A shape change is not forgiven: the ellipse squashed along one axis stays off.
  std::vector<Eigen::Vector2d> squashed;
  for (const auto& p : truth) squashed.emplace_back(p.x(), 0.5 + 0.5 * (p.y() - 0.5));
  EXPECT_GT(alignedParameterError(squashed, truth), 0.01);
  EXPECT_LE(alignedParameterError(squashed, truth), parameterError(squashed, truth) + 1e-15);
}
