#include <gtest/gtest.h>

#include "geometry/error.h"
#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/gnurbs_report.h"
#include "gnurbs/sample_cages.h"

using namespace holefill;

// The polar cage is what its doc says: n·k² quads around a valence-n EP at vertex 0, its points
// on height().
TEST(SampleCages, APolarCageHasItsValenceQuadsAndHeights) {
  for (int n : {3, 5, 8}) {
    const QuadCage c = cages::polarCage(n, 3);
    EXPECT_EQ(c.quads.rows(), n * 9) << n;
    EXPECT_EQ(c.vertices.rows(), 1 + n * 3 * (3 + 1)) << n;  // the EP, then per sector its spoke (k points) and its k × k block
    int valence0 = 0;
    for (Eigen::Index q = 0; q < c.quads.rows(); ++q)
      for (int k = 0; k < 4; ++k) valence0 += c.quads(q, k) == 0;
    EXPECT_EQ(valence0, n);
    for (Eigen::Index v = 0; v < c.vertices.rows(); ++v)
      EXPECT_NEAR(c.vertices(v, 2), cages::height(c.vertices(v, 0), c.vertices(v, 1)), 1e-12) << v;
  }
}

// Every bundled cage builds a G² surface (the cube after its Catmull–Clark step) with its EPs,
// continuous across every interior cage edge.
TEST(SampleCages, EveryBundledCageBuildsAG2Surface) {
  for (const std::string& name : cages::sampleCageNames()) {
    SCOPED_TRACE(name);
    const G2GnurbsResult r = buildG2Gnurbs(cages::sampleCage(name));
    EXPECT_FALSE(r.extraordinaryPoints.empty());
    EXPECT_TRUE(r.warnings.empty());
    const GnurbsContinuity c = measureGnurbsContinuity(r);
    EXPECT_LT(c.g0, 1e-9);
    EXPECT_LT(c.g1Spokes, 1e-7);
    EXPECT_LT(c.g1Elsewhere, 1e-7);
  }
  EXPECT_EQ(buildG2Gnurbs(cages::cubeCage()).refinements, 1);
  EXPECT_THROW(cages::sampleCage("cage_valence4"), Error);
}
