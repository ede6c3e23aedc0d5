// Trimmed regions with known parameters for the fitting tests: the cells of a regular grid over
// [0, nx·h] × [0, ny·h] whose centre `inside` keeps, two triangles each (anticlockwise seen from
// +z), vertices placed by `place(u, v)`; uv = the grid coordinates, exactly. Unused grid vertices
// are left out.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

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

}  // namespace holefill::testregions
