#include "gnurbs/catmull_clark.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_cages.h"

using namespace holefill;

TEST(CatmullClark, OneStepKeepsVerticesCreasesAndIntervalsAndSeparatesEPs) {
  const QuadCage cube = testcages::cubeCage();
  const QuadCage once = catmullClarkStep(cube, CageTopology(cube));
  const CageTopology t(once);
  EXPECT_EQ(once.vertices.rows(), 8 + 12 + 6);
  EXPECT_EQ(t.extraordinaryPoints(), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  // The cube's corner rule: (F + 2R + (n−3)V)/n with n = 3 puts the corner at 5/9 of the way.
  EXPECT_NEAR(once.vertices.row(7).norm(), std::sqrt(3.0) * 5.0 / 9.0, 1e-14);
  for (int f = 0; f < t.faceCount(); ++f) {
    int eps = 0;
    for (int k = 0; k < 4; ++k) eps += t.isExtraordinary(once.quads(f, k));
    EXPECT_EQ(eps, 1) << f;
  }
  // Creases: an open grid's boundary stays on the cage boundary's polygon, sharp edges split into
  // sharp halves, intervals halve.
  QuadCage grid;
  grid.vertices.resize(9, 3);
  for (int v = 0; v < 9; ++v) grid.vertices.row(v) << v % 3, v / 3, (v == 4 ? 1.0 : 0.0);
  grid.quads.resize(4, 4);
  grid.quads << 0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7;
  grid.setSharp(1, 4);
  grid.setSharp(4, 7);
  grid.setKnot(0, 1, 3);
  const QuadCage g1 = catmullClarkStep(grid, CageTopology(grid));
  EXPECT_NEAR(g1.vertices(1, 1), 0, 1e-15);                     // boundary vertex stays on y = 0
  EXPECT_NEAR(g1.vertices(4, 2), 0.75, 1e-15);                  // crease vertex: (6·1 + 0 + 0)/8
  EXPECT_EQ(g1.sharp.size(), 4u);
  for (std::uint64_t key : g1.sharp) {  // each half runs from an original crease vertex to its edge's midpoint
    const int lo = static_cast<int>(key & 0xffffffffu), hi = static_cast<int>(key >> 32);
    EXPECT_TRUE(lo == 1 || lo == 4 || lo == 7) << lo;
    EXPECT_EQ(g1.vertices(hi, 0), 1.0);
  }
  int halves = 0;
  for (const auto& [key, d] : g1.knots) halves += std::abs(d - 1.5) < 1e-15;
  EXPECT_EQ(halves, 2);
  EXPECT_NO_THROW(CageTopology{g1});
}
