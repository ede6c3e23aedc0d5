#include <gtest/gtest.h>

#include <cmath>

#include "fitting/slim_descent.h"
#include "geometry/error.h"

using namespace holefill;

namespace {

// An n × n grid over [0, 1]², two triangles a cell, anticlockwise; vertex (i, j) is j (n + 1) + i.
Eigen::MatrixX3i gridTriangles(int n) {
  Eigen::MatrixX3i t(2 * n * n, 3);
  int k = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      t.row(k++) << a, b, c;
      t.row(k++) << a, c, d;
    }
  return t;
}

// Every vertex's u and v unknown but vertex 0's, held at the origin, and vertex 1's v (so the
// map cannot turn as a whole).
Eigen::SparseMatrix<double> freeMap(int nv, std::vector<int>& unknownOf) {
  std::vector<Eigen::Triplet<double>> T;
  int z = 0;
  unknownOf.assign(2 * nv, -1);
  for (int r = 2; r < 2 * nv; ++r)
    if (r != 3) T.emplace_back(r, z, 1.0), unknownOf[r] = z++;
  Eigen::SparseMatrix<double> m(2 * nv, z);
  m.setFromTriplets(T.begin(), T.end());
  return m;
}

// The problem over an n × n grid whose vertices sit at x (rest shapes from there) and start at
// `start` (stacked u, v per vertex), free as in freeMap; z0: the start's unknowns.
SlimProblem gridProblem(int n, const Eigen::MatrixX3d& x, const Eigen::VectorXd& start, Eigen::VectorXd& z0, std::vector<int>& unknownOf) {
  SlimProblem p;
  p.triangles = gridTriangles(n);
  p.rest = restShapes(x, p.triangles);
  p.skip.assign(p.triangles.rows(), 0);
  p.map = freeMap(static_cast<int>(x.rows()), unknownOf);
  z0.resize(p.map.cols());
  for (size_t r = 0; r < unknownOf.size(); ++r)
    if (unknownOf[r] >= 0) z0[unknownOf[r]] = start[static_cast<Eigen::Index>(r)];
  return p;
}

}  // namespace

TEST(SlimDescent, ASquashedMapOfACylinderPatchOpensToItsDevelopmentWithoutEverFolding) {
  // A quarter cylinder of radius 1 over a 12 × 12 grid develops onto a 1 × π/2 rectangle: the
  // symmetric Dirichlet energy's minimum is 4, an isometry. The start squashes it to a fifth in v.
  const int n = 12, nv = (n + 1) * (n + 1);
  Eigen::MatrixX3d x(nv, 3);
  Eigen::VectorXd start(2 * nv);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = double(i) / n, a = M_PI / 2 * j / n;
      x.row(j * (n + 1) + i) << u, std::sin(a), 1 - std::cos(a);
      start.segment<2>(2 * (j * (n + 1) + i)) << u, 0.2 * double(j) / n;
    }
  std::vector<int> unknownOf;
  Eigen::VectorXd z0;
  const SlimProblem p = gridProblem(n, x, start, z0, unknownOf);
  SlimOptions o;
  o.stop = 1e-12;
  o.iterations = 200;
  const SlimResult r = slimDescent(p, z0, o);
  std::printf("cylinder: energy %.6f -> %.6f in %d rounds\n", r.startEnergy, r.energy, r.iterations);
  EXPECT_GT(r.startEnergy, 10.0);
  EXPECT_NEAR(r.energy, 4.0, 1e-4);
  for (int t = 0; t < p.triangles.rows(); ++t) ASSERT_GT(mappedArea(p, r.z, t), 0) << "triangle " << t;
  // The far corner lands where the development puts it: (1, π/2) from the origin.
  const Eigen::VectorXd U = p.map * r.z;
  EXPECT_NEAR(Eigen::Vector2d(U[2 * (nv - 1)], U[2 * (nv - 1) + 1]).norm(), std::hypot(1.0, M_PI / 2), 1e-3);
}

TEST(SlimDescent, ATriangleStartedAlmostFlatOpensToItsRestShape) {
  // Vertex 0 at the origin, vertex 1 on the u axis (its u unknown), the apex free, started a
  // thousandth above the base: an energy near a million, whose proxy steps would overshoot past
  // the base; the line search keeps the area positive and it ends at the rest shape.
  SlimProblem p;
  p.triangles.resize(1, 3);
  p.triangles << 0, 1, 2;
  Eigen::MatrixX3d x(3, 3);
  x << 0, 0, 0, 1, 0, 0, 0.5, std::sqrt(3.0) / 2, 0;
  p.rest = restShapes(x, p.triangles);
  p.skip = {0};
  std::vector<Eigen::Triplet<double>> T = {{2, 0, 1.0}, {4, 1, 1.0}, {5, 2, 1.0}};
  p.map.resize(6, 3);
  p.map.setFromTriplets(T.begin(), T.end());
  Eigen::VectorXd z0(3);
  z0 << 1, 0.5, 1e-3;
  SlimOptions o;
  o.stop = 1e-12;
  o.iterations = 200;
  const SlimResult r = slimDescent(p, z0, o);
  std::printf("flat start: energy %.3g -> %.9f in %d rounds\n", r.startEnergy, r.energy, r.iterations);
  EXPECT_GT(r.startEnergy, 1e5);
  EXPECT_NEAR(r.energy, 4.0, 1e-6);
  EXPECT_NEAR(mappedArea(p, r.z, 0), std::sqrt(3.0) / 4, 1e-4);
}

TEST(SlimDescent, AStartWithATriangleTurnedOverIsRefused) {
  const int n = 2, nv = 9;
  Eigen::MatrixX3d x(nv, 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) x.row(j * 3 + i) << i, j, 0;
  Eigen::VectorXd start(2 * nv);
  for (int r = 0; r < 2 * nv; ++r) start[r] = x(r / 2, r % 2);
  std::vector<int> unknownOf;
  Eigen::VectorXd z0;
  SlimProblem p = gridProblem(n, x, start, z0, unknownOf);
  z0[unknownOf[2 * 4]] = 3.0;  // the middle vertex pulled out past the right side
  EXPECT_THROW(slimDescent(p, z0), Error);
  // Left out, the triangles it turns over do not count: the rest descends.
  for (int t = 0; t < p.triangles.rows(); ++t) p.skip[t] = !(mappedArea(p, z0, t) > 0);
  const SlimResult r = slimDescent(p, z0);
  EXPECT_LE(r.energy, r.startEnergy);
}
