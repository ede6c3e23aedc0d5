// Small hole patches for the mesh units' tests.
#pragma once

#include <cmath>
#include <functional>

#include "mesh/hole_patch.h"

namespace holefill::testpatches {

// A hexagonal fan: the loop on the unit circle at height z(x, y), one new vertex in the middle.
inline HolePatch fan(double centreZ, const std::function<double(double, double)>& z) {
  HolePatch p;
  for (int k = 0; k < 6; ++k) {
    const double a = M_PI / 3 * k, x = std::cos(a), y = std::sin(a);
    p.points.emplace_back(x, y, z(x, y));
  }
  p.boundaryCount = 6;
  p.points.emplace_back(0, 0, centreZ);
  for (int k = 0; k < 6; ++k) p.triangles.push_back({k, (k + 1) % 6, 6});
  p.scale.assign(7, 1.0);
  return p;
}

}  // namespace holefill::testpatches

namespace holefill::testpatches {

// A flat disk hole: `n` loop vertices on a circle of radius r in the plane z = 0, anticlockwise,
// triangulated as a fan from loop vertex 0 (the thin ears a bare triangulation leaves), each loop
// vertex's σ the loop's edge length.
inline HolePatch flatFanDisk(int n, double r) {
  HolePatch p;
  for (int k = 0; k < n; ++k) p.points.emplace_back(r * std::cos(2 * M_PI * k / n), r * std::sin(2 * M_PI * k / n), 0.0);
  p.boundaryCount = n;
  for (int k = 1; k + 1 < n; ++k) p.triangles.push_back({0, k, k + 1});
  p.scale.assign(n, 2 * r * std::sin(M_PI / n));
  return p;
}

// The longest edge of the patch.
inline double longestEdge(const HolePatch& p) {
  double most = 0;
  for (const auto& t : p.triangles)
    for (int e = 0; e < 3; ++e) most = std::max(most, (p.points[t[e]] - p.points[t[(e + 1) % 3]]).norm());
  return most;
}

// Every triangle turns the way the loop does (normal +z, not degenerate), and the patch stays
// a disk: Euler's T = 2V − B − 2.
inline void expectFlatOrientedDisk(const HolePatch& p) {
  for (const auto& t : p.triangles) {
    double area2 = 0;
    const Eigen::Vector3d n = patchTriangleNormal(p, t, &area2);
    EXPECT_GT(area2, 1e-12);
    EXPECT_GT(n.z(), 0.999);
  }
  for (const auto& q : p.points) EXPECT_NEAR(q.z(), 0.0, 1e-12);
  EXPECT_EQ(static_cast<int>(p.triangles.size()), 2 * static_cast<int>(p.points.size()) - p.boundaryCount - 2);
}

}  // namespace holefill::testpatches
