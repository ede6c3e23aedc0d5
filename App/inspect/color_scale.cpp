#include "inspect/color_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/error.h"

namespace holefill {

namespace {

using RGB = std::array<float, 3>;

RGB lerp(const RGB& a, const RGB& b, double t) {
  return {static_cast<float>(a[0] + (b[0] - a[0]) * t), static_cast<float>(a[1] + (b[1] - a[1]) * t),
          static_cast<float>(a[2] + (b[2] - a[2]) * t)};
}

RGB ramp(const std::vector<RGB>& stops, double t) {
  t = std::clamp(t, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
  const size_t i = std::min(static_cast<size_t>(t), stops.size() - 2);
  return lerp(stops[i], stops[i + 1], t - static_cast<double>(i));
}

// Moreland's cool-warm (diverging) and viridis (sequential), sampled at a few stops.
const std::vector<RGB> kDiverging = {{0.230f, 0.299f, 0.754f}, {0.552f, 0.690f, 0.996f}, {0.865f, 0.865f, 0.865f},
                                     {0.958f, 0.604f, 0.482f}, {0.706f, 0.016f, 0.150f}};
const std::vector<RGB> kSequential = {{0.267f, 0.005f, 0.329f}, {0.283f, 0.141f, 0.458f}, {0.254f, 0.265f, 0.530f},
                                      {0.207f, 0.372f, 0.553f}, {0.164f, 0.471f, 0.558f}, {0.128f, 0.567f, 0.551f},
                                      {0.135f, 0.659f, 0.518f}, {0.267f, 0.749f, 0.441f}, {0.478f, 0.821f, 0.318f},
                                      {0.741f, 0.873f, 0.150f}, {0.993f, 0.906f, 0.144f}};

double percentile(std::vector<double>& v, double p) {
  const double pos = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(v.size() - 1);
  const size_t k = static_cast<size_t>(pos);
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  const double a = v[k];
  if (k + 1 >= v.size()) return a;
  const double b = *std::min_element(v.begin() + static_cast<long>(k) + 1, v.end());
  return a + (b - a) * (pos - static_cast<double>(k));
}

}  // namespace

RGB ColorScale::color(double v) const {
  if (!std::isfinite(v)) return {0.5f, 0.5f, 0.5f};
  const double t = high > low ? (v - low) / (high - low) : 0.5;
  return ramp(diverging ? kDiverging : kSequential, t);
}

std::vector<double> ColorScale::ticks(int approx) const {
  const double span = high - low;
  if (!(span > 0)) return {low};
  const double raw = span / std::max(1, approx - 1), mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw) { step = m * mag; break; }
  std::vector<double> t;
  for (double x = std::ceil(low / step - 1e-9) * step; x <= high + 1e-9 * span; x += step)
    t.push_back(std::abs(x) < 1e-12 * step ? 0.0 : x);
  return t;
}

ColorScale makeColorScale(const Eigen::VectorXd& values, bool signedQuantity, const ColorScaleOptions& o) {
  ColorScale s;
  s.diverging = o.symmetric < 0 ? signedQuantity : o.symmetric == 1;
  if (o.byValue) {
    if (!std::isfinite(o.low) || !std::isfinite(o.high) || !(o.high > o.low))
      throw Error("colour scale by value needs finite low < high");
    s.low = o.low;
    s.high = o.high;
  } else {
    if (!(o.lowPercentile >= 0 && o.lowPercentile < o.highPercentile && o.highPercentile <= 100))
      throw Error("colour scale percentiles must satisfy 0 <= low < high <= 100");
    std::vector<double> v;
    v.reserve(static_cast<size_t>(values.size()));
    for (Eigen::Index i = 0; i < values.size(); ++i)
      if (std::isfinite(values(i))) v.push_back(values(i));
    if (v.empty()) return s;
    s.low = percentile(v, o.lowPercentile);
    s.high = percentile(v, o.highPercentile);
  }
  if (s.diverging && !o.byValue) {
    const double m = std::max(std::abs(s.low), std::abs(s.high));
    s.low = -m;
    s.high = m;
  }
  if (!(s.high > s.low)) {
    // A constant field (a plane, a sphere): widen around the value so it maps to the middle colour.
    const double c = 0.5 * (s.low + s.high), w = std::max(1e-9, std::abs(c) * 0.1);
    s.low = c - w;
    s.high = c + w;
  }
  return s;
}

std::string tickLabel(double v) {
  char buf[32];
  if (v == 0.0) return "0";
  const double a = std::abs(v);
  if (a >= 1e-3 && a < 1e4) std::snprintf(buf, sizeof buf, "%.4g", v);
  else std::snprintf(buf, sizeof buf, "%.2e", v);
  return buf;
}

}  // namespace holefill
