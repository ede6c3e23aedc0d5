#include "geometry/polygon2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace holefill;

TEST(Polygon2d, MeanValueCoordinatesReproduceLinearFunctions) {
  // A non-convex polygon: MVC stay well defined inside it.
  const Polygon2 p = {{0, 0}, {4, 0}, {4, 3}, {2, 1}, {0, 3}};
  for (const Eigen::Vector2d x : {Eigen::Vector2d(1, 0.5), Eigen::Vector2d(3.2, 1.5), Eigen::Vector2d(0.5, 2.0)}) {
    ASSERT_TRUE(contains(p, x));
    const Eigen::VectorXd w = meanValueCoordinates(p, x);
    EXPECT_NEAR(w.sum(), 1.0, 1e-12);
    Eigen::Vector2d r = Eigen::Vector2d::Zero();
    for (int i = 0; i < w.size(); ++i) r += w(i) * p[i];
    EXPECT_LT((r - x).norm(), 1e-12);
  }
}

TEST(Polygon2d, OrientationAndSelfIntersection) {
  const Polygon2 square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_NEAR(signedArea(square), 1.0, 1e-15);
  EXPECT_FALSE(selfIntersects(square));
  const Polygon2 bowtie = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_TRUE(selfIntersects(bowtie));
  const Polygon2 withRepeats = {{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  EXPECT_FALSE(selfIntersects(withRepeats));
  // A corner sampled by both its edges a hair apart (as a hole's boundary samples come): the edges
  // either side of the hair touch there, they do not cross (the fill's parameterizer read such
  // loops as folded and took another map).
  const Polygon2 hair = {{0, 0}, {1, 0}, {1 - 1e-15, -1e-15}, {1, 1}, {0, 1}};
  EXPECT_FALSE(selfIntersects(hair));
}

TEST(Polygon2d, LoopsCross) {
  const Polygon2 square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_FALSE(loopsCross(square, Polygon2{{0.5, 0.5}, {1.5, 0.5}, {1, 1.5}}));  // inside, apart
  EXPECT_FALSE(loopsCross(square, Polygon2{{3, 0}, {4, 0}, {4, 1}}));           // outside, apart
  EXPECT_TRUE(loopsCross(square, Polygon2{{1, 1}, {3, 1}, {3, 1.5}}));          // through the east side
}

TEST(Polygon2d, CrossingEdgesNamesTheEdgesThatCross) {
  // A loop that dips below its first edge: edges 2 and 3 run down through edge 0 and back.
  const Polygon2 dip = {{0, 0}, {2, 0}, {2, 1}, {1, -1}, {0, 1}};
  auto c = crossingEdges({dip});
  ASSERT_EQ(c.size(), 2u);
  std::vector<size_t> others;
  for (const auto& [e, f] : c) {
    EXPECT_EQ(std::min(e.edge, f.edge), 0u);
    others.push_back(std::max(e.edge, f.edge));
  }
  std::sort(others.begin(), others.end());
  EXPECT_EQ(others, (std::vector<size_t>{2, 3}));
  // Between loops: a square and a triangle through its east side, two crossings, none within.
  const Polygon2 square{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, tri{{1, 1}, {3, 1}, {3, 1.5}};
  const auto between = crossingEdges({square, tri});
  ASSERT_EQ(between.size(), 2u);
  for (const auto& [e, f] : between) {
    EXPECT_NE(e.loop, f.loop);
    EXPECT_EQ((e.loop == 0 ? e : f).edge, 1u);  // the square's east side
  }
  EXPECT_EQ(crossingEdges({square, tri}, 1).size(), 1u);  // the limit
}

TEST(Polygon2d, CrossingEdgesOnALargeLoopFindsTheOneCrossing) {
  // 20,000 edges on a wavy circle; two consecutive vertices swapped make their chords cross (the
  // ends interleave along the arc).
  Polygon2 loop;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n, r = 1 + 0.01 * std::sin(40 * t);
    loop.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  EXPECT_TRUE(crossingEdges({loop}).empty());
  std::swap(loop[5000], loop[5001]);
  const auto c = crossingEdges({loop});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(std::min(c[0].first.edge, c[0].second.edge), 4999u);
  EXPECT_EQ(std::max(c[0].first.edge, c[0].second.edge), 5001u);
}

// A loop that runs along the bottom of a square, turns up and back over its own stretch and then
// below it (a map folded at a held side, as on the corpus's cone_blob_n0p2): no edge crosses
// another properly, a vertex lies on an earlier edge, and the wire is self-intersecting. Counted
// as a contact with `touch`, the fold is cut off and the square kept.
TEST(Polygon2d, AFoldThatTouchesItsOwnStretchIsCutOff) {
  const Polygon2 folded{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {2.9, 0.1}, {1.5, 0}, {2.5, -0.1}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_FALSE(selfIntersects(folded));
  EXPECT_FALSE(crossingEdges({folded}, SIZE_MAX, 1e-12).empty());
  const Polygon2 clean = withoutSelfContacts(folded, 1e-12);
  EXPECT_TRUE(crossingEdges({clean}, SIZE_MAX, 1e-12).empty());
  EXPECT_GT(signedArea(clean), 15.5);
  EXPECT_LE(clean.size(), folded.size() - 3);
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 4), Eigen::Vector2d(0, 4)})
    EXPECT_NE(std::find(clean.begin(), clean.end(), corner), clean.end());
  // A simple loop comes back unchanged, whatever its orientation.
  const Polygon2 square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(withoutSelfContacts(square, 1e-12), square);
  const Polygon2 clockwise(square.rbegin(), square.rend());
  EXPECT_EQ(withoutSelfContacts(clockwise, 1e-12), clockwise);
  // A figure eight keeps its larger lobe.
  const Polygon2 eight{{0, 0}, {2, 2}, {2, 0}, {0, 2}, {-3, 2}, {-3, 0}};
  const Polygon2 lobe = withoutSelfContacts(eight, 0);
  EXPECT_FALSE(selfIntersects(lobe));
  EXPECT_GT(std::abs(signedArea(lobe)), 4);
}

// A 4 × 1 rectangle turned by 0.3 rad, with points inside it: turned by the angle found, it is
// axis-aligned again (back by 0.3, or on by π/2 − 0.3, which the range [0, π/2) picks); an L's
// points need no turn; two points or a line give 0.
TEST(Polygon2d, LeastAreaRectangleAngleAlignsTheSnuggestBox) {
  const Eigen::Matrix2d turn = Eigen::Rotation2Dd(0.3).toRotationMatrix();
  std::vector<Eigen::Vector2d> pts;
  for (const Eigen::Vector2d q : {Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0), Eigen::Vector2d(4, 1), Eigen::Vector2d(0, 1),
                                  Eigen::Vector2d(2, 0.5), Eigen::Vector2d(1, 0.2)})
    pts.push_back(turn * q);
  const double a = leastAreaRectangleAngle(pts);
  EXPECT_NEAR(a, M_PI / 2 - 0.3, 1e-12);
  const Eigen::Matrix2d back = Eigen::Rotation2Dd(a).toRotationMatrix();
  Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
  for (const auto& q : pts) lo = lo.cwiseMin(back * q), hi = hi.cwiseMax(back * q);
  EXPECT_NEAR((hi - lo).prod(), 4, 1e-12);
  const std::vector<Eigen::Vector2d> ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_NEAR(leastAreaRectangleAngle(ell), 0, 1e-12);
  EXPECT_EQ(leastAreaRectangleAngle({{0, 0}, {1, 1}}), 0);
  EXPECT_EQ(leastAreaRectangleAngle({{0, 0}, {1, 1}, {2, 2}}), 0);
}
