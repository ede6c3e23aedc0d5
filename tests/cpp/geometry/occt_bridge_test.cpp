#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <TopoDS.hxx>
#include <gp_Ax3.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>

#include "geometry/occt_bridge.h"

using namespace holefill;

TEST(OcctBridge, PointsAndVectorsCrossUnchanged) {
  const Eigen::Vector3d p(1.5, -2.25, 1e-9);
  EXPECT_EQ(toEigen(toPnt(p)), p);
  EXPECT_EQ(toEigen(gp_Vec(0.5, 0, -3)), Eigen::Vector3d(0.5, 0, -3));
}

// The jet of a cylinder face (radius 2 about z; u the angle, v the height): point, derivatives
// and normal as the analytic surface has them; a REVERSED face negates the v-derivatives, so its
// normal turns inwards while the curvature term along u stays as it is.
TEST(OcctBridge, FaceJetIsTheSurfacesAndAReversedFaceTurnsItsNormal) {
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Cylinder(gp_Ax3(), 2.0), 0, M_PI, 0, 1).Face();
  const BRepAdaptor_Surface s(face);
  const double u = 0.3, v = 0.4;
  const SurfaceJet j = faceJet(s, false, u, v);
  EXPECT_TRUE(j.p.isApprox(Eigen::Vector3d(2 * std::cos(u), 2 * std::sin(u), v), 1e-12));
  EXPECT_TRUE(j.su.isApprox(Eigen::Vector3d(-2 * std::sin(u), 2 * std::cos(u), 0), 1e-12));
  EXPECT_TRUE(j.sv.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  EXPECT_TRUE(j.suu.isApprox(Eigen::Vector3d(-2 * std::cos(u), -2 * std::sin(u), 0), 1e-12));
  Eigen::Vector3d n;
  ASSERT_TRUE(unitNormal(j, n));
  EXPECT_GT(n.dot(j.p - Eigen::Vector3d(0, 0, v)), 0.99 * 2);  // outwards
  const SurfaceJet r = faceJet(s, true, u, v);
  EXPECT_TRUE(r.p.isApprox(j.p, 1e-15));
  EXPECT_TRUE(r.sv.isApprox(-j.sv, 1e-15));
  EXPECT_TRUE(r.suu.isApprox(j.suu, 1e-15));
  ASSERT_TRUE(unitNormal(r, n));
  EXPECT_LT(n.dot(j.p - Eigen::Vector3d(0, 0, v)), -0.99 * 2);  // inwards
}
