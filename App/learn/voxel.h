// Per-axis voxelization of control-point coordinates (uvtran.md Sec. 4.1): each coordinate in
// [0, 1] becomes one of V = 1/dv classes, decoded at the cell centre, so the round trip moves a
// point by at most sqrt(3) dv / 2. Coordinates outside [0, 1] clamp to the first/last class.
#pragma once

#include <algorithm>
#include <cmath>

namespace holefill::learn {

inline int voxelIndex(double x, int classes) {
  const int v = static_cast<int>(std::floor(x * classes));
  return std::clamp(v, 0, classes - 1);
}

inline double voxelCentre(int index, int classes) { return (index + 0.5) / classes; }

}  // namespace holefill::learn
