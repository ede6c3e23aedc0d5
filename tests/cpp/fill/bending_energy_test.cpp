#include "fill/bending_energy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace holefill;

namespace {
// Bicubic Bézier patch (one span each way) with poles p(i, j) on [0,1]^2.
BSplineSurface bicubic(const std::function<Eigen::Vector3d(double, double)>& p) {
  BSplineSurface s;
  s.knotsU = s.knotsV = {0, 0, 0, 0, 1, 1, 1, 1};
  s.poles.resize(16, 3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s.poles.row(s.index(i, j)) = p(i / 3.0, j / 3.0).transpose();
  return s;
}
const Polygon2 kSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
}  // namespace

TEST(BendingEnergy, ZeroOnAPlaneAndIndependentOfTheParameterization) {
  EXPECT_NEAR(trimmedBendingEnergy(bicubic([](double u, double v) { return Eigen::Vector3d(u, 2 * v, 0.5 * u - v); }), kSquare), 0, 1e-12);
  // z = x^2 over [0,1]^2 (a parabolic cylinder) parameterized by x = u and mirrored by x = 1 - u:
  // the same energy, the exact one; half the trim holds half of it.
  // Poles at i/3 reproduce x = u exactly; z = u^2 has cubic Bernstein coefficients 0, 0, 1/3, 1.
  const double zu[4] = {0, 0, 1.0 / 3, 1}, zm[4] = {1, 1.0 / 3, 0, 0};
  const auto a = bicubic([&](double u, double v) { return Eigen::Vector3d(u, v, zu[int(std::lround(3 * u))]); });
  const auto b = bicubic([&](double u, double v) { return Eigen::Vector3d(1 - u, v, zm[int(std::lround(3 * u))]); });
  const double ea = trimmedBendingEnergy(a, kSquare, 60), eb = trimmedBendingEnergy(b, kSquare, 60);
  EXPECT_GT(ea, 0.5);
  EXPECT_NEAR(ea, eb, 1e-3 * ea);
  // ∫ κ² dA for z = x², κ = 2 / (1 + 4x²)^{3/2}, dA = sqrt(1 + 4x²) dx dy: ∫0^1 4 / (1 + 4x²)^{5/2} dx.
  double exact = 0;
  for (int i = 0; i < 100000; ++i) {
    const double x = (i + 0.5) / 100000;
    exact += 4 / std::pow(1 + 4 * x * x, 2.5) / 100000;
  }
  EXPECT_NEAR(ea, exact, 2e-3 * exact);
  const double half = trimmedBendingEnergy(a, {{0, 0}, {1, 0}, {1, 0.5}, {0, 0.5}}, 60);
  EXPECT_NEAR(half, 0.5 * ea, 2e-2 * ea);
}
