#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "geometry/error.h"
#include "gnurbs/bezier_extraction.h"
#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/patch_continuity.h"
#include "test_cages.h"

using namespace holefill;
using namespace holefill::testcages;

namespace {

struct Worst {
  double g0 = 0, g1 = 0, g2 = 0;
  int singular = 0;  // samples without a normal: a degenerate EP would hide there
};
// Over the cage the patches are built on (r.cage: the input or its refinement); separately on
// edges at EPs when asked.
Worst worstContinuity(const G2GnurbsResult& r, bool nearEPOnly = false) {
  Worst w;
  for (const auto& e : cageEdgeContinuity(r.cage, CageTopology(r.cage), faceJets(r), 21, diagonal(r.cage))) {
    if (nearEPOnly && !e.nearEP) continue;
    w.g0 = std::max(w.g0, e.g0);
    w.g1 = std::max(w.g1, e.g1);
    w.g2 = std::max(w.g2, e.g2);
    w.singular += e.singularSamples;
  }
  return w;
}

// The EP keeps a tangent plane: the first derivatives of all faces there span two dimensions.
// σ₂/σ₁ of the 3×2N matrix they form must stay above minRatio × the guidance surface's (the
// cage's own anisotropy); a rank-1 tangent star, which passes the G1/G2 measure everywhere but
// at the EP itself, gives 0.
void expectTangentPlaneAt(const G2GnurbsResult& r, int v, double minRatio = 0.9) {
  const auto jet = faceJets(r);
  const CageTopology topo(r.cage);
  const GuidanceSurface guidance = extractGuidanceSurface(r.cage, topo);
  const auto& fan = topo.facesAround(v);
  Eigen::Matrix3Xd ours(3, 2 * fan.size()), guide(3, 2 * fan.size());
  for (size_t i = 0; i < fan.size(); ++i) {
    const int c = fan[i].corner;
    const double u = c == 1 || c == 2 ? 1 : 0, w = c >= 2 ? 1 : 0;
    const SurfaceJet j = jet(fan[i].face, u, w);
    const auto d = guidance.patches[fan[i].face].derivatives(u, w, 1);
    ours.col(2 * i) = j.su;
    ours.col(2 * i + 1) = j.sv;
    guide.col(2 * i) = d[1][0];
    guide.col(2 * i + 1) = d[0][1];
  }
  const Eigen::Vector3d so = Eigen::JacobiSVD<Eigen::Matrix3Xd>(ours).singularValues();
  const Eigen::Vector3d sg = Eigen::JacobiSVD<Eigen::Matrix3Xd>(guide).singularValues();
  std::printf("  EP %d: tangent star sigma2/sigma1 %.3f, guidance %.3f (sigma3/sigma1 %.3f)\n", v, so(1) / so(0), sg(1) / sg(0), sg(2) / sg(0));
  EXPECT_GT(so(1) / so(0), minRatio * sg(1) / sg(0)) << "EP " << v;
  EXPECT_LT(so(2) / so(0), 1e-10) << "EP " << v;  // and only two: G1 at the EP
}

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
    int singular = 0;
    for (const auto& e : edges) {
      singular += e.singularSamples;
      g0 = std::max(g0, e.g0);
      (e.nearEP ? g1Spoke : g1) = std::max(e.nearEP ? g1Spoke : g1, e.g1);
      (e.nearEP ? g2Spoke : g2) = std::max(e.nearEP ? g2Spoke : g2, e.g2);
    }
    std::printf("valence %d: residual %.2e  G0 %.2e  spokes G1 %.2e G2 %.2e  elsewhere G1 %.2e G2 %.2e\n", n, r.constraintResidual, g0,
                g1Spoke, g2Spoke, g1, g2);
    EXPECT_EQ(singular, 0);
    expectTangentPlaneAt(r, 0);
    EXPECT_LT(g0, 1e-12);
    EXPECT_LT(g1Spoke, 1e-8);
    EXPECT_LT(g2Spoke, 1e-6);
    EXPECT_LT(g1, 1e-8);
    EXPECT_LT(g2, 1e-6);
  }
}


