#include "inspect/inspection_values.h"

#include <BRepPrimAPI_MakeBox.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "brep/sample_models.h"
#include "geometry/error.h"
#include "inspect/shape_tessellation.h"

using namespace holefill;

TEST(InspectionValues, StripesOnAPlaneAreConstant) {
  const Eigen::Vector3d n(0, 0, 1), view = Eigen::Vector3d(0.3, -0.2, -1).normalized(), d(1, 0, 0);
  EXPECT_NEAR(stripeParameter(n, view, d, StripeMode::Isophote), 0.5, 1e-15);
  // The mirrored ray of view at z-up is (0.3, -0.2, 1)/|.|: angle to x.
  const double expect = std::acos(view.x()) / M_PI;
  EXPECT_NEAR(stripeParameter(n, view, d, StripeMode::Reflection), expect, 1e-15);
  EXPECT_NEAR(stripeParameter(-n, view, d, StripeMode::Reflection), expect, 1e-15);  // mirror ignores the normal's sign
  StripeOptions o;
  o.count = 4;
  o.width = 0.25;
  EXPECT_TRUE(stripeBlack(0.01, o));
  EXPECT_FALSE(stripeBlack(0.1, o));
  EXPECT_TRUE(stripeBlack(0.26, o));
}

TEST(InspectionValues, ReflectionLinesAreContinuousAcrossTangentJoints) {
  // filleted_box_corner is G1 everywhere between planes, cylinders and the corner sphere:
  // where two faces share a boundary point, their stripe parameters must agree.
  const TessellationResult t = tessellateForInspection(samples::byName("filleted_box_corner"));
  const InspectionMesh& m = t.mesh;
  std::map<std::array<long long, 3>, std::vector<Eigen::Index>> at;
  for (Eigen::Index i = 0; i < m.fields.size(); ++i) {
    const Eigen::Vector3d p = m.fields.points.row(i) * 1e6;
    at[{std::llround(p.x()), std::llround(p.y()), std::llround(p.z())}].push_back(i);
  }
  const Eigen::Vector3d view = Eigen::Vector3d(-1, 1, -1).normalized(), d = Eigen::Vector3d(1, 1, 0).normalized();
  int shared = 0;
  double worst = 0;
  for (const auto& [key, ids] : at)
    for (size_t k = 1; k < ids.size(); ++k) {
      if (m.vertexFace[ids[k]] == m.vertexFace[ids[0]] || !m.fields.regular[ids[0]] || !m.fields.regular[ids[k]]) continue;
      ++shared;
      const double a = stripeParameter(m.fields.normals.row(ids[0]), view, d, StripeMode::Reflection);
      const double b = stripeParameter(m.fields.normals.row(ids[k]), view, d, StripeMode::Reflection);
      worst = std::max(worst, std::abs(a - b));
    }
  EXPECT_GT(shared, 100);
  EXPECT_LT(worst, 1e-6);
}

TEST(InspectionValues, ReflectionLinesJumpAtASharpEdge) {
  const TessellationResult t = tessellateForInspection(BRepPrimAPI_MakeBox(1, 1, 1).Shape());
  const Eigen::Vector3d view = Eigen::Vector3d(-1, 1, -1).normalized(), d(1, 0, 0);
  double lo = 1, hi = 0;
  for (Eigen::Index i = 0; i < t.mesh.fields.size(); ++i) {
    const double s = stripeParameter(t.mesh.fields.normals.row(i), view, d, StripeMode::Reflection);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  EXPECT_GT(hi - lo, 0.2);
}

TEST(InspectionValues, ParsingNamesAndErrors) {
  EXPECT_EQ(curvatureQuantityFromString("gaussian"), CurvatureQuantity::Gaussian);
  EXPECT_EQ(curvatureQuantityFromString("max"), CurvatureQuantity::MaxPrincipal);
  EXPECT_THROW(curvatureQuantityFromString("bogus"), Error);
  EXPECT_EQ(stripeModeFromString("isophote"), StripeMode::Isophote);
  EXPECT_THROW(stripeModeFromString(""), Error);
}

