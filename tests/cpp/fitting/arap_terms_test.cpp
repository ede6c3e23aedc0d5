#include <gtest/gtest.h>

#include <cmath>

#include "fitting/arap_terms.h"
#include "test_regions.h"

using namespace holefill;

// An equilateral triangle: three terms, each edge's weight half the cotangent of 60°, its vector
// as long as the edge; the reference is Σ w |x|².
TEST(ArapTerms, WeightsAreHalfTheOppositeCotangents) {
  Eigen::MatrixX3d v(3, 3);
  v << 0, 0, 0, 2, 0, 0, 1, std::sqrt(3.0), 0;
  Eigen::MatrixX3i t(1, 3);
  t << 0, 1, 2;
  double reference = 0;
  const std::vector<ArapTerm> terms = arapTerms(v, t, reference);
  ASSERT_EQ(terms.size(), 3u);
  for (const ArapTerm& term : terms) {
    EXPECT_NEAR(term.w, 0.5 / std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(term.x.norm(), 2, 1e-12);
  }
  EXPECT_NEAR(reference, 3 * 0.5 / std::sqrt(3.0) * 4, 1e-12);
}

// A map that is a rotation of the region (by 0.7 rad) and a translation: the local step finds
// that rotation on every triangle; a mirrored map gets a rotation still (no reflection).
TEST(ArapTerms, TheLocalStepFindsEachTrianglesRotation) {
  Eigen::MatrixX2d uv;
  const TriangleMesh flat = testregions::gridRegion(4, 3, 0.5, [](double, double) { return true; },
                                                    [](double x, double y) { return Eigen::Vector3d(x, y, 0); }, uv);
  double reference = 0;
  const std::vector<ArapTerm> terms = arapTerms(flat.vertices, flat.triangles, reference);
  const Eigen::Matrix2d turn = Eigen::Rotation2Dd(0.7).toRotationMatrix();
  Eigen::MatrixX2d m = (uv * turn.transpose()).rowwise() + Eigen::RowVector2d(3, -1);
  const int nt = static_cast<int>(flat.triangles.rows());
  const std::vector<Eigen::Matrix2d> R = arapRotations(terms, m, nt);
  for (const ArapTerm& term : terms)
    EXPECT_LT(((m.row(term.i) - m.row(term.j)).transpose() - R[term.t] * term.x).norm(), 1e-12);
  m.col(0) *= -1;
  for (const Eigen::Matrix2d& r : arapRotations(terms, m, nt)) EXPECT_NEAR(r.determinant(), 1, 1e-12);
}

// Signed areas follow the triangles' turn; a triangle turned over in the input (its normal against
// its corners' mean normals) is found, and no other.
TEST(ArapTerms, TrianglesTurnedInTheInputAreFound) {
  Eigen::MatrixX2d uv;
  TriangleMesh flat = testregions::gridRegion(4, 4, 1, [](double, double) { return true; },
                                              [](double x, double y) { return Eigen::Vector3d(x, y, 0); }, uv);
  EXPECT_GT(signedArea(uv, flat.triangles.row(0).transpose()), 0);
  std::vector<char> turned = trianglesTurnedInInput(flat.vertices, flat.triangles);
  EXPECT_EQ(std::count(turned.begin(), turned.end(), 1), 0);
  // Vertex (2, 2) pushed past its neighbour (3, 3) turns the triangles between them over.
  Eigen::Index centre = 0;
  (uv.rowwise() - Eigen::RowVector2d(2, 2)).rowwise().norm().minCoeff(&centre);
  flat.vertices.row(centre) << 3.4, 3.4, 0;
  turned = trianglesTurnedInInput(flat.vertices, flat.triangles);
  int n = 0;
  for (Eigen::Index t = 0; t < flat.triangles.rows(); ++t) {
    const Eigen::Vector3d a = flat.vertices.row(flat.triangles(t, 0)), b = flat.vertices.row(flat.triangles(t, 1)),
                          c = flat.vertices.row(flat.triangles(t, 2));
    const bool against = (b - a).cross(c - a).z() < 0;
    EXPECT_EQ(turned[t] != 0, against) << t;
    n += against;
  }
  EXPECT_GT(n, 0);
}
