#include "inspect/color_scale.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/error.h"

using namespace holefill;

namespace {

Eigen::VectorXd linspace(double a, double b, int n) { return Eigen::VectorXd::LinSpaced(n, a, b); }

}  // namespace

TEST(ColorScale, SignedQuantitiesGetASymmetricDivergingScale) {
  Eigen::VectorXd v(5);
  v << -0.1, 0.0, 0.2, 0.5, std::nan("");
  ColorScaleOptions o;
  o.lowPercentile = 0;
  o.highPercentile = 100;
  const ColorScale s = makeColorScale(v, true, o);
  EXPECT_TRUE(s.diverging);
  EXPECT_DOUBLE_EQ(s.low, -0.5);
  EXPECT_DOUBLE_EQ(s.high, 0.5);
  const auto mid = s.color(0.0), grey = s.color(std::nan(""));
  EXPECT_NEAR(mid[0], mid[2], 1e-6);  // zero is the neutral middle
  EXPECT_FLOAT_EQ(grey[0], 0.5f);
  EXPECT_GT(s.color(0.5)[0], s.color(0.5)[2]);   // positive red
  EXPECT_LT(s.color(-0.5)[0], s.color(-0.5)[2]); // negative blue
  const ColorScale u = makeColorScale(v, false, o);
  EXPECT_FALSE(u.diverging);
  EXPECT_DOUBLE_EQ(u.low, -0.1);
  EXPECT_DOUBLE_EQ(u.high, 0.5);
}

TEST(ColorScale, PercentilesClampSpikesAndTicksAreInside) {
  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(1001, 0.0, 1.0);
  v(0) = -1e6;  // a spike at a pole
  const ColorScale s = makeColorScale(v, false, {});
  EXPECT_NEAR(s.low, 0.02, 1e-3);
  EXPECT_NEAR(s.high, 0.98, 1e-3);
  const auto ticks = s.ticks(5);
  ASSERT_GE(ticks.size(), 3u);
  for (double t : ticks) {
    EXPECT_GE(t, s.low - 1e-12);
    EXPECT_LE(t, s.high + 1e-12);
  }
  ColorScaleOptions byValue;
  byValue.byValue = true;
  byValue.low = -2;
  byValue.high = 3;
  const ColorScale b = makeColorScale(v, true, byValue);
  EXPECT_EQ(b.low, -2);
  EXPECT_EQ(b.high, 3);
  byValue.high = -5;
  EXPECT_THROW(makeColorScale(v, true, byValue), Error);
  // A constant field (a sphere) still gets a valid range around its value.
  const ColorScale c = makeColorScale(Eigen::VectorXd::Constant(10, 0.25), false, {});
  EXPECT_LT(c.low, 0.25);
  EXPECT_GT(c.high, 0.25);
  EXPECT_EQ(tickLabel(0.0), "0");
  EXPECT_EQ(tickLabel(2.5e-5), "2.50e-05");
}

TEST(ColorScale, NaNIsGreyAndAConstantFieldMapsToTheMiddle) {
  Eigen::VectorXd v = Eigen::VectorXd::Constant(10, 0.5);  // a sphere's mean curvature
  v(3) = std::nan("");
  const ColorScale s = makeColorScale(v, false, {});
  EXPECT_LT(s.low, 0.5);
  EXPECT_GT(s.high, 0.5);
  EXPECT_NEAR(0.5 * (s.low + s.high), 0.5, 1e-12);
  const auto g = s.color(std::nan(""));
  EXPECT_FLOAT_EQ(g[0], 0.5f);
  EXPECT_FLOAT_EQ(g[2], 0.5f);
  // Only NaN: the default range, no crash.
  const ColorScale empty = makeColorScale(Eigen::VectorXd::Constant(4, std::nan("")), true, {});
  EXPECT_TRUE(std::isfinite(empty.low) && std::isfinite(empty.high) && empty.high > empty.low);
}

TEST(ColorScale, ByValueKeepsTheRangeAsGivenAndRefusesABadOne) {
  ColorScaleOptions o;
  o.byValue = true;
  o.low = -0.2;
  o.high = 0.6;
  const ColorScale s = makeColorScale(linspace(-5, 5, 11), true, o);
  EXPECT_DOUBLE_EQ(s.low, -0.2);  // as given, not made symmetric
  EXPECT_DOUBLE_EQ(s.high, 0.6);
  o.high = o.low;
  EXPECT_THROW(makeColorScale(linspace(0, 1, 3), false, o), Error);
  ColorScaleOptions p;
  p.lowPercentile = 60;
  p.highPercentile = 40;
  EXPECT_THROW(makeColorScale(linspace(0, 1, 3), false, p), Error);
}

TEST(ColorScale, TicksAreNiceNumbersInsideTheRangeAndLabelsAreShort) {
  ColorScale s;
  s.low = -0.0123;
  s.high = 0.0123;
  const std::vector<double> t = s.ticks(5);
  ASSERT_GE(t.size(), 3u);
  for (double x : t) {
    EXPECT_GE(x, s.low - 1e-15);
    EXPECT_LE(x, s.high + 1e-15);
    const double m = std::abs(x) / 0.005;  // steps of 0.005 here (1, 2, 2.5 or 5 times a power of ten)
    EXPECT_NEAR(m, std::round(m), 1e-9) << x;
  }
  EXPECT_NE(std::find(t.begin(), t.end(), 0.0), t.end());  // zero is a tick, written "0"
  EXPECT_EQ(tickLabel(0.0), "0");
  EXPECT_EQ(tickLabel(-0.012), "-0.012");
  EXPECT_EQ(tickLabel(2.5e-5), "2.50e-05");
}
