#include "fitting/slim_descent.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/error.h"

namespace holefill {

namespace {

// The map's edge matrix [p1 − p0, p2 − p0] of triangle t from the stacked coordinates U.
Eigen::Matrix2d edges(const Eigen::VectorXd& U, const Eigen::MatrixX3i& tri, int t) {
  Eigen::Matrix2d D;
  for (int m = 0; m < 2; ++m)
    for (int c = 0; c < 2; ++c) D(c, m) = U[2 * tri(t, m + 1) + c] - U[2 * tri(t, 0) + c];
  return D;
}

bool isSoft(const SlimProblem& p, int t) { return !p.soft.empty() && p.soft[t]; }

// The rotation nearest to J (a proper one, also where J is a reflection).
Eigen::Matrix2d nearestRotation(const Eigen::Matrix2d& J) {
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d D = Eigen::Matrix2d::Identity();
  D(1, 1) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  return svd.matrixU() * D * svd.matrixV().transpose();
}

// Σ A_t (|J|² + |J⁻¹|²) / Σ A_t (soft triangles: A_t |J − R|²); |J⁻¹|² = |J|² / det(J)² for a 2 × 2 matrix. Infinite once a
// triangle that counts is flat or turned over.
double energyOf(const SlimProblem& p, const std::vector<Eigen::Matrix2d>& restInverse, const std::vector<double>& area, double totalArea,
                const Eigen::VectorXd& U) {
  double e = 0;
  for (int t = 0; t < static_cast<int>(area.size()); ++t) {
    if (p.skip[t]) continue;
    const Eigen::Matrix2d J = edges(U, p.triangles, t) * restInverse[t];
    if (isSoft(p, t)) {
      e += area[t] * (J - nearestRotation(J)).squaredNorm();
      continue;
    }
    const double det = J.determinant();
    if (!(det > 0)) return std::numeric_limits<double>::infinity();
    e += area[t] * J.squaredNorm() * (1 + 1 / (det * det));
  }
  return e / totalArea;
}

// The largest step along dU (at most 1) that keeps every counted triangle's area positive: the
// smallest positive root of det(D + α dD), a quadratic in α, over the triangles, with a margin.
double maxStep(const SlimProblem& p, const Eigen::VectorXd& U, const Eigen::VectorXd& dU) {
  double step = 1;
  for (int t = 0; t < p.triangles.rows(); ++t) {
    if (p.skip[t] || isSoft(p, t)) continue;
    const Eigen::Matrix2d D = edges(U, p.triangles, t), d = edges(dU, p.triangles, t);
    const double a = d.determinant(), c = D.determinant();
    const double b = D(0, 0) * d(1, 1) + d(0, 0) * D(1, 1) - D(0, 1) * d(1, 0) - d(0, 1) * D(1, 0);
    double root = std::numeric_limits<double>::infinity();
    if (std::abs(a) <= 1e-14 * (std::abs(b) + std::abs(c))) {
      if (b < 0) root = -c / b;
    } else {
      const double disc = b * b - 4 * a * c;
      if (disc >= 0) {
        const double s = std::sqrt(disc);
        for (double r : {(-b - s) / (2 * a), (-b + s) / (2 * a)})
          if (r > 0) root = std::min(root, r);
      }
    }
    step = std::min(step, 0.9 * root);
  }
  return step;
}

}  // namespace

std::vector<Eigen::Matrix2d> restShapes(const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles) {
  std::vector<Eigen::Matrix2d> rest(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Eigen::Vector3d p0 = vertices.row(triangles(t, 0)), e1 = vertices.row(triangles(t, 1)).transpose() - p0,
                          e2 = vertices.row(triangles(t, 2)).transpose() - p0;
    const double l1 = e1.norm();
    rest[t] << l1, l1 > 0 ? e1.dot(e2) / l1 : 0, 0, l1 > 0 ? e1.cross(e2).norm() / l1 : 0;
  }
  return rest;
}

double mappedArea(const SlimProblem& problem, const Eigen::VectorXd& z, int t) {
  const Eigen::VectorXd U = problem.map * z;
  return 0.5 * edges(U, problem.triangles, t).determinant();
}

SlimResult slimDescent(const SlimProblem& p, const Eigen::VectorXd& z0, const SlimOptions& o) {
  const int nt = static_cast<int>(p.triangles.rows());
  if (static_cast<int>(p.rest.size()) != nt || static_cast<int>(p.skip.size()) != nt || !(p.soft.empty() || static_cast<int>(p.soft.size()) == nt) ||
      p.map.cols() != z0.size() ||
      p.map.rows() < 2 * (p.triangles.size() ? p.triangles.maxCoeff() + 1 : 0))
    throw Error("the map's unknowns, triangles and rest shapes disagree in number");
  std::vector<Eigen::Matrix2d> restInverse(nt, Eigen::Matrix2d::Zero());
  std::vector<double> area(nt, 0);
  double totalArea = 0;
  for (int t = 0; t < nt; ++t) {
    if (p.skip[t]) continue;
    const double det = p.rest[t].determinant();
    // A triangle without area at rest has no distortion to measure; it is left out.
    if (!(det > 0)) continue;
    restInverse[t] = p.rest[t].inverse();
    area[t] = 0.5 * det;
    totalArea += area[t];
  }
  if (!(totalArea > 0)) throw Error("the mesh has no area to map");
  SlimProblem q = p;  // triangles without rest area join the skipped ones
  for (int t = 0; t < nt; ++t) q.skip[t] = p.skip[t] || !(area[t] > 0);

  SlimResult r;
  r.z = z0;
  Eigen::VectorXd U = q.map * r.z;
  r.startEnergy = r.energy = energyOf(q, restInverse, area, totalArea, U);
  if (!std::isfinite(r.energy)) throw Error("the map to improve turns a triangle over or flattens it");

  // The global step's rows (4 per triangle: the entries of W (J − R)) over the stacked uv have a
  // fixed pattern; only their values change with the weights.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool analysed = false;
  for (int it = 0; it < o.iterations; ++it) {
    std::vector<Eigen::Triplet<double>> T;
    T.reserve(static_cast<size_t>(nt) * 24);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(4 * nt);
    // Rows √A_t W (J_t − R_t), J_t linear in the corners' uv through the rest shape's inverse.
    auto addRows = [&](int t, const Eigen::Matrix2d& W, const Eigen::Matrix2d& R) {
      const Eigen::Matrix2d target = W * R;
      const double sa = std::sqrt(area[t]);
      const Eigen::Matrix2d& G = restInverse[t];
      for (int rr = 0; rr < 2; ++rr)
        for (int j = 0; j < 2; ++j) {
          const int row = 4 * t + 2 * rr + j;
          const double g[3] = {-(G(0, j) + G(1, j)), G(0, j), G(1, j)};
          for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 2; ++c) T.emplace_back(row, 2 * q.triangles(t, k) + c, sa * W(rr, c) * g[k]);
          b[row] = sa * target(rr, j);
        }
    };
    for (int t = 0; t < nt; ++t) {
      if (q.skip[t]) continue;
      const Eigen::Matrix2d J = edges(U, q.triangles, t) * restInverse[t];
      if (isSoft(q, t)) {
        addRows(t, Eigen::Matrix2d::Identity(), nearestRotation(J));
        continue;
      }
      Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
      Eigen::Matrix2d Uu = svd.matrixU(), V = svd.matrixV();
      // J has a positive determinant, so U Vᵀ is a rotation once U and V agree in handedness.
      if (Uu.determinant() * V.determinant() < 0) Uu.col(1) *= -1;
      const Eigen::Matrix2d R = Uu * V.transpose();
      // Weights of the symmetric Dirichlet energy's proxy: w² = (σ − σ⁻³) / (σ − 1), 4 at σ = 1.
      Eigen::Vector2d w;
      for (int k = 0; k < 2; ++k) {
        const double sk = svd.singularValues()[k];
        w[k] = std::abs(sk - 1) < 1e-8 ? 2 : std::sqrt((sk - std::pow(sk, -3)) / (sk - 1));
      }
      addRows(t, Uu * w.asDiagonal() * Uu.transpose(), R);
    }
    Eigen::SparseMatrix<double> K(4 * nt, q.map.rows());
    K.setFromTriplets(T.begin(), T.end());
    const Eigen::SparseMatrix<double> Kz = K * q.map;
    Eigen::SparseMatrix<double> N = Kz.transpose() * Kz;
    // A faint pull to the current unknowns keeps directions no triangle sees (a translation no
    // held vertex fixes) determined.
    const double lambda = 1e-10 * std::max(1e-300, N.diagonal().cwiseAbs().maxCoeff());
    Eigen::SparseMatrix<double> I(N.rows(), N.cols());
    I.setIdentity();
    N += lambda * I;
    if (!analysed) solver.analyzePattern(N), analysed = true;
    solver.factorize(N);
    if (solver.info() != Eigen::Success) break;
    const Eigen::VectorXd target = solver.solve(Kz.transpose() * b + lambda * r.z);
    if (!target.allFinite()) break;
    const Eigen::VectorXd d = target - r.z;
    const Eigen::VectorXd dU = q.map * d;
    double step = maxStep(q, U, dU), e = std::numeric_limits<double>::infinity();
    Eigen::VectorXd z;
    for (int halving = 0; halving < 40; ++halving, step *= 0.5) {
      z = r.z + step * d;
      e = energyOf(q, restInverse, area, totalArea, q.map * z);
      if (e < r.energy) break;
    }
    if (!(e < r.energy)) break;
    const double drop = (r.energy - e) / r.energy;
    r.z = z;
    r.energy = e;
    U = q.map * r.z;
    r.iterations = it + 1;
    if (drop < o.stop) break;
  }
  return r;
}

}  // namespace holefill
