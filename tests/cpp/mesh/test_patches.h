// Small hole patches for the mesh units' tests.
#pragma once

#include <cmath>
#include <functional>

#include "mesh/hole_patch.h"

namespace holefill::testpatches {

// A hexagonal fan: the loop on the unit circle at height z(x, y), one new vertex in the middle.
inline HolePatch fan(double centreZ, const std::function<double(double, double)>& z) {
  HolePatch p;
  for (int k = 0; k < 6; ++k) {
    const double a = M_PI / 3 * k, x = std::cos(a), y = std::sin(a);
    p.points.emplace_back(x, y, z(x, y));
  }
  p.boundaryCount = 6;
  p.points.emplace_back(0, 0, centreZ);
  for (int k = 0; k < 6; ++k) p.triangles.push_back({k, (k + 1) % 6, 6});
  p.scale.assign(7, 1.0);
  return p;
}

}  // namespace holefill::testpatches
