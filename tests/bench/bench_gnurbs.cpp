// G² G-NURBS against OpenSubdiv's Catmull–Clark limit surface (Gregory end caps) on the same
// cages, in one run: continuity across every cage edge with the one measure both go through
// (cageEdgeContinuity: G1 normal angle, G2 relative curvature jump, near EPs and elsewhere),
// curvature near EPs, and build time. Prints a Markdown table; `scripts/bench.sh` runs it.
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/error.h"
#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/gnurbs_brep.h"
#include "gnurbs/gnurbs_fit.h"
#include "gnurbs/gnurbs_report.h"
#include "gnurbs/patch_continuity.h"
#include "gnurbs/sample_cages.h"

using namespace holefill;
using namespace OpenSubdiv;

namespace {

struct Point3 {
  double p[3] = {0, 0, 0};
  void Clear() { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Point3& s, double w) {
    for (int k = 0; k < 3; ++k) p[k] += w * s.p[k];
  }
};

// The Catmull–Clark limit surface of a cage by adaptive refinement to `isolation` with Gregory
// end caps; sharp cage edges are infinitely sharp creases, boundaries interpolated with corners.
struct OsdLimit {
  std::unique_ptr<Far::TopologyRefiner> refiner;
  std::unique_ptr<Far::PatchTable> patches;
  std::unique_ptr<Far::PatchMap> map;
  std::vector<Point3> points;

  OsdLimit(const QuadCage& cage, int isolation) {
    const int nv = static_cast<int>(cage.vertices.rows()), nf = static_cast<int>(cage.quads.rows());
    std::vector<int> perFace(nf, 4), indices(4 * nf), creasePairs;
    std::vector<float> creaseWeights;
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 4; ++k) indices[4 * f + k] = cage.quads(f, k);
    for (std::uint64_t key : cage.sharp) {
      creasePairs.push_back(static_cast<int>(key & 0xffffffffu));
      creasePairs.push_back(static_cast<int>(key >> 32));
      creaseWeights.push_back(Sdc::Crease::SHARPNESS_INFINITE);
    }
    Far::TopologyDescriptor d;
    d.numVertices = nv;
    d.numFaces = nf;
    d.numVertsPerFace = perFace.data();
    d.vertIndicesPerFace = indices.data();
    d.numCreases = static_cast<int>(creaseWeights.size());
    d.creaseVertexIndexPairs = creasePairs.data();
    d.creaseWeights = creaseWeights.data();
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    refiner.reset(Factory::Create(d, Factory::Options(Sdc::SCHEME_CATMARK, sdc)));
    if (!refiner) throw Error("OpenSubdiv refused the cage");
    refiner->RefineAdaptive(Far::TopologyRefiner::AdaptiveOptions(isolation));
    Far::PatchTableFactory::Options po(isolation);
    po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    po.SetPatchPrecision<double>();
    po.useInfSharpPatch = true;
    patches.reset(Far::PatchTableFactory::Create(*refiner, po));
    points.resize(refiner->GetNumVerticesTotal() + patches->GetNumLocalPoints());
    for (int v = 0; v < nv; ++v)
      for (int k = 0; k < 3; ++k) points[v].p[k] = cage.vertices(v, k);
    Far::PrimvarRefinerReal<double> pr(*refiner);
    Point3* src = points.data();
    for (int level = 1; level <= refiner->GetMaxLevel(); ++level) {
      Point3* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
      pr.Interpolate(level, src, dst);
      src = dst;
    }
    if (patches->GetNumLocalPoints() > 0)
      patches->GetLocalPointStencilTable<double>()->UpdateValues(points.data(), points.data() + refiner->GetNumVerticesTotal());
    map.reset(new Far::PatchMap(*patches));
  }

  SurfaceJet jet(int face, double u, double v) const {
    const Far::PatchTable::PatchHandle* h = map->FindPatch(face, u, v);
    if (!h) throw Error("OpenSubdiv has no patch at face " + std::to_string(face));
    double w[6][20];
    patches->EvaluateBasis(*h, u, v, w[0], w[1], w[2], w[3], w[4], w[5]);
    const auto cvs = patches->GetPatchVertices(*h);
    Eigen::Vector3d out[6];
    for (auto& o : out) o.setZero();
    for (int i = 0; i < cvs.size(); ++i) {
      const Eigen::Vector3d p(points[cvs[i]].p[0], points[cvs[i]].p[1], points[cvs[i]].p[2]);
      for (int k = 0; k < 6; ++k) out[k] += w[k][i] * p;
    }
    return SurfaceJet{out[0], out[1], out[2], out[3], out[4], out[5]};
  }
};

