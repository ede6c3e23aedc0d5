// Colour scales of the curvature maps. Signed quantities (Gaussian, mean) get a symmetric
// diverging blue-white-red scale centred on zero, so flat and saddle regions read at a
// glance; the others a sequential perceptual scale (viridis-like). The range is clamped by
// percentiles of the values (robust against the curvature spikes at a boundary or a pole)
// or given by value. The legend ticks are "nice" numbers inside the range.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

namespace holefill {

struct ColorScaleOptions {
  bool byValue = false;           // false: clamp by percentiles; true: [low, high] as given
  double lowPercentile = 2.0;     // percent of the finite values below the range (clamped)
  double highPercentile = 98.0;
  double low = 0.0, high = 0.0;   // used when byValue
  int symmetric = -1;             // -1: by quantity (diverging), 0: no, 1: yes
};

struct ColorScale {
  double low = 0.0, high = 1.0;
  bool diverging = false;
  // RGB in [0, 1]; values outside the range get the end colours, NaN grey.
  std::array<float, 3> color(double v) const;
  std::vector<double> ticks(int approx = 5) const;
};

// `signedQuantity` decides symmetric/diverging when options.symmetric is -1.
ColorScale makeColorScale(const Eigen::VectorXd& values, bool signedQuantity, const ColorScaleOptions& o = {});

// Short label for a tick value, e.g. "-0.012", "2.5e-05", "0".
std::string tickLabel(double v);

}  // namespace holefill
