#include "geometry/differential_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace holefill;

namespace {

// The sphere of radius r in longitude u and latitude v, with its derivatives.
SurfaceJet sphere(double r, double u, double v) {
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  SurfaceJet j;
  j.p = r * Eigen::Vector3d(cu * cv, su * cv, sv);
  j.su = r * Eigen::Vector3d(-su * cv, cu * cv, 0);
  j.sv = r * Eigen::Vector3d(-cu * sv, -su * sv, cv);
  j.suu = r * Eigen::Vector3d(-cu * cv, -su * cv, 0);
  j.suv = r * Eigen::Vector3d(su * sv, -cu * sv, 0);
  j.svv = r * Eigen::Vector3d(-cu * cv, -su * cv, -sv);
  return j;
}

// The cylinder of radius r about z: (r cos u, r sin u, v).
SurfaceJet cylinder(double r, double u, double v) {
  SurfaceJet j;
  j.p = Eigen::Vector3d(r * std::cos(u), r * std::sin(u), v);
  j.su = Eigen::Vector3d(-r * std::sin(u), r * std::cos(u), 0);
  j.sv = Eigen::Vector3d(0, 0, 1);
  j.suu = Eigen::Vector3d(-r * std::cos(u), -r * std::sin(u), 0);
  j.suv = j.svv = Eigen::Vector3d::Zero();
  return j;
}

}  // namespace

TEST(DifferentialGeometry, ASphereIsUmbilicWithCurvatureOneOverItsRadius) {
  const SurfaceJet j = sphere(2.0, 0.7, 0.3);
  Eigen::Vector3d n;
  ASSERT_TRUE(unitNormal(j, n));
  EXPECT_NEAR(n.dot(j.p.normalized()), 1.0, 1e-12);  // su x sv points outward here
  // Outward normal: the sphere bends away from it, curvature -1/r in every direction.
  const PrincipalCurvatures k = principalCurvatures(j, n);
  EXPECT_NEAR(k.k1, -0.5, 1e-12);
  EXPECT_NEAR(k.k2, -0.5, 1e-12);
  EXPECT_NEAR(k.gaussian, 0.25, 1e-12);
  EXPECT_NEAR(k.mean, -0.5, 1e-12);
  EXPECT_NEAR(normalCurvature(j, n, j.su + 3 * j.sv), -0.5, 1e-12);
  EXPECT_NEAR(normalCurvature(j, -n, j.sv), 0.5, 1e-12);  // the sign follows the normal
}

TEST(DifferentialGeometry, ACylinderBendsAroundAndIsStraightAlong) {
  const SurfaceJet j = cylinder(4.0, 1.1, -2.0);
  Eigen::Vector3d n;
  ASSERT_TRUE(unitNormal(j, n));
  const PrincipalCurvatures k = principalCurvatures(j, n);
  // Normal su x sv points outward; k1 >= k2: 0 along the axis, -1/4 around it.
  EXPECT_NEAR(k.k1, 0.0, 1e-12);
  EXPECT_NEAR(k.k2, -0.25, 1e-12);
  EXPECT_NEAR(k.gaussian, 0.0, 1e-12);
  EXPECT_NEAR(std::abs(k.d1.dot(Eigen::Vector3d::UnitZ())), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(k.d2.dot(j.su.normalized())), 1.0, 1e-12);
  // Euler's theorem: at 60 degrees from the axis, k1 cos^2 + k2 sin^2.
  const Eigen::Vector3d d = 0.5 * Eigen::Vector3d::UnitZ() + std::sqrt(0.75) * j.su.normalized();
  EXPECT_NEAR(normalCurvature(j, n, d), -0.25 * 0.75, 1e-12);
  EXPECT_NEAR(curvatureAlong(k.k1, k.k2, k.d1, n, d), -0.25 * 0.75, 1e-12);
  // A direction off the tangent plane is projected onto it first.
  EXPECT_NEAR(curvatureAlong(k.k1, k.k2, k.d1, n, d + 5 * n), -0.25 * 0.75, 1e-12);
}

TEST(DifferentialGeometry, ParameterDirectionInvertsTheTangentMap) {
  const SurfaceJet j = sphere(1.5, -0.4, 0.9);
  const Eigen::Vector2d ab = parameterDirection(j, 0.3 * j.su - 1.7 * j.sv);
  EXPECT_NEAR(ab.x(), 0.3, 1e-12);
  EXPECT_NEAR(ab.y(), -1.7, 1e-12);
  Eigen::Vector3d n;
  ASSERT_TRUE(unitNormal(j, n));
  const Eigen::Vector2d off = parameterDirection(j, j.su + 2 * n);  // the normal part is dropped
  EXPECT_NEAR(off.x(), 1.0, 1e-12);
  EXPECT_NEAR(off.y(), 0.0, 1e-12);
}

TEST(DifferentialGeometry, ParallelOrVanishingTangentsHaveNoNormalAPolesDirectionIsKept) {
  // Near the sphere's pole su shrinks to round-off but stays square to sv: the normal su x sv
  // still points along the axis, and it is given.
  const SurfaceJet pole = sphere(1.0, 0.3, M_PI / 2);
  Eigen::Vector3d n;
  ASSERT_TRUE(unitNormal(pole, n));
  EXPECT_NEAR(n.z(), 1.0, 1e-9);
  // A folded patch (su parallel to sv) and a collapsed one (su = 0) have none.
  SurfaceJet folded = cylinder(1.0, 0.0, 0.0);
  folded.sv = 2.0 * folded.su;
  EXPECT_FALSE(unitNormal(folded, n));
  SurfaceJet collapsed = cylinder(1.0, 0.0, 0.0);
  collapsed.su.setZero();
  EXPECT_FALSE(unitNormal(collapsed, n));
}
