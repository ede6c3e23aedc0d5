#include <gtest/gtest.h>

#include <cmath>

#include "geometry/error.h"
#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/patch_continuity.h"

using namespace holefill;

namespace {

double height(double x, double y) { return 0.25 * std::sin(0.8 * x + 0.3) * std::cos(0.6 * y) + 0.04 * x * y; }

// A valence-n EP (vertex 0) with n sectors of k×k quads: sector i spans spokes i and i+1, its
// point (a, b) sits at a·e_i + b·e_{i+1} lifted onto height(), e_i at angle 2πi/n.
QuadCage polarCage(int n, int k) {
  QuadCage c;
  c.vertices.resize(1 + n * k + n * k * k, 3);
  auto pos = [&](int i, int a, int b) {
    const double ai = 2 * M_PI * i / n, aj = 2 * M_PI * (i + 1) / n;
    const double x = a * std::cos(ai) + b * std::cos(aj), y = a * std::sin(ai) + b * std::sin(aj);
    return Eigen::RowVector3d(x, y, height(x, y));
  };
  auto id = [&](int i, int a, int b) {
    i %= n;
    if (a == 0 && b == 0) return 0;
    if (b == 0) return 1 + i * k + (a - 1);
    if (a == 0) return 1 + ((i + 1) % n) * k + (b - 1);
    return 1 + n * k + i * k * k + (a - 1) * k + (b - 1);
  };
  for (int i = 0; i < n; ++i)
    for (int a = 0; a <= k; ++a)
      for (int b = 0; b <= k; ++b) c.vertices.row(id(i, a, b)) = pos(i, a, b);
  c.quads.resize(n * k * k, 4);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) c.quads.row((i * k + a) * k + b) << id(i, a, b), id(i, a + 1, b), id(i, a + 1, b + 1), id(i, a, b + 1);
  return c;
}

double diagonal(const QuadCage& c) { return (c.vertices.colwise().maxCoeff() - c.vertices.colwise().minCoeff()).norm(); }

}  // namespace

TEST(G2Gnurbs, SingleEPsOfValence3568AreG2AcrossEveryEdge) {
  for (int n : {3, 5, 6, 8}) {
    SCOPED_TRACE("valence " + std::to_string(n));
    const QuadCage cage = polarCage(n, 4);
    const G2GnurbsResult r = buildG2Gnurbs(cage);
    EXPECT_EQ(r.extraordinaryPoints, std::vector<int>{0});
    EXPECT_EQ(r.irregularFaces, n);
    EXPECT_LT(r.infeasibility, 1e-10);
    const auto edges = cageEdgeContinuity(cage, CageTopology(cage), faceJets(r), 21, diagonal(cage));
    double g0 = 0, g1Spoke = 0, g2Spoke = 0, g1 = 0, g2 = 0;
    for (const auto& e : edges) {
      g0 = std::max(g0, e.g0);
      (e.nearEP ? g1Spoke : g1) = std::max(e.nearEP ? g1Spoke : g1, e.g1);
      (e.nearEP ? g2Spoke : g2) = std::max(e.nearEP ? g2Spoke : g2, e.g2);
    }
    std::printf("valence %d: residual %.2e  G0 %.2e  spokes G1 %.2e G2 %.2e  elsewhere G1 %.2e G2 %.2e\n", n, r.constraintResidual, g0,
                g1Spoke, g2Spoke, g1, g2);
    EXPECT_LT(g0, 1e-12);
    EXPECT_LT(g1Spoke, 1e-8);
    EXPECT_LT(g2Spoke, 1e-6);
    EXPECT_LT(g1, 1e-8);
    EXPECT_LT(g2, 1e-6);
  }
}