TEST(G2Gnurbs, NonUniformKnotIntervalsAndEPsNearTheBoundaryStayG2) {
  // Valence 5 and 6 with a knot interval sequence per spoke line (edges parallel to a spoke share
  // its intervals, as in a cage cut from NURBS) that differs from spoke to spoke beyond the
  // 1-ring, the spokes' own first intervals equal (see G2GnurbsResult::warnings); and EPs whose
  // 1-ring reaches the cage boundary (k = 2, 1).
  struct Case {
    int n, k;
    bool nonUniform;
  };
  for (const Case c : {Case{5, 4, true}, Case{6, 3, true}, Case{5, 2, false}, Case{6, 1, false}}) {
    SCOPED_TRACE("valence " + std::to_string(c.n) + ", k " + std::to_string(c.k) + (c.nonUniform ? ", non-uniform" : ""));
    const auto interval = [&](int spoke, int j) { return c.nonUniform && j > 0 ? (1 + 0.6 * spoke / c.n) * (1 + 0.25 * j) : 1.0; };
    const QuadCage cage = polarCage(c.n, c.k, interval);
    const G2GnurbsResult r = buildG2Gnurbs(cage);
    const Worst w = worstContinuity(r);
    std::printf("valence %d k %d%s: infeasibility %.1e  G0 %.1e G1 %.1e G2 %.1e\n", c.n, c.k, c.nonUniform ? " non-uniform" : "",
                r.infeasibility, w.g0, w.g1, w.g2);
    EXPECT_LT(r.infeasibility, 1e-10);
    EXPECT_LT(w.g0, 1e-12);
    EXPECT_LT(w.g1, 1e-8);
    EXPECT_LT(w.g2, 1e-6);
  }
}

TEST(G2Gnurbs, RegularCageIsTheBicubicSplineAndSymmetricCagesGiveSymmetricSurfaces) {
  const QuadCage regular = polarCage(4, 3);
  const G2GnurbsResult r = buildG2Gnurbs(regular);
  EXPECT_TRUE(r.extraordinaryPoints.empty());
  EXPECT_EQ(r.irregularFaces, 0);
  ASSERT_EQ(r.patches.size(), static_cast<size_t>(regular.quads.rows()));
  for (const auto& p : r.patches) EXPECT_EQ(p.sub, -1);
  const Worst w = worstContinuity(r);
  EXPECT_LT(w.g1, 1e-12);
  EXPECT_LT(w.g2, 1e-10);

  // A cage symmetric under rotation by 2π/n about z: the surface must map onto itself.
  for (int n : {3, 5, 6}) {
    SCOPED_TRACE("valence " + std::to_string(n));
    QuadCage cage = polarCage(n, 3);
    for (int v = 0; v < cage.vertices.rows(); ++v) {
      const double rr = cage.vertices.row(v).head<2>().squaredNorm();
      cage.vertices(v, 2) = 0.3 * std::cos(0.4 * rr) + 0.02 * rr;
    }
    const G2GnurbsResult s = buildG2Gnurbs(cage);
    const auto jet = faceJets(s);
    const double a = 2 * M_PI / n;
    Eigen::Matrix3d R;
    R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    double worst = 0, moved = 0;
    for (int f = 0; f < 9; ++f)  // sector 0's faces against sector 1's
      for (double u : {0.0, 0.1, 0.37, 0.5, 0.8, 1.0})
        for (double v : {0.0, 0.05, 0.5, 0.66, 1.0}) {
          const Eigen::Vector3d p = jet(f, u, v).p, q = jet(f + 9, u, v).p;
          worst = std::max(worst, (R * p - q).norm());
          moved = std::max(moved, (p - q).norm());
        }
    EXPECT_LT(worst, 1e-7);  // measured 3.8e-8 at most (valence 3, 5, 6): round-off of the solves
    EXPECT_GT(moved, 0.5);  // the comparison is between different places
  }
}


