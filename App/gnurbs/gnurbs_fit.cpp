#include "gnurbs/gnurbs_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "geometry/error.h"
#include "geometry/surface_projection.h"

namespace holefill {

namespace {

struct Footpoint {
  int patch = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  double distance = 0;
};

// Closest points of the target on a surface's patches: nearest grid sample (a uniform hash
// grid over the samples), then Newton on that sample's patch.
std::vector<Footpoint> project(const G2GnurbsResult& s, const Eigen::MatrixX3d& target, int samples) {
  std::vector<Eigen::Vector3d> xyz;
  std::vector<Footpoint> seeds;
  for (size_t p = 0; p < s.patches.size(); ++p)
    for (int i = 0; i <= samples; ++i)
      for (int j = 0; j <= samples; ++j) {
        const Eigen::Vector2d uv(static_cast<double>(i) / samples, static_cast<double>(j) / samples);
        xyz.push_back(s.patches[p].surface.point(uv.x(), uv.y()));
        seeds.push_back({static_cast<int>(p), uv, 0});
      }
  Eigen::AlignedBox3d box;
  for (const auto& q : xyz) box.extend(q);
  for (Eigen::Index k = 0; k < target.rows(); ++k) box.extend(Eigen::Vector3d(target.row(k)));
  const double cell = std::max(box.diagonal().norm() / std::cbrt(static_cast<double>(xyz.size())), 1e-300);
  auto key = [&](const Eigen::Vector3d& q, int dx, int dy, int dz) {
    const Eigen::Vector3d r = (q - box.min()) / cell;
    const auto ix = static_cast<std::int64_t>(std::floor(r.x())) + dx, iy = static_cast<std::int64_t>(std::floor(r.y())) + dy,
               iz = static_cast<std::int64_t>(std::floor(r.z())) + dz;
    return (ix * 73856093) ^ (iy * 19349663) ^ (iz * 83492791);
  };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  for (size_t k = 0; k < xyz.size(); ++k) grid[key(xyz[k], 0, 0, 0)].push_back(static_cast<int>(k));
  // Sample spacing bound: the longest distance between neighbouring samples of a patch.
  double spacing = 0;
  for (size_t p = 0; p < s.patches.size(); ++p)
    for (int i = 0; i < samples; ++i) {
      const size_t a = p * (samples + 1) * (samples + 1) + i * (samples + 1);
      spacing = std::max({spacing, (xyz[a] - xyz[a + 1]).norm(), (xyz[a] - xyz[a + samples + 1]).norm()});
    }
  std::vector<Footpoint> out(target.rows());
  for (Eigen::Index k = 0; k < target.rows(); ++k) {
    const Eigen::Vector3d q = target.row(k);
    // Every patch with a sample within the nearest sample's distance plus the spacing may hold
    // the closest point (a point near a patch border is often nearest to a sample of the
    // neighbour): Newton on each, keep the best.
    std::vector<std::pair<double, int>> near;
    double bestD = 1e300;
    for (int ring = 0; ring < 64 && (near.empty() || (ring - 1) * cell < std::sqrt(bestD) + spacing); ++ring)
      for (int dx = -ring; dx <= ring; ++dx)
        for (int dy = -ring; dy <= ring; ++dy)
          for (int dz = -ring; dz <= ring; ++dz) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring) continue;
            const auto it = grid.find(key(q, dx, dy, dz));
            if (it == grid.end()) continue;
            for (int c : it->second) {
              const double d = (xyz[c] - q).squaredNorm();
              near.emplace_back(d, c);
              bestD = std::min(bestD, d);
            }
          }
    if (near.empty())  // farther than 64 cells from every sample: search them all
      for (size_t c = 0; c < xyz.size(); ++c) {
        const double d = (xyz[c] - q).squaredNorm();
        near.emplace_back(d, static_cast<int>(c));
        bestD = std::min(bestD, d);
      }
    const double reach = std::pow(std::sqrt(bestD) + spacing, 2);
    std::sort(near.begin(), near.end());
    std::vector<int> tried;
    Footpoint best;
    best.distance = 1e300;
    for (const auto& [d, c] : near) {
      if (d > reach) break;
      if (std::find(tried.begin(), tried.end(), seeds[c].patch) != tried.end()) continue;
      tried.push_back(seeds[c].patch);
      Footpoint f = seeds[c];
      f.distance = projectPointFrom(s.patches[f.patch].surface, q, f.uv);
      if (f.distance < best.distance) best = f;
    }
    out[k] = best;
  }
  return out;
}

}  // namespace

