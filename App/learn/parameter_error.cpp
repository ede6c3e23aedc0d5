#include "learn/parameter_error.h"

#include <cmath>

#include "geometry/error.h"

namespace holefill::learn {

double parameterError(const std::vector<Eigen::Vector2d>& uv, const std::vector<Eigen::Vector2d>& truth) {
  HF_CHECK(uv.size() == truth.size() && !uv.empty(), "parameter lists must match");
  double e = 0;
  for (size_t i = 0; i < uv.size(); ++i) e += (uv[i] - truth[i]).norm();
  return e / uv.size();
}

double alignedParameterError(const std::vector<Eigen::Vector2d>& uv, const std::vector<Eigen::Vector2d>& truth) {
  HF_CHECK(uv.size() == truth.size() && !uv.empty(), "parameter lists must match");
  const size_t n = uv.size();
  Eigen::Vector2d ca = Eigen::Vector2d::Zero(), cb = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < n; ++i) { ca += uv[i]; cb += truth[i]; }
  ca /= double(n);
  cb /= double(n);
  double best = 1e300;
  for (double flip : {1.0, -1.0}) {  // both handednesses
    // 2D least-squares similarity in closed form: x -> s R(theta) x with tan(theta) = sum(x cross y) / sum(x . y).
    double dot = 0, cross = 0, xx = 0;
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d x((uv[i] - ca).x() * flip, (uv[i] - ca).y()), y = truth[i] - cb;
      dot += x.dot(y);
      cross += x.x() * y.y() - x.y() * y.x();
      xx += x.squaredNorm();
    }
    if (!(xx > 0)) continue;
    const double th = std::atan2(cross, dot), sc = std::hypot(dot, cross) / xx;
    const Eigen::Matrix2d R = sc * Eigen::Rotation2Dd(th).toRotationMatrix();
    std::vector<Eigen::Vector2d> moved;
    for (size_t i = 0; i < n; ++i)
      moved.push_back(cb + R * Eigen::Vector2d((uv[i] - ca).x() * flip, (uv[i] - ca).y()));
    best = std::min(best, parameterError(moved, truth));
  }
  return best;
}

std::vector<Eigen::Vector2d> classicalParameters(const UvtranSample& x, ParamMethod method) {
  Hole hole;
  const int n = static_cast<int>(x.boundary.size());
  const int N = static_cast<int>(x.cornerSamples.size());
  std::vector<BoundarySample> s(n);
  for (int c = 0; c < N; ++c) {
    HoleEdge e;
    e.cornerAtStart = true;
    hole.edges.push_back(e);
    const int a = x.cornerSamples[c], b = c + 1 < N ? x.cornerSamples[c + 1] : x.cornerSamples[0] + n;
    for (int k = a; k < b; ++k) s[k % n].edge = c;
  }
  hole.corners = N;
  for (int i = 0; i < n; ++i) {
    s[i].point = x.boundary[i];
    s[i].weight = 0.5 * ((x.boundary[(i + 1) % n] - x.boundary[i]).norm() + (x.boundary[i] - x.boundary[(i + n - 1) % n]).norm());
  }
  // Edges must start at sample 0 for MVC's corner search: rotate so the first corner is sample 0.
  const int r = N ? x.cornerSamples[0] : 0;
  std::vector<BoundarySample> rot(n);
  for (int i = 0; i < n; ++i) rot[i] = s[(i + r) % n];
  const Parameterization P = parameterize(hole, rot, method);
  std::vector<Eigen::Vector2d> uv(n);
  for (int i = 0; i < n; ++i) uv[(i + r) % n] = P.uv[i];
  return uv;
}

}  // namespace holefill::learn