TEST(G2Gnurbs, CreasesThroughEPsStayC0AndEverythingElseG2) {
  // A dart (one sharp spoke), a crease through the EP with 2 and 3 faces on its sides, a corner
  // of three creases: every non-sharp edge G², each sharp edge exactly the guidance's crease.
  struct Case {
    int n;
    std::vector<int> spokes;
  };
  for (const Case& c : {Case{5, {0}}, Case{5, {0, 2}}, Case{6, {0, 3}}, Case{8, {0, 4}}, Case{6, {0, 2, 4}}, Case{3, {0, 1}},
                        Case{5, {0, 1, 2, 3, 4}}}) {
    std::string name = "valence " + std::to_string(c.n) + ", sharp spokes";
    for (int s : c.spokes) name += " " + std::to_string(s);
    SCOPED_TRACE(name);
    QuadCage cage = polarCage(c.n, 3);
    for (int s : c.spokes) cages::setSharpSpokeLine(cage, 3, s);
    const G2GnurbsResult r = buildG2Gnurbs(cage);
    EXPECT_EQ(r.refinements, 0);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    double g1 = 0, g2 = 0, creaseAngle = 0;
    int sharp = 0, singular = 0;
    for (const auto& e : cageEdgeContinuity(r.cage, CageTopology(r.cage), faceJets(r), 21, diagonal(r.cage))) {
      singular += e.singularSamples;
      EXPECT_LT(e.g0, 1e-12);
      if (e.sharp) {
        ++sharp;
        creaseAngle = std::max(creaseAngle, e.g1);
        continue;
      }
      g1 = std::max(g1, e.g1);
      g2 = std::max(g2, e.g2);
    }
    std::printf("%s: smooth edges G1 %.1e G2 %.1e; largest normal jump across a crease %.2f rad\n", name.c_str(), g1, g2, creaseAngle);
    EXPECT_EQ(sharp, 3 * static_cast<int>(c.spokes.size()));
    EXPECT_EQ(singular, 0);
    // No tangent collapses at the EP: every face's derivatives there keep at least a fifth of
    // the guidance's length (a zero crease tangent passes the G1 measure everywhere else).
    const CageTopology topo(r.cage);
    const GuidanceSurface guidance = extractGuidanceSurface(r.cage, topo);
    double shortest = 1e9;
    for (const auto& corner : topo.facesAround(0)) {
      const double u = corner.corner == 1 || corner.corner == 2 ? 1 : 0, w = corner.corner >= 2 ? 1 : 0;
      const SurfaceJet j = faceJets(r)(corner.face, u, w);
      const auto d = guidance.patches[corner.face].derivatives(u, w, 1);
      shortest = std::min({shortest, j.su.norm() / d[1][0].norm(), j.sv.norm() / d[0][1].norm()});
    }
    EXPECT_GT(shortest, 0.2);
    EXPECT_LT(g1, 1e-8);
    EXPECT_LT(g2, 1e-6);
  }
}

TEST(G2Gnurbs, AnAnchorPlacesItsSharpEPAndChangesOnlyTheEPsNeighbourhood) {
  QuadCage cage = polarCage(5, 3);
  cages::setSharpSpokeLine(cage, 3, 0);
  cages::setSharpSpokeLine(cage, 3, 2);
  const G2GnurbsResult plain = buildG2Gnurbs(cage);
  cage.anchors[0] = Eigen::Vector3d(0.1, -0.05, 0.9);  // pull the sharp EP up: a peak
  const G2GnurbsResult anchored = buildG2Gnurbs(cage);
  const auto jet = faceJets(anchored);
  EXPECT_LT((jet(0, 0, 0).p - cage.anchors[0]).norm(), 1e-12);  // face 0's corner 0 is the EP
  EXPECT_LT(worstContinuity(anchored).g0, 1e-12);
  ASSERT_EQ(plain.patches.size(), anchored.patches.size());
  int changed = 0;
  for (size_t i = 0; i < plain.patches.size(); ++i) {
    const double d = (plain.patches[i].surface.poles - anchored.patches[i].surface.poles).cwiseAbs().maxCoeff();
    const bool inRing = plain.patches[i].sub >= 0;
    if (!inRing) EXPECT_EQ(d, 0.0) << "patch " << i << " of face " << plain.patches[i].face << " is outside the 1-ring";
    changed += d > 1e-3;
  }
  EXPECT_GT(changed, 10);  // the 1-ring moved
  QuadCage regularAnchor = polarCage(5, 3);
  regularAnchor.anchors[1] = Eigen::Vector3d(0, 0, 1);  // vertex 1 is regular (a spoke vertex)
  EXPECT_THROW(buildG2Gnurbs(regularAnchor), Error);
}

