#include "mesh/fill_metrics.h"

#include "mesh/self_intersection.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <tuple>

#include "geometry/json_writer.h"

namespace holefill {

namespace {

// Positions are compared at float precision: FreeCAD's mesh kernel stores float coordinates,
// so a point it kept comes back rounded, and must still count as kept.
using Key = std::array<float, 3>;

Key keyOf(const Eigen::MatrixX3d& v, int i) {
  return {static_cast<float>(v(i, 0)), static_cast<float>(v(i, 1)), static_cast<float>(v(i, 2))};
}

// Closest distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
double pointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const double denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

// Per undirected edge (by welded vertex ids): how many triangles, and whether two run it the same way.
std::pair<int, int> edgeDefects(const TriangleMesh& m, const std::vector<int>& weld, int& boundary) {
  std::map<std::pair<int, int>, std::pair<int, int>> count;  // edge (lo, hi) → (# forward, # backward)
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = weld[m.triangles(t, k)], v = weld[m.triangles(t, (k + 1) % 3)];
      if (u == v) continue;
      auto& c = count[{std::min(u, v), std::max(u, v)}];
      (u < v ? c.first : c.second)++;
    }
  int nonManifold = 0, misoriented = 0;
  boundary = 0;
  for (const auto& [e, c] : count) {
    const int n = c.first + c.second;
    if (n == 1) ++boundary;
    if (n > 2) ++nonManifold;
    if (n == 2 && (c.first == 2 || c.second == 2)) ++misoriented;
  }
  return {nonManifold, misoriented};
}

}  // namespace

Eigen::VectorXd distancesToMesh(const Eigen::MatrixX3d& points, const TriangleMesh& mesh) {
  const Eigen::Index nt = mesh.triangles.rows();
  std::vector<Eigen::Vector3d> lo(nt), hi(nt);
  for (Eigen::Index t = 0; t < nt; ++t) {
    lo[t] = hi[t] = mesh.vertices.row(mesh.triangles(t, 0)).transpose();
    for (int k = 1; k < 3; ++k) {
      lo[t] = lo[t].cwiseMin(mesh.vertices.row(mesh.triangles(t, k)).transpose());
      hi[t] = hi[t].cwiseMax(mesh.vertices.row(mesh.triangles(t, k)).transpose());
    }
  }
  Eigen::VectorXd d(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = points.row(i).transpose();
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index t = 0; t < nt; ++t) {
      // The distance to a triangle is at least the distance to its box.
      const double boxDist = (p - p.cwiseMax(lo[t]).cwiseMin(hi[t])).norm();
      if (boxDist >= best) continue;
      best = std::min(best, pointTriangleDistance(p, mesh.vertices.row(mesh.triangles(t, 0)).transpose(),
                                                  mesh.vertices.row(mesh.triangles(t, 1)).transpose(),
                                                  mesh.vertices.row(mesh.triangles(t, 2)).transpose()));
    }
    d[i] = best;
  }
  return d;
}

FillMetrics measureFill(const TriangleMesh& input, const TriangleMesh& output, const TriangleMesh& groundTruth) {
  FillMetrics m;
  const double diagonal = boundingDiagonal(input.vertices);
  std::set<Key> inputPoints;
  for (Eigen::Index i = 0; i < input.vertices.rows(); ++i) inputPoints.insert(keyOf(input.vertices, i));
  auto triangleKey = [](const Eigen::MatrixX3d& v, const Eigen::RowVector3i& f) {
    std::array<Key, 3> k = {keyOf(v, f[0]), keyOf(v, f[1]), keyOf(v, f[2])};
    std::sort(k.begin(), k.end());
    return k;
  };
  std::multiset<std::array<Key, 3>> inputTriangles;
  for (Eigen::Index t = 0; t < input.triangles.rows(); ++t) inputTriangles.insert(triangleKey(input.vertices, input.triangles.row(t)));

  std::vector<Eigen::Vector3d> samples;
  for (Eigen::Index i = 0; i < output.vertices.rows(); ++i)
    if (!inputPoints.count(keyOf(output.vertices, i))) {
      ++m.newVertices;
      samples.push_back(output.vertices.row(i).transpose());
    }
  double sum = 0;
  m.minQuality = 1;
  std::vector<bool> added(output.triangles.rows(), false);
  for (Eigen::Index t = 0; t < output.triangles.rows(); ++t) {
    auto it = inputTriangles.find(triangleKey(output.vertices, output.triangles.row(t)));
    if (it != inputTriangles.end()) { inputTriangles.erase(it); continue; }
    added[t] = true;
    const Eigen::Vector3d a = output.vertices.row(output.triangles(t, 0)).transpose();
    const Eigen::Vector3d b = output.vertices.row(output.triangles(t, 1)).transpose();
    const Eigen::Vector3d c = output.vertices.row(output.triangles(t, 2)).transpose();
    const double q = triangleQuality(a, b, c);
    ++m.newTriangles;
    sum += q;
    m.minQuality = std::min(m.minQuality, q);
    m.goodShare += q >= 0.7 ? 1 : 0;
    if (!((b - a).cross(c - a).norm() > 0)) ++m.degenerateTriangles;
    samples.push_back((a + b + c) / 3);
  }
  m.keptInput = inputTriangles.empty();
  if (m.newTriangles > 0) m.selfIntersections = static_cast<int>(selfIntersections(output, added).pairs.size());
  if (m.newTriangles > 0) {
    m.meanQuality = sum / m.newTriangles;
    m.goodShare /= m.newTriangles;
  } else {
    m.minQuality = 0;
  }

  const double tol = 1e-9 * diagonal;
  int boundary = 0;
  const auto before = edgeDefects(input, weldMap(input.vertices, tol), boundary);
  m.boundaryEdgesBefore = boundary;
  const auto after = edgeDefects(output, weldMap(output.vertices, tol), boundary);
  m.boundaryEdgesAfter = boundary;
  m.nonManifoldEdgesAdded = std::max(0, after.first - before.first);
  m.misorientedEdgesAdded = std::max(0, after.second - before.second);

  if (groundTruth.triangles.rows() > 0 && !samples.empty() && diagonal > 0) {
    Eigen::MatrixX3d p(static_cast<Eigen::Index>(samples.size()), 3);
    for (size_t i = 0; i < samples.size(); ++i) p.row(i) = samples[i].transpose();
    const Eigen::VectorXd d = distancesToMesh(p, groundTruth) / diagonal;
    m.rmsDistance = std::sqrt(d.squaredNorm() / static_cast<double>(d.size()));
    m.maxDistance = d.maxCoeff();
  }
  return m;
}

std::string toJson(const FillMetrics& m) {
  JsonWriter w;
  w.beginObject();
  w.field("new_vertices", m.newVertices).field("new_triangles", m.newTriangles);
  w.field("boundary_edges_before", m.boundaryEdgesBefore).field("boundary_edges_after", m.boundaryEdgesAfter);
  w.field("non_manifold_edges_added", m.nonManifoldEdgesAdded).field("misoriented_edges_added", m.misorientedEdgesAdded);
  w.field("degenerate_triangles", m.degenerateTriangles).field("self_intersections", m.selfIntersections);
  w.field("min_quality", m.minQuality).field("mean_quality", m.meanQuality).field("share_quality_0_7", m.goodShare);
  w.field("rms_distance", m.rmsDistance).field("max_distance", m.maxDistance).field("kept_input", m.keptInput);
  w.endObject();
  return w.str();
}

}  // namespace holefill
