#include "mesh/triangle_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/error.h"

using namespace holefill;

namespace {

// A unit square of two triangles in z = 0, anticlockwise seen from +z.
TriangleMesh square() {
  TriangleMesh m;
  m.vertices.resize(4, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 2, 3;
  return m;
}

}  // namespace

TEST(TriangleMesh, ValidationNamesTheFirstBadVertexOrTriangle) {
  EXPECT_NO_THROW(validateMesh(square()));
  TriangleMesh m = square();
  m.vertices(2, 1) = std::nan("");
  try {
    validateMesh(m, "scan.obj");
    ADD_FAILURE() << "a NaN vertex was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("scan.obj"), std::string::npos) << e.what();
  }
  m = square();
  m.triangles(1, 2) = 4;  // out of range
  EXPECT_THROW(validateMesh(m), Error);
  m = square();
  m.triangles(0, 1) = 0;  // a vertex repeated
  EXPECT_THROW(validateMesh(m), Error);
}

TEST(TriangleMesh, QualityAnglesAndNormalsOfKnownTriangles) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(0.75), 0);
  EXPECT_NEAR(triangleQuality(a, b, c), 1.0, 1e-12);  // equilateral: the best
  EXPECT_NEAR(maxInnerAngle(a, b, c), M_PI / 3, 1e-12);
  EXPECT_NEAR(triangleQuality(a, b, Eigen::Vector3d(2, 0, 0)), 0.0, 1e-12);  // collinear
  EXPECT_NEAR(maxInnerAngle(a, b, Eigen::Vector3d(0.5, 0, 0)), M_PI, 1e-12);
  EXPECT_NEAR(maxInnerAngle(a, b, b), M_PI, 1e-12);  // degenerate: pi
  // atan2 keeps tiny angles: acos of the dot product would give 0 or 1.5e-8.
  EXPECT_NEAR(angleBetween(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1e-12, 0)), 1e-12, 1e-20);
  EXPECT_EQ(angleBetween(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0)), 0.0);
  const Eigen::MatrixX3d n = vertexNormals(square());
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(n.row(k).dot(Eigen::RowVector3d(0, 0, 1)), 1.0, 1e-12) << k;
}

TEST(TriangleMesh, WeldingCopiesClosesASeam) {
  // The square cut along its diagonal into two triangles with their own copies of it (a seam).
  TriangleMesh m;
  m.vertices.resize(6, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 3, 4, 5;
  EXPECT_EQ(countBoundaryEdges(m), 6);  // the seam counts twice
  const std::vector<int> weld = weldMap(m.vertices, 1e-9);
  EXPECT_EQ(weld, (std::vector<int>{0, 1, 2, 0, 2, 5}));
  EXPECT_EQ(countBoundaryEdges(m, weld), 4);  // the square's own rim
  EXPECT_EQ(countBoundaryEdges(square()), 4);
  EXPECT_NEAR(boundingDiagonal(m.vertices), std::sqrt(2.0), 1e-15);
  EXPECT_EQ(boundingDiagonal(Eigen::MatrixX3d(0, 3)), 0.0);
}