TEST(G2Gnurbs, TwoAdjacentEPsAreG2AcrossEveryEdge) {
  // Eq. (16): β linear along the shared spoke, b₀ and b₁ from each end's valence.
  for (const auto [nA, nB] : std::vector<std::pair<int, int>>{{3, 5}, {5, 5}, {5, 6}, {3, 6}, {3, 3}, {6, 8}}) {
    SCOPED_TRACE("valences " + std::to_string(nA) + " and " + std::to_string(nB));
    const QuadCage cage = edgeStarCage(nA, nB, 3);
    const G2GnurbsResult r = buildG2Gnurbs(cage);
    ASSERT_EQ(r.extraordinaryPoints, (std::vector<int>{0, 1}));
    EXPECT_EQ(r.clusters, 1);
    EXPECT_EQ(r.irregularFaces, nA + nB - 2);
    EXPECT_EQ(r.refinements, 0);
    const Worst w = worstContinuity(r), atEP = worstContinuity(r, true);
    std::printf("valences %d+%d: residual %.1e infeasibility %.1e  G0 %.1e  at EPs G1 %.1e G2 %.1e  all G1 %.1e G2 %.1e\n", nA, nB,
                r.constraintResidual, r.infeasibility, w.g0, atEP.g1, atEP.g2, w.g1, w.g2);
    EXPECT_LT(r.infeasibility, 1e-10);
    EXPECT_LT(w.g0, 1e-12);
    EXPECT_LT(w.g1, 1e-8);
    EXPECT_LT(w.g2, 1e-6);
    EXPECT_EQ(w.singular, 0);
    // Measured 0.60 (the valence-3 EP of 3+5) to 1.04 of the guidance's anisotropy.
    for (int v : {0, 1}) expectTangentPlaneAt(r, v, 0.5);
  }
}

TEST(G2Gnurbs, ClosedCubeIsRefinedOnceAndIsG2Everywhere) {
  const QuadCage cube = cubeCage();
  G2GnurbsOptions strict;
  strict.refineWhenNeeded = false;
  try {
    buildG2Gnurbs(cube, strict);
    ADD_FAILURE() << "a cage with chained EPs was accepted without refinement";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("Catmull-Clark"), std::string::npos) << e.what();
  }
  const G2GnurbsResult r = buildG2Gnurbs(cube);
  EXPECT_EQ(r.refinements, 1);
  EXPECT_NE(r.refinementReason.find("chain"), std::string::npos) << r.refinementReason;
  EXPECT_EQ(r.cage.quads.rows(), 24);
  EXPECT_EQ(r.extraordinaryPoints, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));  // the corners keep their numbers
  EXPECT_EQ(r.clusters, 8);
  EXPECT_EQ(r.irregularFaces, 24);  // every face is in one corner's 1-ring: nothing is left bicubic
  const Worst w = worstContinuity(r);
  std::printf("cube: residual %.1e  G0 %.1e G1 %.1e G2 %.1e\n", r.constraintResidual, w.g0, w.g1, w.g2);
  EXPECT_LT(w.g0, 1e-12);
  EXPECT_LT(w.g1, 1e-8);
  EXPECT_LT(w.g2, 1e-6);
  EXPECT_EQ(w.singular, 0);
  for (int v = 0; v < 8; ++v) expectTangentPlaneAt(r, v);
  // The cube's symmetry survives: every corner of the surface is as far from the centre.
  const auto jet = faceJets(r);
  std::vector<double> radii;
  for (int f = 0; f < 24; f += 4) radii.push_back(jet(f, 0, 0).p.norm());  // child 4f has the original corner at (0, 0)
  for (double rad : radii) EXPECT_NEAR(rad, radii[0], 1e-9);
  EXPECT_LT(radii[0], std::sqrt(3.0));  // and inside the cage's corner
}

