#include "inspect/inspection_values.h"

#include <cmath>
#include <limits>

#include "geometry/differential_geometry.h"
#include "geometry/error.h"

namespace holefill {

CurvatureQuantity curvatureQuantityFromString(const std::string& s) {
  if (s == "gauss" || s == "gaussian") return CurvatureQuantity::Gaussian;
  if (s == "mean") return CurvatureQuantity::Mean;
  if (s == "max") return CurvatureQuantity::MaxPrincipal;
  if (s == "min") return CurvatureQuantity::MinPrincipal;
  if (s == "direction") return CurvatureQuantity::Direction;
  throw Error("unknown curvature quantity '" + s + "': use gauss, mean, max, min or direction");
}

std::string toString(CurvatureQuantity q) {
  switch (q) {
    case CurvatureQuantity::Gaussian: return "gauss";
    case CurvatureQuantity::Mean: return "mean";
    case CurvatureQuantity::MaxPrincipal: return "max";
    case CurvatureQuantity::MinPrincipal: return "min";
    case CurvatureQuantity::Direction: return "direction";
  }
  return "?";
}

bool isSigned(CurvatureQuantity q) { return q == CurvatureQuantity::Gaussian || q == CurvatureQuantity::Mean; }

Eigen::VectorXd curvatureValues(const SurfaceFields& f, CurvatureQuantity q, const Eigen::Vector3d& direction) {
  const Eigen::Index n = f.size();
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double k1 = f.k1(i), k2 = f.k2(i);
    switch (q) {
      case CurvatureQuantity::Gaussian: v(i) = k1 * k2; break;
      case CurvatureQuantity::Mean: v(i) = 0.5 * (k1 + k2); break;
      case CurvatureQuantity::MaxPrincipal: v(i) = k1; break;
      case CurvatureQuantity::MinPrincipal: v(i) = k2; break;
      case CurvatureQuantity::Direction:
        v(i) = f.regular[static_cast<size_t>(i)]
                   ? curvatureAlong(k1, k2, f.d1.row(i).transpose(), f.normals.row(i).transpose(), direction)
                   : std::numeric_limits<double>::quiet_NaN();
        break;
    }
  }
  return v;
}

StripeMode stripeModeFromString(const std::string& s) {
  if (s == "reflection" || s == "zebra") return StripeMode::Reflection;
  if (s == "isophote" || s == "isophotes") return StripeMode::Isophote;
  throw Error("unknown stripe mode '" + s + "': use reflection or isophote");
}

double stripeParameter(const Eigen::Vector3d& n, const Eigen::Vector3d& view, const Eigen::Vector3d& d, StripeMode mode) {
  const Eigen::Vector3d a = mode == StripeMode::Isophote ? n : Eigen::Vector3d(view - 2.0 * view.dot(n) * n);
  const double c = a.dot(d) / std::max(a.norm() * d.norm(), 1e-300);
  return std::acos(std::clamp(c, -1.0, 1.0)) / M_PI;
}

bool stripeBlack(double s, const StripeOptions& o) {
  const double x = s * o.count;
  return x - std::floor(x) < o.width;
}

Eigen::Vector3d stripeDirection(const StripeOptions& o, const Eigen::Vector3d& view, const Eigen::Vector3d& up) {
  if (o.mode == StripeMode::Isophote) return o.isophoteDirection.normalized();
  const Eigen::Vector3d right = view.cross(up).normalized(), u = right.cross(view).normalized();
  const double a = o.angleDeg * M_PI / 180.0;
  return std::cos(a) * right + std::sin(a) * u;
}

}  // namespace holefill
