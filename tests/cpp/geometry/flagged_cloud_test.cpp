#include "geometry/flagged_cloud.h"

#include <gtest/gtest.h>

#include "geometry/error.h"

using namespace holefill;

TEST(FlaggedCloud, BareLinesHaveNoFlagsAndMixingIsRefused) {
  const FlaggedCloud c = parseFlaggedCloud("0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_FALSE(c.flagsGiven);
  EXPECT_FALSE(c.boundaryUVGiven);
  EXPECT_EQ(c.points.rows(), 3);
  EXPECT_THROW(parseFlaggedCloud("0 0 0\n1 0 0 1\n"), Error);
  EXPECT_TRUE(parseFlaggedCloud("0 0 0 1 0 0\n1 0 0 0\n").flagsGiven);
}
