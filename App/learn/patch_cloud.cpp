#include "learn/patch_cloud.h"

#include <cmath>
#include <random>

#include "geometry/error.h"

namespace holefill::learn {

namespace {

double bernstein(int n, int i, double t) {
  double binom = 1;
  for (int k = 1; k <= i; ++k) binom = binom * (n - k + 1) / k;
  return binom * std::pow(t, i) * std::pow(1 - t, n - i);
}

}  // namespace

uint64_t patchCloudSeed(PatchCloudSplit split, uint64_t index) {
  const uint64_t base = split == PatchCloudSplit::Train ? 0 : split == PatchCloudSplit::Validation ? (1ull << 40) : (2ull << 40);
  return base + index;
}

PatchCloud randomPatchCloud(uint64_t seed, const PatchCloudOptions& o) {
  HF_CHECK(o.degree >= 1 && o.degree <= 7, "patch clouds take degrees 1 to 7");
  HF_CHECK(o.boundary >= 4 && o.interior >= 0, "a patch cloud needs at least its 4 corners on the boundary");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1), jitter(-0.25, 0.25), height(-1, 1);
  const int n = o.degree;
  // The paper's boxes for degree 2 (spacing 1/2 about a unit grid), the same spacing 1/n otherwise.
  std::vector<Eigen::Vector3d> c((n + 1) * (n + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      c[i * (n + 1) + j] = Eigen::Vector3d(double(i) / n + jitter(rng) * 2.0 / n, double(j) / n + jitter(rng) * 2.0 / n, height(rng));
  const Eigen::Vector3d axis = Eigen::Vector3d(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5).normalized();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(2 * M_PI * U(rng), axis).toRotationMatrix();
  const auto S = [&](double u, double v) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) p += bernstein(n, i, u) * bernstein(n, j, v) * c[i * (n + 1) + j];
    return Eigen::Vector3d(R * p);
  };
  const int total = o.interior + o.boundary;
  PatchCloud cl;
  cl.points.resize(total, 3);
  cl.uv.resize(total, 2);
  cl.boundary.assign(total, false);
  for (int k = 0; k < total; ++k) {
    double u = U(rng), v = U(rng);
    if (k < o.boundary) {
      const int side = k < 4 ? k : static_cast<int>(4 * U(rng)) % 4;
      const double t = k < 4 ? 0.0 : U(rng);
      const double su[4] = {t, 1, 1 - t, 0}, sv[4] = {0, t, 1, 1 - t};
      u = su[side], v = sv[side];
      cl.boundary[k] = true;
    }
    cl.points.row(k) = S(u, v).transpose();
    cl.uv.row(k) << u, v;
  }
  const Eigen::RowVector3d lo = cl.points.colwise().minCoeff();
  cl.points = (cl.points.rowwise() - lo) / (cl.points.colwise().maxCoeff() - lo).maxCoeff();
  if (o.sigma > 0) {
    std::normal_distribution<double> noise(0, o.sigma);
    for (Eigen::Index k = 0; k < cl.points.size(); ++k) cl.points.data()[k] += noise(rng);
  }
  return cl;
}

double bezierFitMse(const Eigen::MatrixX3d& p, const Eigen::MatrixX2d& uv, int degree) {
  HF_CHECK(p.rows() == uv.rows() && p.rows() > 0, "bezierFitMse needs one parameter pair per point");
  const int m = degree + 1;
  Eigen::MatrixXd B(p.rows(), m * m);
  for (Eigen::Index k = 0; k < p.rows(); ++k)
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) B(k, m * i + j) = bernstein(degree, i, uv(k, 0)) * bernstein(degree, j, uv(k, 1));
  const Eigen::MatrixX3d C = B.colPivHouseholderQr().solve(p);
  return (B * C - p).rowwise().squaredNorm().mean();
}

}  // namespace holefill::learn
