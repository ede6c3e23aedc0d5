// First- and second-order differential geometry of parametric surfaces shared
// by boundary sampling, the G2 energy and the continuity report: the unit
// normal, the parameter-space direction of a tangent vector, and the normal
// curvature kappa(d) = II(d, d) / I(d, d) in a tangent direction d (do Carmo, Sec. 3-2),
// and the principal curvatures and directions from the shape operator I^-1 II
// (do Carmo, Sec. 3-3) that the inspection maps colour.
#pragma once

#include <Eigen/Dense>

namespace holefill {

struct SurfaceJet {
  Eigen::Vector3d p, su, sv, suu, suv, svv;
};

// Unit normal su x sv; false when the surface is singular there (|su x sv| ~ 0).
bool unitNormal(const SurfaceJet& j, Eigen::Vector3d& n);

// (a, b) with a*su + b*sv closest to the tangent vector d (least squares over the tangent plane).
Eigen::Vector2d parameterDirection(const SurfaceJet& j, const Eigen::Vector3d& d);

// Normal curvature in the direction of tangent vector d, signed with respect to n.
double normalCurvature(const SurfaceJet& j, const Eigen::Vector3d& n, const Eigen::Vector3d& d);

// Principal curvatures k1 >= k2 (signed with respect to n) with their unit tangent directions;
// gaussian = k1 k2, mean = (k1 + k2) / 2. At umbilics d1, d2 are an arbitrary orthonormal pair.
struct PrincipalCurvatures {
  double k1 = 0, k2 = 0, gaussian = 0, mean = 0;
  Eigen::Vector3d d1 = Eigen::Vector3d::Zero(), d2 = Eigen::Vector3d::Zero();
};
PrincipalCurvatures principalCurvatures(const SurfaceJet& j, const Eigen::Vector3d& n);

// Normal curvature along tangent direction d from the principal frame (Euler's theorem,
// k1 cos^2 + k2 sin^2 of the angle to d1); d is projected onto the tangent plane n^perp first.
double curvatureAlong(double k1, double k2, const Eigen::Vector3d& d1, const Eigen::Vector3d& n, const Eigen::Vector3d& d);

}  // namespace holefill
