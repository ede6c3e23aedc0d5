#include "fill/bending_energy.h"

#include <algorithm>

#include "geometry/differential_geometry.h"
#include "geometry/error.h"

namespace holefill {

double trimmedBendingEnergy(const BSplineSurface& s, const Polygon2& trim, int grid) {
  HF_CHECK(grid >= 2, "the bending-energy grid needs at least 2 cells per side");
  HF_CHECK(trim.size() >= 3, "the trim polygon needs at least 3 vertices");
  Eigen::Vector2d lo = trim[0], hi = trim[0];
  for (const auto& p : trim) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
  const double u0 = std::max(lo.x(), s.knotsU[s.degreeU]), u1 = std::min(hi.x(), s.knotsU[s.knotsU.size() - s.degreeU - 1]);
  const double v0 = std::max(lo.y(), s.knotsV[s.degreeV]), v1 = std::min(hi.y(), s.knotsV[s.knotsV.size() - s.degreeV - 1]);
  if (!(u1 > u0 && v1 > v0)) return 0.0;
  const double du = (u1 - u0) / grid, dv = (v1 - v0) / grid;
  double e = 0.0;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const Eigen::Vector2d c(u0 + (i + 0.5) * du, v0 + (j + 0.5) * dv);
      if (!contains(trim, c)) continue;
      const auto d = s.derivatives(c.x(), c.y(), 2);
      const SurfaceJet jet{d[0][0], d[1][0], d[0][1], d[2][0], d[1][1], d[0][2]};
      Eigen::Vector3d n;
      if (!unitNormal(jet, n)) continue;
      const PrincipalCurvatures k = principalCurvatures(jet, n);
      e += (k.k1 * k.k1 + k.k2 * k.k2) * jet.su.cross(jet.sv).norm() * du * dv;
    }
  return e;
}

}  // namespace holefill
