#include <gtest/gtest.h>

#include <cmath>

#include "gnurbs/patch_continuity.h"

using namespace holefill;

namespace {

// Two unit quads side by side sharing the edge 1–4: face 0 over [0, 1] × [0, 1], face 1 over
// [1, 2] × [0, 1], each u along x from its first corner and v along y.
QuadCage twoQuads() {
  QuadCage c;
  c.vertices.resize(6, 3);
  c.vertices << 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0;
  c.quads.resize(2, 4);
  c.quads << 0, 1, 4, 3, 1, 2, 5, 4;
  return c;
}

SurfaceJet flat(double x, double y) {
  SurfaceJet j;
  j.p = {x, y, 0};
  j.su = {1, 0, 0};
  j.sv = {0, 1, 0};
  j.suu = j.suv = j.svv = Eigen::Vector3d::Zero();
  return j;
}

}  // namespace

// The one interior edge is measured as DESIGN.md defines it: no gap and no kink between two
// faces of one plane; the angle θ between them when the second is turned about the edge; a
// curvature jump when it curls away with curvature κ from the edge.
TEST(PatchContinuity, MeasuresTheGapTheKinkAndTheCurvatureJumpAcrossAnEdge) {
  const QuadCage cage = twoQuads();
  const CageTopology topology(cage);
  const auto measure = [&](const std::function<SurfaceJet(double, double)>& second) {
    const auto all = cageEdgeContinuity(cage, topology, [&](int f, double u, double v) { return f == 0 ? flat(u, v) : second(u, v); }, 11, 1.0);
    EXPECT_EQ(all.size(), 1u);
    return all.front();
  };
  const CageEdgeContinuity plane = measure([](double u, double v) { return flat(1 + u, v); });
  EXPECT_EQ(std::min(plane.a, plane.b), 1);
  EXPECT_EQ(std::max(plane.a, plane.b), 4);
  EXPECT_FALSE(plane.sharp);
  EXPECT_LT(plane.g0, 1e-14);
  EXPECT_LT(plane.g1, 1e-14);
  EXPECT_LT(plane.g2, 1e-14);
  const double theta = 0.2;
  const CageEdgeContinuity kinked = measure([&](double u, double v) {
    SurfaceJet j = flat(0, v);
    j.p = {1 + u * std::cos(theta), v, u * std::sin(theta)};
    j.su = {std::cos(theta), 0, std::sin(theta)};
    return j;
  });
  EXPECT_LT(kinked.g0, 1e-14);
  EXPECT_NEAR(kinked.g1, theta, 1e-12);
  const double kappa = 2;
  const CageEdgeContinuity curled = measure([&](double u, double v) {
    SurfaceJet j = flat(1 + u, v);
    j.p.z() = 0.5 * kappa * u * u;
    j.su.z() = kappa * u;
    j.suu = {0, 0, kappa};
    return j;
  });
  EXPECT_LT(curled.g1, 1e-12);
  EXPECT_NEAR(curled.maxCurvature, kappa, 1e-9);
  EXPECT_GE(curled.g2, 1.0 - 1e-9);  // |κ_f − κ_g| / max(|κ_g|, 1/scale): 1 or 2 by which face is g
}
