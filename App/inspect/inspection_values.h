// What the inspection maps show per vertex or pixel: a curvature quantity (Gaussian,
// mean, max/min principal, or the normal curvature along a fixed direction) and the
// stripe parameter of zebra pictures. Reflection lines (Klass 1980) follow the view:
// the view ray is mirrored at the surface normal and the stripes are cones of equal
// angle between the mirrored ray and a stripe direction fixed in the view, so a G1 break
// cuts a stripe and a G2 break kinks it. Isophotes use the normal itself against a fixed
// world direction, so they stay put when the camera moves. One formula serves the
// software renderer here and the GPU shader in Gui/ (which repeats these few lines in GLSL).
#pragma once

#include <Eigen/Dense>
#include <string>

#include "inspect/surface_fields.h"

namespace holefill {

enum class CurvatureQuantity { Gaussian, Mean, MaxPrincipal, MinPrincipal, Direction };
CurvatureQuantity curvatureQuantityFromString(const std::string& s);  // gauss|gaussian|mean|max|min|direction
std::string toString(CurvatureQuantity q);
// Gaussian and mean curvature change sign meaningfully: they get a symmetric diverging scale.
bool isSigned(CurvatureQuantity q);

// Per-vertex values; `direction` (world) is used by Direction only. NaN at singular points.
Eigen::VectorXd curvatureValues(const SurfaceFields& f, CurvatureQuantity q,
                                const Eigen::Vector3d& direction = Eigen::Vector3d::UnitX());

enum class StripeMode { Reflection, Isophote };
StripeMode stripeModeFromString(const std::string& s);  // reflection|isophote

struct StripeOptions {
  StripeMode mode = StripeMode::Reflection;
  int count = 16;          // stripe pairs over the half-turn of the parameter (0..pi)
  double width = 0.5;      // share of each period that is black
  // Reflection: stripe direction in view coordinates (x right, y up) as an angle in degrees.
  // Isophote: the world direction `isophoteDirection`.
  double angleDeg = 0.0;
  Eigen::Vector3d isophoteDirection = Eigen::Vector3d::UnitZ();
};

// Stripe parameter in [0, 1]: angle(a, d) / pi with a = normal (isophote) or the view ray
// mirrored at the normal (reflection). `view` points from the eye into the scene.
double stripeParameter(const Eigen::Vector3d& normal, const Eigen::Vector3d& view, const Eigen::Vector3d& stripeDir,
                       StripeMode mode);
// True where the stripe is black.
bool stripeBlack(double parameter, const StripeOptions& o);

// The world stripe direction for a view given by its direction and up vector.
Eigen::Vector3d stripeDirection(const StripeOptions& o, const Eigen::Vector3d& view, const Eigen::Vector3d& up);

}  // namespace holefill
