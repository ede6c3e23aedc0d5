#include "geometry/differential_geometry.h"

#include <cmath>

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

PrincipalCurvatures principalCurvatures(const SurfaceJet& j, const Eigen::Vector3d& n) {
  Eigen::Matrix2d I, II;
  I << j.su.dot(j.su), j.su.dot(j.sv), j.su.dot(j.sv), j.sv.dot(j.sv);
  II << j.suu.dot(n), j.suv.dot(n), j.suv.dot(n), j.svv.dot(n);
  // II x = k I x: symmetric-definite, so the eigenvalues are real and the directions I-orthogonal.
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(II, I);
  PrincipalCurvatures p;
  p.k2 = es.eigenvalues()(0);
  p.k1 = es.eigenvalues()(1);
  p.gaussian = II.determinant() / I.determinant();
  p.mean = 0.5 * (p.k1 + p.k2);
  const Eigen::Vector2d x1 = es.eigenvectors().col(1);
  p.d1 = (x1(0) * j.su + x1(1) * j.sv).normalized();
  p.d2 = n.cross(p.d1).normalized();
  return p;
}

double curvatureAlong(double k1, double k2, const Eigen::Vector3d& d1, const Eigen::Vector3d& n, const Eigen::Vector3d& d) {
  const Eigen::Vector3d t = d - d.dot(n) * n;
  const double len2 = t.squaredNorm();
  if (len2 <= 0.0) return 0.0;
  const double c2 = std::pow(t.dot(d1), 2) / len2;
  return k1 * c2 + k2 * (1.0 - c2);
}

}  // namespace holefill
