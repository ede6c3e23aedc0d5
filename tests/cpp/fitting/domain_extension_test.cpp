#include <gtest/gtest.h>

#include <cmath>

#include "fitting/domain_extension.h"
#include "geometry/error.h"
#include "test_regions.h"

using namespace holefill;

namespace {

// A disk-like region: the grid cells of [0, 4] × [0, 2] (spacing 0.25) whose centre lies in an
// ellipse, lifted by f; uv = (x, y).
TriangleMesh ellipseRegion(const std::function<double(double, double)>& f, Eigen::MatrixX2d& uv) {
  return testregions::gridRegion(
      16, 8, 0.25, [](double x, double y) { return (x - 2) * (x - 2) / 3.2 + (y - 1) * (y - 1) / 0.7 <= 1; },
      [&](double x, double y) { return Eigen::Vector3d(x, y, f(x, y)); }, uv);
}

}  // namespace

TEST(DomainExtension, FillsTheRectangleKeepsTheRegionAndContinuesPlanesAndQuadrics) {
  struct Case {
    const char* name;
    std::function<double(double, double)> f;
    double tolerance;
  };
  for (const Case& c : {Case{"plane", [](double x, double y) { return 0.3 * x - 0.2 * y + 1; }, 1e-8},
                        Case{"quadric", [](double x, double y) { return 0.1 * (x - 2) * (x - 2) - 0.15 * (y - 1) * (y - 1) + 0.05 * x * y; }, 0.01}}) {
    for (int order : {2, 3}) {
      SCOPED_TRACE(std::string(c.name) + ", order " + std::to_string(order));
      Eigen::MatrixX2d uv;
      const TriangleMesh region = ellipseRegion(c.f, uv);
      DomainExtensionOptions o;
      o.order = order;
      o.marginLayers = 1;
      const DomainExtension e = extendToRectangle(region, uv, 4, 2, o);
      ASSERT_GT(e.mesh.vertices.rows(), region.vertices.rows());
      EXPECT_EQ(e.mesh.vertices.topRows(region.vertices.rows()), region.vertices);  // the region stays as it was
      EXPECT_EQ(e.mesh.triangles.topRows(region.triangles.rows()), region.triangles);
      // The extended triangles tile the enlarged rectangle: areas add up, none folded.
      double area = 0;
      int folded = 0;
      for (Eigen::Index t = 0; t < e.mesh.triangles.rows(); ++t) {
        const Eigen::Vector2d a = e.uv.row(e.mesh.triangles(t, 1)) - e.uv.row(e.mesh.triangles(t, 0));
        const Eigen::Vector2d b = e.uv.row(e.mesh.triangles(t, 2)) - e.uv.row(e.mesh.triangles(t, 0));
        const double s = 0.5 * (a.x() * b.y() - a.y() * b.x());
        area += s;
        folded += s <= 0;
      }
      EXPECT_EQ(folded, 0);
      EXPECT_NEAR(area, (e.u1 - e.u0) * (e.v1 - e.v0), 1e-9);
      // New vertices continue the surface: exact for a plane, close for the quadric.
      double worst = 0;
      for (Eigen::Index v = region.vertices.rows(); v < e.mesh.vertices.rows(); ++v)
        worst = std::max(worst, std::abs(e.mesh.vertices(v, 2) - c.f(e.uv(v, 0), e.uv(v, 1))));
      std::printf("%s, order %d: %d new vertices, max deviation from the truth outside the region %.2e\n", c.name, order,
                  static_cast<int>(e.mesh.vertices.rows() - region.vertices.rows()), worst);
      // Measured: the plane to 1.4e-9; the quadric (heights within ±0.4) to 2.0e-3 with k = 2 and
      // 7.2e-3 with k = 3 (the grid here does not run through the region's vertices, so the
      // cotangent Laplacian next to the region's boundary is exact on linear data only; on a
      // grid through them a bicubic is continued exactly, see tensor_fit_test).
      EXPECT_LT(worst, c.tolerance);
    }
  }
}

TEST(DomainExtension, RefusesMismatchedOrBadInput) {
  Eigen::MatrixX2d uv;
  const TriangleMesh region = ellipseRegion([](double, double) { return 0.0; }, uv);
  EXPECT_THROW(extendToRectangle(region, uv.topRows(3), 4, 2), Error);
  Eigen::MatrixX2d bad = uv;
  bad(2, 0) = std::nan("");
  EXPECT_THROW(extendToRectangle(region, bad, 4, 2), Error);
  DomainExtensionOptions o;
  o.order = 4;
  EXPECT_THROW(extendToRectangle(region, uv, 4, 2, o), Error);
  EXPECT_THROW(extendToRectangle(region, uv, 0, 2), Error);
}
