#include "inspect/surface_fields.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <Geom_BezierSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <cmath>
#include <random>

#include "geometry/occt_bridge.h"
#include "inspect/inspection_values.h"

using namespace holefill;

namespace {

TopoDS_Face firstFace(const TopoDS_Shape& s, GeomAbs_SurfaceType type) {
  for (TopExp_Explorer ex(s, TopAbs_FACE); ex.More(); ex.Next())
    if (BRepAdaptor_Surface(TopoDS::Face(ex.Current())).GetType() == type) return TopoDS::Face(ex.Current());
  return {};
}

Eigen::MatrixX2d randomUv(const TopoDS_Face& f, int n, unsigned seed, double margin) {
  const BRepAdaptor_Surface s(f);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(margin, 1 - margin);
  Eigen::MatrixX2d uv(n, 2);
  for (int i = 0; i < n; ++i)
    uv.row(i) << s.FirstUParameter() + d(rng) * (s.LastUParameter() - s.FirstUParameter()),
        s.FirstVParameter() + d(rng) * (s.LastVParameter() - s.FirstVParameter());
  return uv;
}

// z = a x^2 + b xy + c y^2 + d x + e y over [0,1]^2 as a biquadratic Bezier patch (exact: the
// polynomial is biquadratic), poles from interpolation at the 3x3 grid {0, 1/2, 1}^2.
struct Quadric {
  double a = 0.7, b = -1.3, c = -0.9, d = 0.2, e = -0.4;
  double f(double x, double y) const { return a * x * x + b * x * y + c * y * y + d * x + e * y; }
  TopoDS_Face face() const {
    const auto B = [](int i, double t) { return i == 0 ? (1 - t) * (1 - t) : i == 1 ? 2 * t * (1 - t) : t * t; };
    Eigen::Matrix<double, 9, 9> M;
    Eigen::Matrix<double, 9, 1> z;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) {
        const double x = p / 2.0, y = q / 2.0;
        z(3 * p + q) = f(x, y);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) M(3 * p + q, 3 * i + j) = B(i, x) * B(j, y);
      }
    const Eigen::Matrix<double, 9, 1> w = M.lu().solve(z);
    TColgp_Array2OfPnt poles(1, 3, 1, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) poles(i + 1, j + 1) = gp_Pnt(i / 2.0, j / 2.0, w(3 * i + j));
    return BRepBuilderAPI_MakeFace(new Geom_BezierSurface(poles), 1e-9).Face();
  }
  // Graph curvatures with the upward normal, in the CAD sign (bending away from the normal is positive).
  void curvatures(double x, double y, double& K, double& H) const {
    const double fx = 2 * a * x + b * y + d, fy = b * x + 2 * c * y + e, fxx = 2 * a, fxy = b, fyy = 2 * c;
    const double g = 1 + fx * fx + fy * fy;
    K = (fxx * fyy - fxy * fxy) / (g * g);
    H = -((1 + fy * fy) * fxx - 2 * fx * fy * fxy + (1 + fx * fx) * fyy) / (2 * std::pow(g, 1.5));
  }
};

}  // namespace

TEST(SurfaceFields, SphereHasConstantCurvatureOneOverRadius) {
  const double r = 3.0;
  const TopoDS_Face f = firstFace(BRepPrimAPI_MakeSphere(r).Shape(), GeomAbs_Sphere);
  const SurfaceFields s = evaluateFaceFields(f, randomUv(f, 5000, 1, 0.02));
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    ASSERT_TRUE(s.regular[i]);
    EXPECT_NEAR(s.k1(i), 1 / r, 1e-12);
    EXPECT_NEAR(s.k2(i), 1 / r, 1e-12);
    EXPECT_NEAR(s.points.row(i).norm(), r, 1e-12);
    EXPECT_GT(s.normals.row(i).dot(s.points.row(i)), 0.999 * r);  // outward
  }
  const Eigen::VectorXd K = curvatureValues(s, CurvatureQuantity::Gaussian), H = curvatureValues(s, CurvatureQuantity::Mean);
  EXPECT_NEAR(K.minCoeff(), 1 / (r * r), 1e-12);
  EXPECT_NEAR(K.maxCoeff(), 1 / (r * r), 1e-12);
  EXPECT_NEAR(H.minCoeff(), 1 / r, 1e-12);
}

