// Point-cloud parameterization methods side by side on the bidgcn paper's test data (bidgcn.md
// sec. 4.2/5): clouds of N interior points and 34 boundary points with exact parameters, sampled
// from random biquadratic Bézier patches (control points c_ij from [i/2 ± 1/4] × [j/2 ± 1/4] ×
// [−1, 1]), randomly rotated, scaled into the unit cube, Gaussian noise σ added to every
// coordinate. Measure per method: the least-squares biquadratic fit's mean squared residual at the
// method's parameters (the paper's quality measure, eq. (2)), failures (no parameters), time.
// Prints a Markdown table; `scripts/bench.sh` runs it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "fitting/cloud_parameterization.h"

using namespace holefill;

namespace {

double bernstein2(int i, double t) {
  const double s = 1 - t;
  return i == 0 ? s * s : i == 1 ? 2 * s * t : t * t;
}

struct Cloud {
  Eigen::MatrixX3d points;
  std::vector<bool> boundary;
  Eigen::MatrixX2d uv;
};

Cloud sample(int interior, double sigma, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0, 1), jitter(-0.25, 0.25), height(-1, 1);
  Eigen::Vector3d c[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = Eigen::Vector3d(i / 2.0 + jitter(rng), j / 2.0 + jitter(rng), height(rng));
  const Eigen::Vector3d axis = Eigen::Vector3d(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5).normalized();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(2 * M_PI * U(rng), axis).toRotationMatrix();
  const auto S = [&](double u, double v) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) p += bernstein2(i, u) * bernstein2(j, v) * c[i][j];
    return Eigen::Vector3d(R * p);
  };
  const int boundary = 34, n = interior + boundary;
  Cloud cl;
  cl.points.resize(n, 3);
  cl.uv.resize(n, 2);
  cl.boundary.assign(n, false);
  for (int k = 0; k < n; ++k) {
    double u = U(rng), v = U(rng);
    if (k < boundary) {  // the four corners, then random points on random sides
      const int side = k < 4 ? k : static_cast<int>(4 * U(rng));
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
  std::normal_distribution<double> noise(0, sigma > 0 ? sigma : 1);
  if (sigma > 0)
    for (Eigen::Index k = 0; k < cl.points.size(); ++k) cl.points.data()[k] += noise(rng);
  return cl;
}

// Mean squared residual of the least-squares biquadratic Bézier fit at the parameters.
double biquadraticMse(const Eigen::MatrixX3d& p, const Eigen::MatrixX2d& uv) {
  Eigen::MatrixXd B(p.rows(), 9);
  for (Eigen::Index k = 0; k < p.rows(); ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) B(k, 3 * i + j) = bernstein2(i, uv(k, 0)) * bernstein2(j, uv(k, 1));
  const Eigen::MatrixX3d C = B.colPivHouseholderQr().solve(p);
  return (B * C - p).rowwise().squaredNorm().mean();
}

}  // namespace

int main(int argc, char** argv) {
  const int clouds = argc > 1 ? std::atoi(argv[1]) : 100;
  std::printf("| interior points | noise σ | method | median MSE | mean MSE | failed | fallbacks (median) | time per cloud (median, ms) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  const std::pair<const char*, CloudWeights> methods[] = {
      {"shape-preserving", CloudWeights::ShapePreserving}, {"inverse distance", CloudWeights::InverseDistance}, {"uniform", CloudWeights::Uniform}};
  for (int interior : {200, 1000, 2000})
    for (double sigma : {0.0, 0.005, 0.01, 0.05}) {
      if (interior != 1000 && sigma > 0) continue;  // sizes noise-free, noise at 1000 points
      for (const auto& [name, weights] : methods) {
        std::mt19937 rng(1234);  // the same clouds for every method
        std::vector<double> mse, ms, fb;
        int failed = 0;
        double truthMse = 0;
        for (int c = 0; c < clouds; ++c) {
          const Cloud cl = sample(interior, sigma, rng);
          truthMse += biquadraticMse(cl.points, cl.uv) / clouds;
          CloudParameterizationOptions o;
          o.weights = weights;
          try {
            const auto t0 = std::chrono::steady_clock::now();
            const CloudParameterization p = parameterizeCloud(cl.points, cl.boundary, cl.uv, o);
            ms.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            mse.push_back(biquadraticMse(cl.points, p.uv));
            fb.push_back(p.fallbacks);
          } catch (const std::exception&) {
            ++failed;
          }
        }
        const auto median = [](std::vector<double> v) {
          if (v.empty()) return std::nan("");
          std::sort(v.begin(), v.end());
          return v[v.size() / 2];
        };
        double mean = 0;
        for (double x : mse) mean += x / std::max<size_t>(1, mse.size());
        std::printf("| %d | %g | %s | %.3e | %.3e | %d of %d | %.0f | %.1f |\n", interior, sigma, name, median(mse), mean, failed, clouds, median(fb), median(ms));
        if (weights == CloudWeights::Uniform)
          std::printf("| %d | %g | (exact parameters) | — | %.3e | — | — | — |\n", interior, sigma, truthMse);
        std::fflush(stdout);
      }
    }
  return 0;
}
