#include "geometry/differential_geometry.h"

namespace holefill {

bool unitNormal(const SurfaceJet& j, Eigen::Vector3d& n) {
  const Eigen::Vector3d c = j.su.cross(j.sv);
  const double len = c.norm(), ref = j.su.norm() * j.sv.norm();
  if (!(len > 1e-10 * ref) || ref == 0.0) return false;
  n = c / len;
  return true;
}

Eigen::Vector2d parameterDirection(const SurfaceJet& j, const Eigen::Vector3d& d) {
  Eigen::Matrix2d G;
  G << j.su.dot(j.su), j.su.dot(j.sv), j.su.dot(j.sv), j.sv.dot(j.sv);
  return G.ldlt().solve(Eigen::Vector2d(j.su.dot(d), j.sv.dot(d)));
}

double normalCurvature(const SurfaceJet& j, const Eigen::Vector3d& n, const Eigen::Vector3d& d) {
  const Eigen::Vector2d ab = parameterDirection(j, d);
  const Eigen::Vector3d t = ab(0) * j.su + ab(1) * j.sv;
  const double I = t.squaredNorm();
  if (I <= 0.0) return 0.0;
  const double II = (ab(0) * ab(0) * j.suu + 2.0 * ab(0) * ab(1) * j.suv + ab(1) * ab(1) * j.svv).dot(n);
  return II / I;
}

}  // namespace holefill
