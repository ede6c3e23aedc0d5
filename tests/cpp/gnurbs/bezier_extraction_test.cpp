#include <gtest/gtest.h>

#include <cmath>

#include "geometry/error.h"
#include "gnurbs/bezier_extraction.h"
#include "test_cages.h"

using namespace holefill;

namespace {

double height(double x, double y) { return 0.3 * std::sin(0.7 * x) * std::cos(0.5 * y) + 0.05 * x * y; }

// A regular open grid of (nx+1)×(ny+1) vertices, quads anticlockwise seen from +z, with knot
// intervals du[i] on the edges of column i and dv[j] on those of row j (a tensor-product cage).
QuadCage grid(const std::vector<double>& du, const std::vector<double>& dv) {
  const int nx = static_cast<int>(du.size()), ny = static_cast<int>(dv.size());
  QuadCage c;
  c.vertices.resize((nx + 1) * (ny + 1), 3);
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) c.vertices.row(i * (ny + 1) + j) << i * 1.1, j * 0.9 + 0.1 * i, height(i, j);
  c.quads.resize(nx * ny, 4);
  auto id = [&](int i, int j) { return i * (ny + 1) + j; };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) c.quads.row(i * ny + j) << id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1);
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      if (i < nx) c.setKnot(id(i, j), id(i + 1, j), du[i]);
      if (j < ny) c.setKnot(id(i, j), id(i, j + 1), dv[j]);
    }
  return c;
}

// Knots t_{-2} … t_{n+1} for control points 0 … n-1 (vertex i at t_i, edge i of length d[i]).
std::vector<double> knotVector(const std::vector<double>& d) {
  std::vector<double> t = {-2 * d.front(), -d.front(), 0};
  for (double x : d) t.push_back(t.back() + x);
  t.push_back(t.back() + d.back());
  t.push_back(t.back() + d.back());
  return t;
}

}  // namespace

TEST(QuadCage, FindsExtraordinaryPointsAndRefusesBadCages) {
  // Five quads around vertex 0: a valence-5 EP with a boundary ring.
  QuadCage c;
  c.vertices.resize(11, 3);
  c.vertices.row(0) << 0, 0, 0;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * M_PI * i / 5, b = a + M_PI / 5;
    c.vertices.row(1 + 2 * i) << std::cos(a), std::sin(a), 0;
    c.vertices.row(2 + 2 * i) << 1.6 * std::cos(b), 1.6 * std::sin(b), 0.2;
  }
  c.quads.resize(5, 4);
  for (int i = 0; i < 5; ++i) c.quads.row(i) << 0, 1 + 2 * i, 2 + 2 * i, 1 + 2 * ((i + 1) % 5);
  const CageTopology t(c);
  EXPECT_EQ(t.extraordinaryPoints(), std::vector<int>{0});
  EXPECT_EQ(t.valence(0), 5);
  EXPECT_TRUE(t.onBoundary(1));
  EXPECT_EQ(t.valence(1), 3);
  EXPECT_EQ(t.facesAround(1).size(), 2u);

  // The guidance surface is watertight: patches meeting at an edge share its border curve.
  c.setSharp(0, 3);
  c.anchors[0] = Eigen::Vector3d(0, 0, 0.4);
  const GuidanceSurface g = extractGuidanceSurface(c, CageTopology(c));
  EXPECT_LT((g.vertexPoints[0] - Eigen::Vector3d(0, 0, 0.4)).norm(), 1e-15);
  for (int f = 0; f < 5; ++f) {
    const int h = (f + 1) % 5;  // face f's last edge (3 → 0) is face h's first edge (0 → 1)
    for (double s : {0.0, 0.2, 0.5, 0.9, 1.0})
      EXPECT_LT((g.patches[f].point(0, s) - g.patches[h].point(s, 0)).norm(), 1e-14) << f << " " << s;
  }

  QuadCage bad = c;
  bad.quads(1, 0) = 42;
  EXPECT_THROW(CageTopology{bad}, Error);
  bad = c;
  bad.quads.row(1) << 0, 1 + 2 * 2, 2 + 2, 3;  // flipped: reuses directed edge 0 → 3 of quad 1's neighbour
  EXPECT_THROW(CageTopology{bad}, Error);
  bad = c;
  bad.setKnot(0, 1, -1);
  EXPECT_THROW(CageTopology{bad}, Error);
  bad = c;
  bad.setSharp(1, 5);
  EXPECT_THROW(CageTopology{bad}, Error);
  bad = c;
  bad.anchors.clear();
  bad.anchors[1] = Eigen::Vector3d::Zero();  // not an EP
  EXPECT_THROW(extractGuidanceSurface(bad, CageTopology(bad)), Error);
  bad = c;
  bad.vertices.conservativeResize(12, 3);
  bad.vertices.row(11) << 5, 5, 5;  // isolated
  EXPECT_THROW(CageTopology{bad}, Error);
  bad = c;
  bad.setKnot(0, 1, 0);
  EXPECT_THROW(CageTopology{bad}, Error);
  bad.quads.resize(0, 4);
  EXPECT_THROW(CageTopology{bad}, Error);
}

TEST(BezierExtraction, RegularNonUniformCageIsItsTensorProductBSpline) {
  const std::vector<double> du = {1.0, 0.5, 2.0, 1.2, 0.7, 1.5, 0.9}, dv = {0.8, 1.4, 0.6, 1.0, 2.2, 0.9};
  const QuadCage c = grid(du, dv);
  const CageTopology t(c);
  EXPECT_TRUE(t.extraordinaryPoints().empty());
  const GuidanceSurface g = extractGuidanceSurface(c, t);
  BSplineSurface ref;
  ref.knotsU = knotVector(du);
  ref.knotsV = knotVector(dv);
  ref.poles = c.vertices;
  const int nx = static_cast<int>(du.size()), ny = static_cast<int>(dv.size());
  ASSERT_EQ(ref.numU(), nx + 1);
  ASSERT_EQ(ref.numV(), ny + 1);
  double worst = 0;
  // Faces whose four corners have full B-spline support: not touching the cage boundary.
  for (int i = 1; i + 1 < nx; ++i)
    for (int j = 1; j + 1 < ny; ++j) {
      const double u0 = ref.knotsU[i + 2], v0 = ref.knotsV[j + 2];
      for (double s : {0.0, 0.25, 0.6, 1.0})
        for (double r : {0.0, 0.4, 0.8, 1.0})
          worst = std::max(worst, (g.patches[i * ny + j].point(s, r) - ref.point(u0 + s * du[i], v0 + r * dv[j])).norm());
    }
  EXPECT_LT(worst, 1e-12);
}