GnurbsFitResult fitGnurbs(const QuadCage& initial, const Eigen::MatrixX3d& target, const GnurbsFitOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (target.rows() == 0) throw Error("the fitting target has no points");
  if (o.iterations < 0) throw Error("the fit takes zero or more rounds");
  if (!target.allFinite()) throw Error("the fitting target has a point with a non-finite coordinate");
  const double diagonal = (target.colwise().maxCoeff() - target.colwise().minCoeff()).norm();
  if (!(diagonal > 0)) throw Error("the fitting target's points all coincide");
  G2GnurbsBuilder builder(o.surface);

  GnurbsFitResult r;
  r.cage = initial;
  r.points = static_cast<int>(target.rows());
  std::vector<int> anchorIds;
  if (o.fitAnchors)
    for (const auto& [v, a] : initial.anchors) anchorIds.push_back(v);
  const int nv = static_cast<int>(initial.vertices.rows()), na = static_cast<int>(anchorIds.size()), n = nv + na;
  r.variables = n;

  // Basis surfaces: variable j's coordinate c is 1 in run j/3 when j % 3 == c.
  std::vector<G2GnurbsResult> basis;
  auto unitCage = [&](int first) {
    QuadCage c = initial;
    c.vertices.setZero();
    for (auto& [v, a] : c.anchors) a.setZero();
    for (int j = first; j < std::min(first + 3, n); ++j) {
      if (j < nv) c.vertices(j, j - first) = 1;
      else c.anchors[anchorIds[j - nv]][j - first] = 1;
    }
    return c;
  };
  for (int first = 0; first < n; first += 3) basis.push_back(builder.build(unitCage(first)));
  // The part of the surface no variable carries: fixed anchors.
  QuadCage rest = initial;
  rest.vertices.setZero();
  for (auto& [v, a] : rest.anchors)
    if (o.fitAnchors) a.setZero();
  const G2GnurbsResult constant = builder.build(rest);

  r.surface = builder.build(r.cage);
  std::vector<Footpoint> foot = project(r.surface, target, o.samplesPerPatch);
  auto average = [&] {
    double sum = 0;
    for (const auto& f : foot) sum += f.distance;
    return sum / static_cast<double>(foot.size()) / diagonal;
  };
  r.dAvgPerRound.push_back(average());

  // Cage Laplacian (umbrella) over vertex variables; anchors are left out of it.
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  {
    const CageTopology topo(initial);
    for (int v = 0; v < nv; ++v) {
      const auto& sp = topo.spokes(v);
      L(v, v) = 1;
      for (int w : sp) L(v, w) -= 1.0 / static_cast<double>(sp.size());
    }
  }
  // The Laplacian term per coordinate (x, y, z interleaved), the same every round.
  Eigen::MatrixXd LtL = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  {
    const Eigen::MatrixXd l = L.transpose() * L + 1e-3 * Eigen::MatrixXd::Identity(n, n);
    for (int j = 0; j < n; ++j)
      for (int q = 0; q < n; ++q)
        if (l(j, q) != 0)
          for (int a = 0; a < 3; ++a) LtL(3 * j + a, 3 * q + a) = l(j, q);
  }
  for (int round = 0; round < o.iterations; ++round) {
    const Eigen::Index m = target.rows();
    Eigen::MatrixXd Phi(m, n);
    Eigen::MatrixX3d rhs = target, normal(m, 3);
    Eigen::VectorXd pointWeight(m);
    for (Eigen::Index k = 0; k < m; ++k) {
      const Footpoint& f = foot[k];
      rhs.row(k) -= constant.patches[f.patch].surface.point(f.uv.x(), f.uv.y()).transpose();
      for (size_t b = 0; b < basis.size(); ++b) {
        const Eigen::Vector3d w = basis[b].patches[f.patch].surface.point(f.uv.x(), f.uv.y());
        for (int c = 0; c < 3 && 3 * static_cast<int>(b) + c < n; ++c) Phi(k, 3 * b + c) = w[c];
      }
      const auto d = r.surface.patches[f.patch].surface.derivatives(f.uv.x(), f.uv.y(), 1);
      const Eigen::Vector3d nk = d[1][0].cross(d[0][1]);
      // A footpoint on a patch border may be a point beyond the surface's boundary: its residual
      // is tangential, which the tangent plane would ignore, so it keeps the point distance.
      const bool border = f.uv.minCoeff() <= 0 || f.uv.maxCoeff() >= 1;
      normal.row(k) = nk.norm() > 0 && !border ? Eigen::RowVector3d(nk.normalized()) : Eigen::RowVector3d::Zero();
      pointWeight[k] = border ? 1.0 : o.tangentialWeight;
    }
    // Tangent distance (Wang, Pottmann & Liu 2006): per point the squared distance to the tangent
    // plane at its footpoint plus μ times the squared point distance, W_k = n nᵀ + μ I. Points
    // then slide along the surface instead of holding it back (the point distance alone stalled
    // at 3e-4 of the diagonal on a surface it could reproduce exactly).
    Eigen::MatrixXd N = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * n);
    for (int a = 0; a < 3; ++a)
      for (int c = a; c < 3; ++c) {
        Eigen::VectorXd w = normal.col(a).cwiseProduct(normal.col(c));
        if (a == c) w += pointWeight;
        const Eigen::MatrixXd block = Phi.transpose() * w.asDiagonal() * Phi;
        for (int j = 0; j < n; ++j)
          for (int l = 0; l < n; ++l) {
            N(3 * j + a, 3 * l + c) = block(j, l);
            N(3 * j + c, 3 * l + a) = block(j, l);
          }
      }
    for (Eigen::Index k = 0; k < m; ++k) {
      const Eigen::Vector3d nk = normal.row(k).transpose(), rk = rhs.row(k).transpose();
      const Eigen::Vector3d wr = nk * nk.dot(rk) + pointWeight[k] * rk;
      for (int j = 0; j < n; ++j) b.segment<3>(3 * j) += Phi(k, j) * wr;
    }
    Eigen::VectorXd X(3 * n);
    for (int v = 0; v < nv; ++v) X.segment<3>(3 * v) = r.cage.vertices.row(v).transpose();
    for (int j = 0; j < na; ++j) X.segment<3>(3 * (nv + j)) = r.cage.anchors.at(anchorIds[j]);
    // + λ |L (X − X_now)|²: the update is smooth where the data is silent.
    const double lambda = o.smoothness * std::max(N.trace() / (3 * n), 1e-300);
    const Eigen::VectorXd Xn = (N + lambda * LtL).ldlt().solve(b + lambda * LtL * X);
    if (!Xn.allFinite()) throw Error("the fitting system is singular: the target leaves cage vertices undetermined");
    for (int v = 0; v < nv; ++v) r.cage.vertices.row(v) = Xn.segment<3>(3 * v).transpose();
    for (int j = 0; j < na; ++j) r.cage.anchors[anchorIds[j]] = Xn.segment<3>(3 * (nv + j));
    r.surface = builder.build(r.cage);
    foot = project(r.surface, target, o.samplesPerPatch);
    r.dAvgPerRound.push_back(average());
  }

  // Distances, overall and on patches of faces touching a sharp edge.
  std::vector<bool> sharpFace(r.surface.cage.quads.rows(), false);
  for (Eigen::Index f = 0; f < r.surface.cage.quads.rows(); ++f)
    for (int k = 0; k < 4; ++k) sharpFace[f] = sharpFace[f] || r.surface.cage.isSharp(r.surface.cage.quads(f, k), r.surface.cage.quads(f, (k + 1) % 4));
  double sum = 0, sumSharp = 0;
  for (const auto& f : foot) {
    const double d = f.distance / diagonal;
    r.dMax = std::max(r.dMax, d);
    sum += d;
    if (sharpFace[r.surface.patches[f.patch].face]) {
      r.dMaxSharp = std::max(r.dMaxSharp, d);
      sumSharp += d;
      ++r.sharpPoints;
    }
  }
  r.dAvg = sum / static_cast<double>(foot.size());
  r.dAvgSharp = r.sharpPoints ? sumSharp / r.sharpPoints : 0;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace holefill
