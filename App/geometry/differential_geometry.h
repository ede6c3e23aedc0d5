// First- and second-order differential geometry of parametric surfaces shared
// by boundary sampling, the G2 energy and the continuity report: the unit
// normal, the parameter-space direction of a tangent vector, and the normal
// curvature kappa(d) = II(d, d) / I(d, d) in a tangent direction d (do Carmo, Sec. 3-2).
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

}  // namespace holefill
