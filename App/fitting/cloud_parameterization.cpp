#include "fitting/cloud_parameterization.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>

#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "learn/bidgcn.h"

namespace holefill {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;

// Points within `r` of each point (itself excluded), by a uniform grid of cells of size r.
std::vector<std::vector<int>> radiusNeighbours(const Eigen::MatrixX3d& p, double r) {
  std::map<std::array<long, 3>, std::vector<int>> cells;
  const auto cellOf = [&](Eigen::Index k) {
    return std::array<long, 3>{static_cast<long>(std::floor(p(k, 0) / r)), static_cast<long>(std::floor(p(k, 1) / r)),
                               static_cast<long>(std::floor(p(k, 2) / r))};
  };
  for (Eigen::Index k = 0; k < p.rows(); ++k) cells[cellOf(k)].push_back(static_cast<int>(k));
  std::vector<std::vector<int>> out(p.rows());
  for (Eigen::Index k = 0; k < p.rows(); ++k) {
    const auto c = cellOf(k);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (int j : it->second)
            if (j != k && (p.row(j) - p.row(k)).squaredNorm() <= r * r) out[k].push_back(j);
        }
  }
  return out;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Floater's shape-preserving weights of the origin w.r.t. a star of neighbours q (anticlockwise
// around it): for each neighbour l, the barycentric coordinates of the origin in the triangle of
// l and the opposite ring edge that the ray from l through the origin crosses, averaged over l.
// Empty when the origin is not inside the star.
std::vector<double> shapePreservingWeights(const std::vector<Eigen::Vector2d>& q) {
  const int d = static_cast<int>(q.size());
  std::vector<double> w(d, 0.0);
  for (int l = 0; l < d; ++l) {
    bool found = false;
    for (int r = 0; r < d && !found; ++r) {
      const int s = (r + 1) % d;
      if (r == l || s == l) continue;
      const double area = cross2(q[r] - q[l], q[s] - q[l]);
      if (std::abs(area) < 1e-300) continue;
      // Barycentric coordinates of the origin in (q_l, q_r, q_s).
      const double a = cross2(q[r], q[s]) / area, b = cross2(q[s], q[l]) / area, c = cross2(q[l], q[r]) / area;
      if (a >= -1e-12 && b >= -1e-12 && c >= -1e-12) {
        w[l] += a, w[r] += b, w[s] += c;
        found = true;
      }
    }
    if (!found) return {};
  }
  for (double& x : w) x /= d;
  return w;
}

// The shape-preserving star of point i in its ball: the ball projected on its best-fit plane and
// Delaunay-triangulated gives i's neighbours in order; the geodesic polar map (3D lengths, 3D
// angles scaled to sum to 2π) places them around i, and Floater's weights follow. Empty weights
// when i is on the hull of the projected ball.
std::vector<int> shapePreservingStar(const Eigen::MatrixX3d& p, int i, const std::vector<int>& ball, std::vector<double>& weights) {
  weights.clear();
  Eigen::RowVector3d c = p.row(i);
  for (int j : ball) c += p.row(j);
  c /= static_cast<double>(ball.size() + 1);
  Eigen::Matrix3d C = (p.row(i) - c).transpose() * (p.row(i) - c);
  for (int j : ball) C += (p.row(j) - c).transpose() * (p.row(j) - c);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  const Eigen::Vector3d e1 = eig.eigenvectors().col(2), e2 = eig.eigenvectors().col(1);
  Delaunay dt;
  const auto plane = [&](int k) { return Delaunay::Point((p.row(k) - c).dot(e1.transpose()), (p.row(k) - c).dot(e2.transpose())); };
  auto vi = dt.insert(plane(i));
  vi->info() = i;
  for (int j : ball) dt.insert(plane(j))->info() = j;
  std::vector<int> ring;
  auto circ = dt.incident_vertices(vi), start = circ;
  if (circ == nullptr) return ring;
  do {
    if (dt.is_infinite(circ)) return {};
    ring.push_back(circ->info());
  } while (++circ != start);
  const int d = static_cast<int>(ring.size());
  if (d < 3) return {};
  std::vector<double> angle(d), len(d);
  double total = 0;
  for (int k = 0; k < d; ++k) {
    const Eigen::Vector3d a = (p.row(ring[k]) - p.row(i)).transpose(), b = (p.row(ring[(k + 1) % d]) - p.row(i)).transpose();
    angle[k] = std::atan2(a.cross(b).norm(), a.dot(b));
    len[k] = a.norm();
    total += angle[k];
  }
  std::vector<Eigen::Vector2d> q(d);
  double phi = 0;
  for (int k = 0; k < d; ++k) {
    q[k] = len[k] * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    phi += angle[k] * 2 * M_PI / total;
  }
  weights = shapePreservingWeights(q);
  return ring;
}

}  // namespace