TEST(SurfaceFields, SpherePoleIsSingularNotNan) {
  const TopoDS_Face f = firstFace(BRepPrimAPI_MakeSphere(1.0).Shape(), GeomAbs_Sphere);
  Eigen::MatrixX2d uv(2, 2);
  uv << 0.3, M_PI / 2, 0.3, 0.0;
  const SurfaceFields s = evaluateFaceFields(f, uv, 1);
  EXPECT_FALSE(s.regular[0]);
  EXPECT_TRUE(std::isnan(s.k1(0)));
  EXPECT_TRUE(s.regular[1]);
}

TEST(SurfaceFields, CylinderHasZeroAndOneOverRadius) {
  const double r = 2.0;
  const TopoDS_Face f = firstFace(BRepPrimAPI_MakeCylinder(r, 5.0).Shape(), GeomAbs_Cylinder);
  const SurfaceFields s = evaluateFaceFields(f, randomUv(f, 3000, 2, 0.0));
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    EXPECT_NEAR(s.k1(i), 1 / r, 1e-12);
    EXPECT_NEAR(s.k2(i), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(s.d1(i, 2)), 0.0, 1e-9);  // the bending direction goes round the axis
  }
  EXPECT_NEAR(curvatureValues(s, CurvatureQuantity::Gaussian).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  // Along the axis the normal curvature is 0, around it 1/r.
  EXPECT_NEAR(curvatureValues(s, CurvatureQuantity::Direction, Eigen::Vector3d::UnitZ()).cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

TEST(SurfaceFields, BezierQuadricMatchesAnalyticCurvature) {
  const Quadric q;
  const TopoDS_Face f = q.face();
  const SurfaceFields s = evaluateFaceFields(f, randomUv(f, 2000, 3, 0.0));
  int saddles = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    double K, H;
    q.curvatures(s.points(i, 0), s.points(i, 1), K, H);
    EXPECT_NEAR(s.points(i, 2), q.f(s.points(i, 0), s.points(i, 1)), 1e-12);
    EXPECT_NEAR(s.k1(i) * s.k2(i), K, 1e-10);
    EXPECT_NEAR(0.5 * (s.k1(i) + s.k2(i)), H, 1e-10);
    saddles += K < 0;
  }
  EXPECT_EQ(saddles, s.size());  // 4ac - b^2 < 0: a saddle everywhere, Gaussian curvature negative
}

TEST(SurfaceFields, DirectionCurvatureMatchesFiniteDifferences) {
  const TopoDS_Face f = Quadric().face();
  const BRepAdaptor_Surface surf(f);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> d(0.1, 0.9), ang(0, M_PI);
  for (int k = 0; k < 50; ++k) {
    const double u = d(rng), v = d(rng), a = ang(rng);
    Eigen::MatrixX2d uv(1, 2);
    uv << u, v;
    const SurfaceFields s = evaluateFaceFields(f, uv, 1);
    const SurfaceJet j = faceJet(surf, false, u, v);
    const Eigen::Vector3d n = s.normals.row(0), t = std::cos(a) * j.su.normalized() + std::sin(a) * n.cross(j.su).normalized();
    // The surface curve through (u, v) whose tangent is t; normal curvature = -c''.n / |c'|^2 (CAD sign).
    const Eigen::Vector2d ab = parameterDirection(j, t);
    const double h = 1e-4;
    const auto c = [&](double s_) { return toEigen(surf.Value(u + s_ * ab(0), v + s_ * ab(1))); };
    const Eigen::Vector3d c1 = (c(h) - c(-h)) / (2 * h), c2 = (c(h) - 2 * c(0) + c(-h)) / (h * h);
    const double fd = -c2.dot(n) / c1.squaredNorm();
    EXPECT_NEAR(curvatureValues(s, CurvatureQuantity::Direction, t)(0), fd, 1e-5);
  }
}

TEST(SurfaceFields, ThreadsGiveTheSameNumbers) {
  const TopoDS_Face f = Quadric().face();
  const Eigen::MatrixX2d uv = randomUv(f, 20000, 5, 0.0);
  const SurfaceFields a = evaluateFaceFields(f, uv, 1), b = evaluateFaceFields(f, uv, 2);
  EXPECT_EQ((a.k1 - b.k1).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((a.normals - b.normals).cwiseAbs().maxCoeff(), 0.0);
}
