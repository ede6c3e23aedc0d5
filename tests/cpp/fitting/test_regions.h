// Trimmed regions with known parameters for the fitting tests: the cells of a regular grid over
// [0, nx·h] × [0, ny·h] whose centre `inside` keeps, two triangles each (anticlockwise seen from
// +z), vertices placed by `place(u, v)`; uv = the grid coordinates, exactly. Unused grid vertices
// are left out.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <random>
#include <vector>

#include "fitting/labeled_parameterization.h"
#include "mesh/mesh_holes.h"
#include "mesh/triangle_mesh.h"

namespace holefill::testregions {

inline TriangleMesh gridRegion(int nx, int ny, double h, const std::function<bool(double, double)>& inside,
                               const std::function<Eigen::Vector3d(double, double)>& place, Eigen::MatrixX2d& uv) {
  std::vector<int> id((nx + 1) * (ny + 1), -1);
  std::vector<Eigen::Vector3i> tris;
  std::vector<Eigen::Vector2d> pts;
  auto vid = [&](int i, int j) {
    int& k = id[j * (nx + 1) + i];
    if (k < 0) k = static_cast<int>(pts.size()), pts.emplace_back(i * h, j * h);
    return k;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (!inside((i + 0.5) * h, (j + 0.5) * h)) continue;
      const int a = vid(i, j), b = vid(i + 1, j), c = vid(i + 1, j + 1), d = vid(i, j + 1);
      tris.emplace_back(a, b, c);
      tris.emplace_back(a, c, d);
    }
  TriangleMesh m;
  m.vertices.resize(static_cast<Eigen::Index>(pts.size()), 3);
  uv.resize(static_cast<Eigen::Index>(pts.size()), 2);
  for (size_t k = 0; k < pts.size(); ++k) {
    m.vertices.row(static_cast<Eigen::Index>(k)) = place(pts[k].x(), pts[k].y()).transpose();
    uv.row(static_cast<Eigen::Index>(k)) = pts[k].transpose();
  }
  m.triangles.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (size_t k = 0; k < tris.size(); ++k) m.triangles.row(static_cast<Eigen::Index>(k)) = tris[k].transpose();
  return m;
}

// Labels with the corners given: the outer boundary vertices nearest the four points `at` (true
// parameters, in S, E, N, W order of their segments' starts: SW, SE, NE, NW); S, E, N, W run
// between them anticlockwise, every boundary vertex labeled (the corpus's labels by corner angles
// put corners where the bounding-box rule would not).
inline std::vector<LabeledSegment> cornerLabels(const TriangleMesh& region, const Eigen::MatrixX2d& uv, const std::array<Eigen::Vector2d, 4>& at) {
  const MeshHoleReport holes = findMeshHoles(region);
  size_t outer = 0;
  for (size_t k = 1; k < holes.holes.size(); ++k)
    if (holes.holes[k].length > holes.holes[outer].length) outer = k;
  const std::vector<int>& loop = holes.holes.at(outer).loop;
  std::array<size_t, 4> corner{};
  for (int c = 0; c < 4; ++c)
    for (size_t k = 0; k < loop.size(); ++k)
      if ((uv.row(loop[k]).transpose() - at[c]).norm() < (uv.row(loop[corner[c]]).transpose() - at[c]).norm()) corner[c] = k;
  std::vector<LabeledSegment> labels;
  for (int side = 0; side < 4; ++side) {
    LabeledSegment seg{static_cast<Side>(side), {}};
    for (size_t k = corner[side];; k = (k + 1) % loop.size()) {
      seg.vertices.push_back(loop[k]);
      if (k == corner[(side + 1) % 4]) break;
    }
    labels.push_back(seg);
  }
  return labels;
}

// Labels by the corpus's bounding-box rule (tests/corpus/labeled_regions.py): the corners are the
// outer boundary vertices nearest the corners of the region's box in its true parameters `uv`;
// S, E, N, W run between them anticlockwise, every boundary vertex labeled.
inline std::vector<LabeledSegment> boundingBoxLabels(const TriangleMesh& region, const Eigen::MatrixX2d& uv) {
  const Eigen::Vector2d lo = uv.colwise().minCoeff().transpose(), hi = uv.colwise().maxCoeff().transpose();
  return cornerLabels(region, uv, {lo, Eigen::Vector2d(hi.x(), lo.y()), hi, Eigen::Vector2d(lo.x(), hi.y())});
}

// An L of the unit square less its upper right quarter, labeled by four of its five convex corners
// as the corpus's corner-angle rule does: S the bottom, E the right arm's end, N the inner corner's
// two legs (a reflex turn inside one side), W round the convex corner at the top left.
inline std::vector<LabeledSegment> lShapeCornerLabels(const TriangleMesh& region, const Eigen::MatrixX2d& uv) {
  return cornerLabels(region, uv, {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 0.5), Eigen::Vector2d(0.5, 1)});
}

// Scan noise: a normal deviate of `fraction` of the region's diagonal on every coordinate.
inline void addNoise(TriangleMesh& region, double fraction, unsigned seed) {
  const double diagonal = (region.vertices.colwise().maxCoeff() - region.vertices.colwise().minCoeff()).norm();
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, fraction * diagonal);
  for (Eigen::Index v = 0; v < region.vertices.rows(); ++v)
    for (int c = 0; c < 3; ++c) region.vertices(v, c) += noise(rng);
}

}  // namespace holefill::testregions
