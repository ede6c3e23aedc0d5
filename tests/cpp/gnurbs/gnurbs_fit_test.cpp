#include <gtest/gtest.h>

#include <random>

#include "geometry/error.h"
#include "gnurbs/gnurbs_fit.h"
#include "test_cages.h"

using namespace holefill;
using namespace holefill::testcages;

namespace {

// Points on a G-NURBS surface at random parameters of every patch.
Eigen::MatrixX3d samplesOf(const G2GnurbsResult& s, int perPatch, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  Eigen::MatrixX3d out(static_cast<Eigen::Index>(s.patches.size()) * perPatch, 3);
  Eigen::Index k = 0;
  for (const auto& p : s.patches)
    for (int i = 0; i < perPatch; ++i) out.row(k++) = p.surface.point(U(rng), U(rng)).transpose();
  return out;
}

}  // namespace

TEST(GnurbsFit, ReproducesAGnurbsSurfaceFromAPerturbedCage) {
  QuadCage truth = polarCage(5, 3);
  cages::setSharpSpokeLine(truth, 3, 0);  // a sharp EP with an anchor: anchors are fitted too
  truth.anchors[0] = Eigen::Vector3d(0.05, -0.02, 0.35);
  const Eigen::MatrixX3d target = samplesOf(buildG2Gnurbs(truth), 12, 1);
  QuadCage start = truth;
  std::mt19937 rng(2);
  std::normal_distribution<double> N(0, 0.05);
  for (Eigen::Index v = 0; v < start.vertices.rows(); ++v)
    for (int c = 0; c < 3; ++c) start.vertices(v, c) += N(rng);
  start.anchors[0] = start.vertices.row(0).transpose();
  GnurbsFitOptions o;
  o.iterations = 6;
  const GnurbsFitResult r = fitGnurbs(start, target, o);
  std::printf("reproduction: d_max %.2e d_avg %.2e (of the diagonal), sharp d_max %.2e over %d points; d_avg per round", r.dMax, r.dAvg,
              r.dMaxSharp, r.sharpPoints);
  for (double d : r.dAvgPerRound) std::printf(" %.1e", d);
  std::printf("\n");
  EXPECT_EQ(r.variables, static_cast<int>(truth.vertices.rows()) + 1);
  EXPECT_GT(r.dAvgPerRound.front(), 1e-3);  // the start is off
  EXPECT_LT(r.dAvg, 1e-4);
  EXPECT_LT(r.dMax, 1e-3);
  EXPECT_GT(r.sharpPoints, 50);
  EXPECT_LT((r.cage.anchors.at(0) - truth.anchors.at(0)).norm(), 0.05);  // the anchor went back to its place
  // The fitted surface is a G-NURBS surface like any other: G² off the creases.
  const auto edges = cageEdgeContinuity(r.surface.cage, CageTopology(r.surface.cage), faceJets(r.surface), 21, diagonal(r.surface.cage));
  for (const auto& e : edges)
    if (!e.sharp) EXPECT_LT(e.g2, 1e-6) << e.a << "-" << e.b;
}

TEST(GnurbsFit, StartingAtTheAnswerStaysThereAndBadTargetsAreRefused) {
  const QuadCage truth = polarCage(6, 2);
  const Eigen::MatrixX3d target = samplesOf(buildG2Gnurbs(truth), 8, 3);
  GnurbsFitOptions o;
  o.iterations = 2;
  const GnurbsFitResult r = fitGnurbs(truth, target, o);
  EXPECT_LT(r.dMax, 1e-10);
  EXPECT_LT((r.cage.vertices - truth.vertices).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_THROW(fitGnurbs(truth, Eigen::MatrixX3d(0, 3)), Error);
  Eigen::MatrixX3d bad = target;
  bad(3, 1) = std::nan("");
  EXPECT_THROW(fitGnurbs(truth, bad), Error);
  EXPECT_THROW(fitGnurbs(truth, Eigen::MatrixX3d::Ones(5, 3)), Error);  // all points alike
}