double seconds(const std::function<void()>& f, int repeats = 3) {
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// `copies` polar cages (k = 2) of valence 3, 5, 6, 8 in turn, side by side in one cage (separate
// components): the timing case of the issue (about 1,000 faces, 50 EPs). Only the cluster
// configurations matter for the cost (four here); positions differ from copy to copy.
QuadCage manyEPs(int copies) {
  QuadCage c;
  std::vector<QuadCage> parts;
  Eigen::Index nv = 0, nf = 0;
  for (int i = 0; i < copies; ++i) {
    QuadCage one = cages::polarCage(std::vector<int>{3, 5, 6, 8}[i % 4], 2);
    one.vertices.rowwise() += Eigen::RowVector3d(6.0 * (i % 10), 6.0 * (i / 10), 0);
    one.vertices.col(2) *= 1 + 0.1 * i;  // every copy its own shape
    nv += one.vertices.rows();
    nf += one.quads.rows();
    parts.push_back(one);
  }
  c.vertices.resize(nv, 3);
  c.quads.resize(nf, 4);
  Eigen::Index v = 0, f = 0;
  for (const QuadCage& one : parts) {
    c.vertices.middleRows(v, one.vertices.rows()) = one.vertices;
    c.quads.middleRows(f, one.quads.rows()) = one.quads.array() + static_cast<int>(v);
    v += one.vertices.rows();
    f += one.quads.rows();
  }
  return c;
}

bool nonUniform(const QuadCage& c) {
  for (const auto& [key, d] : c.knots)
    if (d != 1.0) return true;
  return false;
}

// Points (x, y, f(x, y)) over the footprint of the flat cage's surface (a 14×14 grid per patch).
Eigen::MatrixX3d targetOver(const QuadCage& cage, const std::function<double(double, double)>& f) {
  QuadCage flat = cage;
  flat.vertices.col(2).setZero();
  flat.anchors.clear();
  const G2GnurbsResult s = buildG2Gnurbs(flat);
  std::vector<Eigen::RowVector3d> pts;
  for (const auto& p : s.patches)
    for (int i = 0; i <= 13; ++i)
      for (int j = 0; j <= 13; ++j) {
        const Eigen::Vector3d q = p.surface.point(i / 13.0, j / 13.0);
        pts.emplace_back(q.x(), q.y(), f(q.x(), q.y()));
      }
  Eigen::MatrixX3d out(pts.size(), 3);
  for (size_t k = 0; k < pts.size(); ++k) out.row(k) = pts[k];
  return out;
}

void fittingTable() {
  struct Target {
    std::string name;
    QuadCage cage;
    std::function<double(double, double)> f;
  };
  std::vector<Target> targets;
  targets.push_back({"smooth: wave over a valence-5 cage", cages::polarCage(5, 3),
                     [](double x, double y) { return 0.3 * std::sin(0.6 * x) * std::cos(0.5 * y) + 0.02 * x * y; }});
  {
    QuadCage c = cages::polarCage(6, 3);
    for (int sp : {0, 3}) cages::setSharpSpokeLine(c, 3, sp);
    targets.push_back({"ridge through a valence-6 EP (creases on 2 spokes)", c,
                       [](double x, double y) { return 0.6 - 0.3 * std::abs(y) + 0.02 * x * x; }});
  }
  {
    QuadCage c = cages::polarCage(6, 3);
    for (int sp : {0, 2, 4}) cages::setSharpSpokeLine(c, 3, sp);
    targets.push_back({"three-sided corner at a valence-6 EP (creases on 3 spokes)", c, [](double x, double y) {
                         double m = -1e9;
                         for (double a : {M_PI / 3, M_PI, 5 * M_PI / 3}) m = std::max(m, std::cos(a) * x + std::sin(a) * y);
                         return 0.8 - 0.3 * m;
                       }});
  }
  std::printf("\n| target | points | anchors | d_max %% | d_avg %% | d_max %% sharp | d_avg %% sharp | rounds | time (s) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Target& t : targets) {
    const Eigen::MatrixX3d target = targetOver(t.cage, t.f);
    QuadCage start = t.cage;
    start.vertices.col(2).setZero();  // from the flat cage
    for (bool anchors : {false, true}) {
      if (anchors && t.cage.sharp.empty()) continue;
      QuadCage c = start;
      if (anchors) c.anchors[0] = c.vertices.row(0).transpose();
      GnurbsFitOptions o;
      o.iterations = 8;
      const GnurbsFitResult r = fitGnurbs(c, target, o);
      std::printf("| %s | %d | %s | %.4f | %.5f | %.4f | %.5f | %d | %.2f |\n", t.name.c_str(), static_cast<int>(target.rows()),
                  anchors ? "at the EP" : "none", 100 * r.dMax, 100 * r.dAvg, 100 * r.dMaxSharp, 100 * r.dAvgSharp, o.iterations, r.seconds);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  struct Case {
    std::string name;
    QuadCage cage;
  };
  std::vector<Case> cases;
  for (int n : {3, 5, 6, 8}) cases.push_back({"valence " + std::to_string(n), cages::polarCage(n, 4)});
  cases.push_back({"adjacent EPs 3+5", cages::edgeStarCage(3, 5, 3)});
  cases.push_back({"adjacent EPs 5+6", cages::edgeStarCage(5, 6, 3)});
  cases.push_back({"EP at the boundary (valence 5, 1 ring)", cages::polarCage(5, 1)});
  cases.push_back({"closed: cube", cages::cubeCage()});
  cases.push_back({"non-uniform knots (valence 5)", cages::polarCage(5, 4, [](int s, int j) { return j > 0 ? (1 + 0.6 * s / 5) * (1 + 0.25 * j) : 1.0; })});
  {
    // A straight crease from boundary to boundary through the first vertex out along spoke 0
    // (polarCage's numbering, k = 4): across the EP's 1-ring border.
    QuadCage c = cages::polarCage(6, 4);
    const std::vector<int> line = {28, 27, 26, 25, 1, 105, 109, 113, 117};
    for (size_t i = 0; i + 1 < line.size(); ++i) c.setSharp(line[i], line[i + 1]);
    cases.push_back({"crease across an EP's 1-ring (valence 6)", c});
  }
  {
    // Creases along spoke lines 0 and 2 from the cage boundary through the EP: a sharp EP.
    QuadCage c = cages::polarCage(5, 3);
    for (int sp : {0, 2}) cages::setSharpSpokeLine(c, 3, sp);
    cases.push_back({"crease through an EP (valence 5)", c});
    c.anchors[0] = Eigen::Vector3d(0, 0, 0.8);
    cases.push_back({"crease through an anchored EP (valence 5)", c});
  }
  {
    const QuadCage many = manyEPs(50);
    cases.push_back({"timing: 50 EPs of valence 3/5/6/8, " + std::to_string(many.quads.rows()) + " faces (50 separate cages)", many});
  }
  const int isolation = argc > 1 ? std::atoi(argv[1]) : 4;
  std::printf("| case | method | G1 at EPs (rad) | G2 at EPs | G1 elsewhere | G2 elsewhere | max curvature at EPs × diag | time (ms) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    try {
      G2GnurbsResult r;
      const double t = seconds([&] { r = buildG2Gnurbs(c.cage); });
      const GnurbsContinuity m = measureCageContinuity(r.cage, faceJets(r), 51);
      std::printf("| %s | HoleFill G² G-NURBS%s | %.1e | %.1e | %.1e | %.1e | %.3g | %.1f |\n", c.name.c_str(),
                  r.refinements ? " (refined once)" : "", m.g1Spokes, m.g2Spokes, m.g1Elsewhere, m.g2Elsewhere, m.maxCurvatureNearEPs, 1e3 * t);
    } catch (const Error& e) {
      std::printf("| %s | HoleFill G² G-NURBS | refused: %s | | | | | |\n", c.name.c_str(), e.what());
    }
    try {
      std::unique_ptr<OsdLimit> osd;
      const double t = seconds([&] { osd.reset(new OsdLimit(c.cage, isolation)); });
      const GnurbsContinuity m = measureCageContinuity(c.cage, [&](int f, double u, double v) { return osd->jet(f, u, v); }, 51);
      std::printf("| | OpenSubdiv limit, Gregory end caps, isolation %d%s | %.1e | %.1e | %.1e | %.1e | %.3g | %.1f |\n", isolation,
                  nonUniform(c.cage) ? " (ignores knot intervals)" : "", m.g1Spokes, m.g2Spokes, m.g1Elsewhere, m.g2Elsewhere, m.maxCurvatureNearEPs, 1e3 * t);
    } catch (const std::exception& e) {
      std::printf("| | OpenSubdiv | failed: %s | | | | | |\n", e.what());
    }
  }
  fittingTable();
  // Curvature next to high-valence EPs as OpenSubdiv isolates them further, against ours (which
  // has no isolation level).
  std::printf("\n| valence | HoleFill max curvature at EPs × diag |");
  for (int iso : {2, 4, 6, 8}) std::printf(" OpenSubdiv isolation %d |", iso);
  std::printf("\n|---|---|---|---|---|---|\n");
  for (int n : {5, 6, 8}) {
    const QuadCage cage = cages::polarCage(n, 4);
    const G2GnurbsResult r = buildG2Gnurbs(cage);
    std::printf("| %d | %.3g |", n, measureCageContinuity(r.cage, faceJets(r), 51).maxCurvatureNearEPs);
    for (int iso : {2, 4, 6, 8}) {
      const OsdLimit osd(cage, iso);
      std::printf(" %.3g |", measureCageContinuity(cage, [&](int f, double u, double v) { return osd.jet(f, u, v); }, 51).maxCurvatureNearEPs);
    }
    std::printf("\n");
  }
  return 0;
}
