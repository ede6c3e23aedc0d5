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
  // Closed form of II x = k I x (a 2x2 symmetric-definite pencil): an eigen solver per sample
  // made 1M samples cost twice OCCT's SLProps.
  const double E = j.su.dot(j.su), F = j.su.dot(j.sv), G = j.sv.dot(j.sv);
  const double L = j.suu.dot(n), M = j.suv.dot(n), N = j.svv.dot(n);
  const double detI = E * G - F * F;
  PrincipalCurvatures p;
  p.gaussian = (L * N - M * M) / detI;
  p.mean = (E * N - 2.0 * F * M + G * L) / (2.0 * detI);
  // H^2 - K from the shape operator W = I^-1 II as ((W11 - W22)/2)^2 + W12 W21: near umbilics
  // (spheres) the textbook difference cancels and its square root leaves 1e-9 of noise.
  const double w11 = (G * L - F * M) / detI, w12 = (G * M - F * N) / detI, w21 = (E * M - F * L) / detI,
               w22 = (E * N - F * M) / detI;
  const double disc = std::sqrt(std::max(0.0, 0.25 * (w11 - w22) * (w11 - w22) + w12 * w21));
  p.k1 = p.mean + disc;
  p.k2 = p.mean - disc;
  // (II - k1 I) x = 0: either row gives x; take the better conditioned one.
  const Eigen::Vector2d a(M - p.k1 * F, -(L - p.k1 * E)), b(N - p.k1 * G, -(M - p.k1 * F));
  Eigen::Vector2d x = a.squaredNorm() >= b.squaredNorm() ? a : b;
  if (x.squaredNorm() <= 1e-24 * (L * L + M * M + N * N + 1e-300)) x = Eigen::Vector2d(1, 0);  // umbilic: any direction
  p.d1 = (x(0) * j.su + x(1) * j.sv).normalized();
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