TEST(G2Gnurbs, PlanarRegularCagesStayInjectiveAtEveryValence) {
  // The planar polar cage is the characteristic configuration: its surface must be an injective
  // planar map whose smallest corner angle is the regular star's, 2π/N. With the paper's r = 1
  // this folded at valence 7 and above (signed sin −1); see connectionRho.
  for (int n : {3, 5, 6, 7, 8, 9, 10, 12}) {
    for (int k : {2, 3}) {
      if (k == 3 && n > 8) continue;
      QuadCage cage = polarCage(n, k);
      cage.vertices.col(2).setZero();
      const G2GnurbsResult r = buildG2Gnurbs(cage);
      const auto jet = faceJets(r);
      double worst = 1;
      for (int f = 0; f < static_cast<int>(cage.quads.rows()); f += k * k)  // one sector: the rest are its rotations
        for (int g = f; g < f + k * k; ++g)
          for (int i = 0; i <= 30; ++i)
            for (int j = 0; j <= 30; ++j) {
              const SurfaceJet J = jet(g, i / 30.0, j / 30.0);
              worst = std::min(worst, J.su.cross(J.sv).z() / (J.su.norm() * J.sv.norm()));
            }
      std::printf("valence %d k %d: min signed sin %.4f (regular star %.4f)\n", n, k, worst, std::sin(2 * M_PI / n));
      EXPECT_GT(worst, 0.99 * std::sin(2 * M_PI / n)) << "valence " << n << " k " << k;
    }
  }
}

namespace {

// Largest |mean curvature| over the EP 1-ring faces (21×21 samples each).
double maxMeanCurvatureInRings(const G2GnurbsResult& r) {
  const auto jet = faceJets(r);
  std::vector<bool> ring(r.cage.quads.rows(), false);
  for (const auto& p : r.patches) ring[p.face] = ring[p.face] || p.sub >= 0;
  double worst = 0;
  for (int f = 0; f < static_cast<int>(ring.size()); ++f) {
    if (!ring[f]) continue;
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const SurfaceJet J = jet(f, i / 20.0, j / 20.0);
        Eigen::Vector3d n;
        if (!unitNormal(J, n)) continue;
        const double E = J.su.dot(J.su), F = J.su.dot(J.sv), G = J.sv.dot(J.sv);
        const double H = (E * J.svv.dot(n) - 2 * F * J.suv.dot(n) + G * J.suu.dot(n)) / (2 * (E * G - F * F));
        worst = std::max(worst, std::abs(H));
      }
  }
  return worst;
}

}  // namespace

TEST(G2Gnurbs, FairSolveKeepsCurvatureNearTheGuidanceAndStepwiseMeetsTheSameConditions) {
  G2GnurbsOptions stepwise;
  stepwise.solve = G2GnurbsOptions::Solve::Stepwise;
  for (int n : {5, 8}) {
    SCOPED_TRACE("valence " + std::to_string(n));
    const QuadCage cage = polarCage(n, 3);
    const G2GnurbsResult fair = buildG2Gnurbs(cage), paper = buildG2Gnurbs(cage, stepwise);
    const Worst wf = worstContinuity(fair), wp = worstContinuity(paper);
    const double hf = maxMeanCurvatureInRings(fair), hp = maxMeanCurvatureInRings(paper);
    std::printf("valence %d: max |H| in the 1-ring fair %.3f, stepwise %.3f; G2 fair %.1e stepwise %.1e\n", n, hf, hp, wf.g2, wp.g2);
    EXPECT_LT(wp.g1, 1e-8);
    EXPECT_LT(wp.g2, 1e-6);
    EXPECT_LT(wf.g2, 1e-6);
    EXPECT_LT(hf, 0.7 * hp);  // measured 0.27 against 0.48 (valence 5) and 0.39 against 1.03 (valence 8)
  }
  const G2GnurbsResult pair = buildG2Gnurbs(edgeStarCage(5, 6, 2), stepwise);
  EXPECT_LT(worstContinuity(pair).g2, 1e-6);
}