std::string CloudParameterization::toJson() const {
  JsonWriter j;
  j.beginObject()
      .field("points", points)
      .field("boundary_points", boundaryPoints)
      .field("method", method)
      .field("radius", radius)
      .field("min_neighbours", minNeighbours)
      .field("max_neighbours", maxNeighbours)
      .field("grown", grown)
      .field("fallbacks", fallbacks)
      .field("seconds", seconds)
      .field("warnings", warnings)
      .endObject();
  return j.str();
}

std::string cloudWeightsName(CloudWeights w) {
  const char* names[] = {"uniform", "invdist", "shape", "bidgcn"};
  return names[static_cast<int>(w)];
}

CloudWeights cloudWeightsByName(const std::string& name) {
  if (name == "uniform") return CloudWeights::Uniform;
  if (name == "invdist" || name == "inverse-distance") return CloudWeights::InverseDistance;
  if (name == "shape" || name == "shape-preserving") return CloudWeights::ShapePreserving;
  if (name == "bidgcn") return CloudWeights::Bidgcn;
  throw Error("unknown parameterization method '" + name + "': use bidgcn, shape, invdist or uniform");
}

CloudParameterization parameterizeCloud(const Eigen::MatrixX3d& points, const std::vector<bool>& boundary, const Eigen::MatrixX2d& boundaryUV,
                                        const CloudParameterizationOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const int n = static_cast<int>(points.rows());
  if (n < 10) throw Error("the cloud has " + std::to_string(n) + " points; parameterizing needs at least 10");
  if (static_cast<int>(boundary.size()) != n || boundaryUV.rows() != n) throw Error("the boundary flags or parameters do not match the points in number");
  if (!points.allFinite()) throw Error("the cloud has a non-finite coordinate");
  const int nb = static_cast<int>(std::count(boundary.begin(), boundary.end(), true));
  if (nb < 3) throw Error("the cloud has " + std::to_string(nb) + " boundary points with parameters; it needs at least 3 (flag 1 with u v)");
  for (int k = 0; k < n; ++k)
    if (boundary[k] && !boundaryUV.row(k).allFinite()) throw Error("boundary point " + std::to_string(k) + " has a non-finite parameter");
  if (!(o.radius >= 0)) throw Error("the neighbourhood radius must be positive (or 0 for the default)");

  // The unit cube: shifted to the origin and scaled by the largest extent (shape kept).
  const Eigen::RowVector3d lo = points.colwise().minCoeff(), hi = points.colwise().maxCoeff();
  const double extent = (hi - lo).maxCoeff();
  if (!(extent > 0)) throw Error("all points of the cloud coincide");
  const Eigen::MatrixX3d p = (points.rowwise() - lo) / extent;
  CloudParameterization out;
  out.points = n;
  out.boundaryPoints = nb;
  out.method = cloudWeightsName(o.weights);
  out.radius = o.radius > 0 ? o.radius : 3.0 / std::sqrt(static_cast<double>(n));
  const std::vector<std::vector<int>> ball = radiusNeighbours(p, out.radius);
  for (int k = 0; k < n; ++k)
    for (int j : ball[k])
      if (j > k && (p.row(j) - p.row(k)).squaredNorm() <= 1e-24) throw Error("points " + std::to_string(k) + " and " + std::to_string(j) + " coincide: remove duplicates first");
  if (o.weights == CloudWeights::Bidgcn) {
    learn::BidgcnOptions bo;
    bo.weights = o.weightsFile;
    out.uv = learn::bidgcnParameters(p, boundary, boundaryUV, bo);
    out.radius = 0;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }

  // Rows u_i − Σ λ_ik u_k = 0 for interior points, u_j = given for boundary points.
  std::vector<Eigen::Triplet<double>> T;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(n, 2);
  out.minNeighbours = n;
  for (int i = 0; i < n; ++i) {
    T.emplace_back(i, i, 1.0);
    if (boundary[i]) {
      rhs.row(i) = boundaryUV.row(i);
      continue;
    }
    if (ball[i].empty())
      throw Error("interior point " + std::to_string(i) + " has no neighbour within radius " + std::to_string(out.radius) +
                  " (unit-cube scale): give a larger radius");
    std::vector<int> nbr = ball[i];
    std::vector<double> w;
    if (o.weights == CloudWeights::ShapePreserving) {
      // A point on the hull of its projected ball (next to a sparse boundary) has no star around
      // it: the ball is grown (2r, 4r) until it has one, else inverse distance.
      std::vector<double> weights;
      std::vector<int> ring = shapePreservingStar(p, i, nbr, weights);
      for (double grow : {2.0, 4.0}) {
        if (!weights.empty()) break;
        std::vector<int> wider;
        for (int j = 0; j < n; ++j)
          if (j != i && (p.row(j) - p.row(i)).squaredNorm() <= grow * grow * out.radius * out.radius) wider.push_back(j);
        ring = shapePreservingStar(p, i, wider, weights);
        if (!weights.empty()) ++out.grown;
      }
      if (!weights.empty()) nbr = ring, w = weights;
      else ++out.fallbacks;
    }
    if (w.empty()) {
      w.resize(nbr.size());
      for (size_t k = 0; k < nbr.size(); ++k)
        w[k] = o.weights == CloudWeights::Uniform ? 1.0 : 1.0 / (p.row(nbr[k]) - p.row(i)).norm();
      const double sum = std::accumulate(w.begin(), w.end(), 0.0);
      for (double& x : w) x /= sum;
    }
    out.minNeighbours = std::min(out.minNeighbours, static_cast<int>(nbr.size()));
    out.maxNeighbours = std::max(out.maxNeighbours, static_cast<int>(nbr.size()));
    for (size_t k = 0; k < nbr.size(); ++k) T.emplace_back(i, nbr[k], -w[k]);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(T.begin(), T.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success)
    throw Error("some interior points are not connected to the boundary within radius " + std::to_string(out.radius) + ": give a larger radius");
  out.uv = lu.solve(rhs);
  if (!out.uv.allFinite()) throw Error("the parameterization's system is singular: some interior points are not connected to the boundary");
  if (out.fallbacks > 0)
    out.warnings.push_back(std::to_string(out.fallbacks) + " points lie on the hull of their projected ball even at 4 times the radius and got inverse-distance weights");
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace holefill

namespace holefill {

Eigen::MatrixX2d boundaryChordParameters(const Eigen::MatrixX3d& points, const std::vector<bool>& boundary, const std::vector<int>& corners) {
  const int n = static_cast<int>(points.rows());
  if (static_cast<int>(boundary.size()) != n) throw Error("the boundary flags do not match the points in number");
  std::vector<int> loop;
  for (int k = 0; k < n; ++k)
    if (boundary[k]) loop.push_back(k);
  const int L = static_cast<int>(loop.size());
  if (L < 4) throw Error("the cloud has " + std::to_string(L) + " boundary points; four corners need at least 4");
  // The cloud's best-fit plane; boundary points by angle about their centroid there.
  const Eigen::RowVector3d mean = points.colwise().mean();
  const Eigen::MatrixX3d q = points.rowwise() - mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(q.transpose() * q);
  Eigen::Vector3d e1 = eig.eigenvectors().col(2), e2 = eig.eigenvectors().col(1);
  Eigen::MatrixX2d flat(n, 2);
  flat.col(0) = q * e1;
  flat.col(1) = q * e2;
  Eigen::RowVector2d centre = Eigen::RowVector2d::Zero();
  for (int k : loop) centre += flat.row(k) / L;
  std::sort(loop.begin(), loop.end(), [&](int a, int b) {
    return std::atan2(flat(a, 1) - centre.y(), flat(a, 0) - centre.x()) < std::atan2(flat(b, 1) - centre.y(), flat(b, 0) - centre.x());
  });
  // Corners: given, or the four sharpest turns (neighbours two steps away), at least L/8 apart.
  std::vector<int> at;  // loop positions of the corners
  if (!corners.empty()) {
    if (corners.size() != 4) throw Error("give exactly four corners, got " + std::to_string(corners.size()));
    for (int c : corners) {
      const auto it = std::find(loop.begin(), loop.end(), c);
      if (c < 0 || c >= n || it == loop.end()) throw Error("corner " + std::to_string(c) + " is not a boundary point");
      at.push_back(static_cast<int>(it - loop.begin()));
    }
    std::sort(at.begin(), at.end());
    if (std::adjacent_find(at.begin(), at.end()) != at.end()) throw Error("the four corners must be four different points");
  } else {
    std::vector<std::pair<double, int>> turn;
    for (int k = 0; k < L; ++k) {
      const Eigen::Vector2d a = (flat.row(loop[k]) - flat.row(loop[(k + L - 2) % L])).transpose(), b = (flat.row(loop[(k + 2) % L]) - flat.row(loop[k])).transpose();
      turn.emplace_back(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)), k);
    }
    std::sort(turn.rbegin(), turn.rend());
    const int gap = std::max(1, L / 8);
    for (const auto& [angle, k] : turn) {
      bool apart = true;
      for (int c : at) apart = apart && std::min(std::abs(c - k), L - std::abs(c - k)) >= gap;
      if (apart) at.push_back(k);
      if (at.size() == 4) break;
    }
    if (at.size() < 4) throw Error("could not find four corners on the boundary: give them");
    std::sort(at.begin(), at.end());
  }
  // The first corner: the one nearest the plane's lower left (u along e1, v along e2).
  int first = 0;
  for (int c = 1; c < 4; ++c)
    if (flat(loop[at[c]], 0) + flat(loop[at[c]], 1) < flat(loop[at[first]], 0) + flat(loop[at[first]], 1)) first = c;
  Eigen::MatrixX2d uv = Eigen::MatrixX2d::Zero(n, 2);
  for (int side = 0; side < 4; ++side) {
    const int from = at[(first + side) % 4], to = at[(first + side + 1) % 4];
    std::vector<int> run;
    for (int k = from;; k = (k + 1) % L) {
      run.push_back(loop[k]);
      if (k == to) break;
    }
    std::vector<double> s(run.size(), 0.0);
    for (size_t k = 1; k < run.size(); ++k) s[k] = s[k - 1] + (points.row(run[k]) - points.row(run[k - 1])).norm();
    for (size_t k = 0; k < run.size(); ++k) {
      const double t = s.back() > 0 ? s[k] / s.back() : 0;
      const double u[4] = {t, 1, 1 - t, 0}, v[4] = {0, t, 1, 1 - t};
      uv.row(run[k]) << u[side], v[side];
    }
  }
  return uv;
}

}  // namespace holefill
