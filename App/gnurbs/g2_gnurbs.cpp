#include "gnurbs/g2_gnurbs.h"

#include <algorithm>
#include <map>
#include <memory>
#include <unordered_map>
#include <functional>
#include <numeric>
#include <set>
#include <tuple>

#include "fill/fairness_energy.h"
#include "geometry/bezier_patch.h"
#include "geometry/error.h"
#include "gnurbs/bezier_extraction.h"
#include "gnurbs/catmull_clark.h"
#include "gnurbs/spoke_conditions.h"

namespace holefill {

// Factorisations of the cluster problems met so far: M and H depend only on the
// cluster's topology and knot intervals (positions enter c and g), so EPs of one configuration
// repeated over a cage share one factorisation. Keyed by size and sums, confirmed bit for bit.
class SolverCacheImpl {
public:
  const StepwiseSolver& get(const StepwiseProblem& p, const StepwiseOptions& o) {
    std::size_t key = std::hash<double>()(p.M.sum()) ^ (std::hash<Eigen::Index>()(p.M.rows()) << 1) ^ (std::hash<Eigen::Index>()(p.M.cols()) << 2);
    for (const auto& h : p.H) key ^= std::hash<double>()(h.sum()) + 0x9e3779b9 + (key << 6) + (key >> 2);
    for (const auto& s : bucket_[key])
      if (s->matches(p)) return *s;
    bucket_[key].push_back(std::make_unique<StepwiseSolver>(p, o));
    return *bucket_[key].back();
  }

private:
  std::unordered_map<std::size_t, std::vector<std::unique_ptr<StepwiseSolver>>> bucket_;
};


namespace {

constexpr int kGrid = 11;              // coefficients per side of a face's 2×2 biquintic grid
constexpr int kFacePoints = kGrid * kGrid;

// Grid position (a along u, b along v) of each face corner.
constexpr int kCornerA[4] = {0, 10, 10, 0}, kCornerB[4] = {0, 0, 10, 10};

// Grid index of the point m steps from corner p towards adjacent corner q and n steps towards
// p's other neighbour.
int gridIndex(int p, int q, int m, int n) {
  const int r = (q == (p + 1) % 4) ? (p + 3) % 4 : (p + 1) % 4;
  const int a = kCornerA[p] + m * (kCornerA[q] - kCornerA[p]) / 10 + n * (kCornerA[r] - kCornerA[p]) / 10;
  const int b = kCornerB[p] + m * (kCornerB[q] - kCornerB[p]) / 10 + n * (kCornerB[r] - kCornerB[p]) / 10;
  return a * kGrid + b;
}

int cornerOf(const QuadCage& cage, int f, int v) {
  for (int k = 0; k < 4; ++k)
    if (cage.quads(f, k) == v) return k;
  return -1;
}

// The guidance patch of an irregular face as its 11×11 grid: elevated to degree 5 and split at ½.
Eigen::MatrixX3d elevatedGrid(const BSplineSurface& bicubic) {
  const auto subs = splitBezier(elevateBezier(bicubic, 5, 5));
  Eigen::MatrixX3d g(kFacePoints, 3);
  for (int sub = 0; sub < 4; ++sub)
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        g.row((5 * (sub & 1) + i) * kGrid + 5 * (sub >> 1) + j) = subs[sub].poles.row(i * 6 + j);
  return g;
}

BSplineSurface subPatch(const Eigen::MatrixX3d& grid, int sub) {
  Eigen::MatrixX3d poles(36, 3);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) poles.row(i * 6 + j) = grid.row((5 * (sub & 1) + i) * kGrid + 5 * (sub >> 1) + j);
  return bezierPatch(5, 5, poles);
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

// Thin-plate energy of one 2×2 biquintic face over its grid (index a*11 + b).
const Eigen::MatrixXd& thinPlateOfFace() {
  static const Eigen::MatrixXd E = [] {
    const std::vector<double> knots = {0, 0, 0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1, 1, 1};
    return Eigen::MatrixXd(fairnessMatrix(5, knots, 5, knots, FairnessWeights{1.0, 0.0}));
  }();
  return E;
}

// One EP, or two joined by an edge, with its 1-ring faces: grids, variables, constraints and steps.
struct ClusterSolve {
  const QuadCage& cage;
  const CageTopology& topo;
  const GuidanceSurface& guidance;
  const G2GnurbsOptions& options;
  SolverCacheImpl& cache;
  const StepwiseSolver& solverFor(const StepwiseProblem& p) { return cache.get(p, options.solver); }
  std::vector<int> eps, faces;
  std::map<int, int> localFace;
  Eigen::MatrixX3d guide;  // per local face, 121 rows

  int gid(int lf, int index) const { return lf * kFacePoints + index; }
  bool isClusterEP(int v) const { return std::find(eps.begin(), eps.end(), v) != eps.end(); }

  // b and r at EP v: the eigen-polyhedron's b and connectionRho, also at a sharp EP, whose
  // smooth spokes keep the regular N-star's angle 2π/N (measured G² with darts and corners).
  std::pair<double, double> connectionAt(int v) const {
    const int n = topo.valence(v);
    return {eigenPolyhedronB(n), std::isnan(options.rho) || n == 3 ? connectionRho(n) : options.rho};
  }

  // Face-local ids of a spoke's rows: m along the spoke from v, n into face f.
  std::function<int(int, int)> spokeRows(int f, int v, int w) const {
    const int lf = localFace.at(f), p = cornerOf(cage, f, v), q = cornerOf(cage, f, w);
    return [this, lf, p, q](int m, int n) { return gid(lf, gridIndex(p, q, m, n)); };
  }

  void solve(std::vector<Eigen::MatrixX3d>& finalGrids, G2GnurbsResult& result) {
    const int nl = static_cast<int>(faces.size());
    guide.resize(nl * kFacePoints, 3);
    for (int lf = 0; lf < nl; ++lf) guide.middleRows(lf * kFacePoints, kFacePoints) = elevatedGrid(guidance.patches[faces[lf]]);

    // Spokes: merge the shared boundary rows and collect the G² conditions (once per edge).
    UnionFind uf(nl * kFacePoints);
    std::vector<GridCondition> conditions;
    std::set<std::uint64_t> done;
    std::vector<int> creaseRow;  // grid points on sharp spokes, fixed to the guidance
    for (int v : eps) {
      const auto& fan = topo.facesAround(v);
      const auto& sp = topo.spokes(v);
      const int n = static_cast<int>(sp.size());
      for (int i = 0; i < n; ++i) {
        const int w = sp[i], fa = fan[i].face, fb = fan[(i + n - 1) % n].face;
        const auto A = spokeRows(fa, v, w), B = spokeRows(fb, v, w);
        for (int m = 0; m < kGrid; ++m) uf.join(A(m, 0), B(m, 0));
        if (cage.isSharp(v, w)) {
          // A crease: C0 only. Its curve is the guidance's, which ends at the EP (the extraction
          // makes a sharp EP a corner of its creases), but for its first Bézier point: when
          // the creases split the EP evenly, the smooth spokes' G1 conditions force the two crease
          // tangents to be opposite and of equal knot-scaled length, which the guidance's are
          // not (measured infeasibility 1.6e-2 with the whole curve fixed; a crease run smoothly
          // through the EP was as infeasible, and left free the crease tangents collapsed to 0).
          for (int m = 0; m < kGrid; ++m)
            if (m != 1) creaseRow.push_back(A(m, 0));
          continue;
        }
        if (!done.insert(QuadCage::edgeKey(v, w)).second) continue;
        SpokeConnection k;
        k.dS = cage.knot(v, w);
        k.dA = cage.knot(v, sp[(i + 1) % n]);
        k.dB = cage.knot(v, sp[(i + n - 1) % n]);
        std::tie(k.b0, k.r) = connectionAt(v);
        if (isClusterEP(w)) {
          k.epAtBothEnds = true;
          std::tie(k.b1, k.r1) = connectionAt(w);
        }
        appendSpokeConditions(k, A, B, conditions);
      }
    }
    // C² between each face's sub-patches, across u = ½ and v = ½.
    for (int lf = 0; lf < nl; ++lf)
      for (int line = 0; line < kGrid; ++line)
        for (int dir = 0; dir < 2; ++dir) {
          auto at = [&](int k) { return gid(lf, dir == 0 ? k * kGrid + line : line * kGrid + k); };
          conditions.push_back({{{at(3), 1}, {at(4), -2}, {at(6), 2}, {at(7), -1}}});
          conditions.push_back({{{at(4), 1}, {at(5), -2}, {at(6), 1}}});
        }

    // Gray points (3 rows along each non-spoke edge) are fixed; step classes of the others.
    std::vector<int> step(nl * kFacePoints, 3);
    std::vector<bool> fixed(nl * kFacePoints, false);
    for (int lf = 0; lf < nl; ++lf) {
      const int f = faces[lf];
      for (int k = 0; k < 4; ++k) {
        const int p = cage.quads(f, k), q = cage.quads(f, (k + 1) % 4);
        if (isClusterEP(p) || isClusterEP(q)) continue;
        for (int m = 0; m < kGrid; ++m)
          for (int n = 0; n < 3; ++n) fixed[gid(lf, gridIndex(k, (k + 1) % 4, m, n))] = true;
      }
      for (int p = 0; p < 4; ++p) {
        if (!isClusterEP(cage.quads(f, p))) continue;
        for (int q : {(p + 1) % 4, (p + 3) % 4})
          for (int m = 0; m < kGrid; ++m)
            for (int n = 0; n < 3; ++n) {
              const int s = (m <= 5 && (n <= 1 || m <= 2)) ? 0 : (m <= 5 ? 2 : (m <= 7 ? 1 : 3));
              int& cur = step[gid(lf, gridIndex(p, q, m, n))];
              cur = std::min(cur, s);
            }
      }
    }
    for (int g : creaseRow) fixed[g] = true;
    // An anchored EP is where its anchor puts it (sec. 5.1), fixed like the crease rows.
    for (int v : eps)
      if (cage.anchors.count(v)) {
        const auto& c = topo.facesAround(v)[0];
        fixed[gid(localFace.at(c.face), gridIndex(c.corner, (c.corner + 1) % 4, 0, 0))] = true;
      }
    // Variables: one per merged class that has no fixed member.
    std::vector<int> var(nl * kFacePoints, -1);
    std::map<int, int> classStep;
    std::map<int, bool> classFixed;
    for (int g = 0; g < nl * kFacePoints; ++g) {
      const int root = uf.find(g);
      auto [it, fresh] = classStep.emplace(root, step[g]);
      if (!fresh) it->second = std::min(it->second, step[g]);
      classFixed[root] = classFixed[root] || fixed[g];
    }
    int nv = 0;
    std::map<int, int> rootVar;
    std::vector<std::vector<int>> steps(4);
    for (const auto& [root, s] : classStep)
      if (!classFixed[root]) {
        rootVar[root] = nv;
        steps[s].push_back(nv++);
      }
    for (int g = 0; g < nl * kFacePoints; ++g) {
      const auto it = rootVar.find(uf.find(g));
      var[g] = it == rootVar.end() ? -1 : it->second;
    }
    // A fixed class takes the guidance value of a fixed member (all of them agree: C0 guidance).
    std::vector<int> fixedSource(nl * kFacePoints, -1);
    for (int g = 0; g < nl * kFacePoints; ++g)
      if (fixed[g]) fixedSource[uf.find(g)] = g;
    auto fixedValue = [&](int g) { return Eigen::RowVector3d(guide.row(fixedSource[uf.find(g)])); };

    StepwiseProblem prob;
    prob.M = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(conditions.size()), nv);
    prob.c = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(conditions.size()), 3);
    for (size_t r = 0; r < conditions.size(); ++r)
      for (const auto& [g, w] : conditions[r].terms) {
        if (var[g] >= 0) prob.M(r, var[g]) += w;
        else prob.c.row(r) -= w * fixedValue(g);
      }
    const Eigen::MatrixXd& E = thinPlateOfFace();
    if (options.solve == G2GnurbsOptions::Solve::Fair) {
      // One step: the thin-plate energy of the change from the guidance, over every face, plus
      // a small pull to the guidance's values (the energy ignores affine changes).
      prob.steps = {{}};
      for (int v = 0; v < nv; ++v) prob.steps[0].push_back(v);
      prob.H.assign(1, Eigen::MatrixXd::Zero(nv, nv));
      prob.g.assign(1, Eigen::MatrixXd::Zero(nv, 3));
      for (int lf = 0; lf < nl; ++lf)
        for (int i = 0; i < kFacePoints; ++i) {
          const int gi = gid(lf, i);
          if (var[gi] < 0) continue;
          prob.H[0](var[gi], var[gi]) += options.fairPull;
          prob.g[0].row(var[gi]) += options.fairPull * guide.row(gi);
          for (int j = 0; j < kFacePoints; ++j) {
            const int gj = gid(lf, j);
            prob.g[0].row(var[gi]) += E(i, j) * guide.row(gj);
            if (var[gj] >= 0) prob.H[0](var[gi], var[gj]) += E(i, j);
            else prob.g[0].row(var[gi]) -= E(i, j) * fixedValue(gj);
          }
        }
    } else {
      prob.steps = steps;
      prob.H.assign(4, Eigen::MatrixXd::Zero(nv, nv));
      prob.g.assign(4, Eigen::MatrixXd::Zero(nv, 3));
      // ½‖Σ c_k y_k − target‖² into a step's objective; fixed y_k move to the target.
      auto addTerm = [&](int s, const std::vector<std::pair<int, double>>& terms, Eigen::RowVector3d target) {
        for (const auto& [g, w] : terms)
          if (var[g] < 0) target -= w * fixedValue(g);
        for (const auto& [gi, wi] : terms) {
          if (var[gi] < 0) continue;
          prob.g[s].row(var[gi]) += wi * target;
          for (const auto& [gj, wj] : terms)
            if (var[gj] >= 0) prob.H[s](var[gi], var[gj]) += wi * wj;
        }
      };
      auto stepOfGid = [&](int g) { return var[g] < 0 ? -1 : classStep[uf.find(g)]; };
      for (int lf = 0; lf < nl; ++lf)
        for (int a = 0; a < kGrid; ++a)
          for (int b = 0; b < kGrid; ++b) {
            const int g = gid(lf, a * kGrid + b), s = stepOfGid(g);
            if (s < 0 || s == 3) continue;
            addTerm(s, {{g, 1.0}}, guide.row(g));  // eq. (21): values …
            for (const int h : {a + 1 < kGrid ? gid(lf, (a + 1) * kGrid + b) : -1, b + 1 < kGrid ? gid(lf, a * kGrid + b + 1) : -1,
                                a > 0 ? gid(lf, (a - 1) * kGrid + b) : -1, b > 0 ? gid(lf, a * kGrid + b - 1) : -1}) {
              // … and differences to grid neighbours that are fixed or solved no later.
              if (h < 0 || stepOfGid(h) > s || (stepOfGid(h) == s && h < g)) continue;
              addTerm(s, {{g, 1.0}, {h, -1.0}}, guide.row(g) - guide.row(h));
            }
          }
      for (int lf = 0; lf < nl; ++lf)  // step 4: the paper's thin-plate energy of the surface itself
        for (int i = 0; i < kFacePoints; ++i) {
          const int gi = gid(lf, i);
          if (var[gi] < 0) continue;
          for (int j = 0; j < kFacePoints; ++j) {
            const int gj = gid(lf, j);
            if (var[gj] >= 0) prob.H[3](var[gi], var[gj]) += E(i, j);
            else prob.g[3].row(var[gi]) -= E(i, j) * fixedValue(gj);
          }
        }
    }
    const StepwiseResult sol = solverFor(prob).solve(prob.c, prob.g);
    const double size = std::max(1.0, guide.cwiseAbs().maxCoeff());
    if (sol.stepInfeasibility > 1e-9 * size) {
      std::string who;
      for (int v : eps) who += (who.empty() ? "" : " and ") + std::to_string(v + cage.numberBase);
      result.warnings.push_back("extraordinary point " + who + ": the G² conditions are met only to " + std::to_string(sol.stepInfeasibility) +
                                " (knot intervals that differ between its spokes make the guidance surface non-C² at the spokes' far ends)");
    }
    result.constraintResidual = std::max(result.constraintResidual, sol.constraintResidual);
    result.infeasibility = std::max(result.infeasibility, sol.stepInfeasibility);
    for (int lf = 0; lf < nl; ++lf) {
      Eigen::MatrixX3d& out = finalGrids[faces[lf]];
      out.resize(kFacePoints, 3);
      for (int i = 0; i < kFacePoints; ++i) {
        const int g = gid(lf, i);
        out.row(i) = var[g] >= 0 ? Eigen::RowVector3d(sol.x.row(var[g])) : fixedValue(g);
      }
    }
  }
};

}  // namespace

namespace {

// Why the cage needs a Catmull–Clark step before the construction, or "" when it does not:
// EPs too close (a face holding EPs that share no edge, three EPs joined by edges), or a sharp
// edge touching an EP's 1-ring elsewhere than at the EP (its crease would break the guidance's
// C² where the 1-ring's border rows are taken from it; measured G1 0.3 rad on the spokes).
std::string refinementNeed(const QuadCage& cage, const CageTopology& topo) {
  std::vector<bool> isEP(topo.vertexCount(), false);
  for (int v : topo.extraordinaryPoints()) isEP[v] = true;
  for (int v : topo.extraordinaryPoints()) {
    const auto& sp = topo.spokes(v);
    for (size_t i = 0; i < sp.size(); ++i)
      for (size_t j = i + 1; j < sp.size(); ++j)
        if (isEP[sp[i]] && isEP[sp[j]])
          return "extraordinary points " + std::to_string(sp[i] + cage.numberBase) + ", " + std::to_string(v + cage.numberBase) + " and " +
                 std::to_string(sp[j] + cage.numberBase) +
                 " form a chain joined by edges";
  }
  for (int f = 0; f < topo.faceCount(); ++f)
    for (int k = 0; k < 2; ++k)
      if (isEP[cage.quads(f, k)] && isEP[cage.quads(f, k + 2)])
        return cage.quadName(f) + " holds extraordinary points " + std::to_string(cage.quads(f, k) + cage.numberBase) + " and " +
               std::to_string(cage.quads(f, k + 2) + cage.numberBase) + ", which share no edge";
  // A crease through an EP (its sharp spokes, and their continuations beyond the spokes' ends)
  // is the sharp-EP case the construction handles; other creases must keep off the 1-ring.
  for (std::uint64_t key : cage.sharp) {
    const int a = static_cast<int>(key & 0xffffffffu), b = static_cast<int>(key >> 32);
    for (int end : {a, b})
      for (const auto& c : topo.facesAround(end))
        for (int k = 0; k < 4; ++k) {
          const int v = cage.quads(c.face, k);
          if (isEP[v] && v != a && v != b && !cage.isSharp(v, a) && !cage.isSharp(v, b))
            return "sharp " + cage.edgeName(a, b) + " touches the 1-ring of extraordinary point " + std::to_string(v + cage.numberBase);
        }
  }
  return "";
}

// Where creases leave the surface short of G1 around a regular vertex inside the cage: a dart (one
// sharp edge ends there; the extraction interpolates the vertex, so only C0 around it) and a
// turn (two sharp edges not opposite in the fan: the faces on the outer side meet a corner of
// the crease that no bicubic B-spline rule makes smooth; measured G1 9e-3 rad there).
std::vector<std::string> creaseWarnings(const QuadCage& cage, const CageTopology& topo) {
  std::vector<std::string> out;
  for (int v = 0; v < topo.vertexCount(); ++v) {
    if (topo.onBoundary(v) || topo.isExtraordinary(v)) continue;  // creases at EPs: connectionAt
    const auto& sp = topo.spokes(v);
    std::vector<int> at;
    for (int i = 0; i < static_cast<int>(sp.size()); ++i)
      if (cage.isSharp(v, sp[i])) at.push_back(i);
    if (at.size() == 1)
      out.push_back("a sharp edge ends inside the cage at " + cage.vertexName(v) +
                    " (a dart): the surface is only C0 around that vertex; end creases at the cage boundary or at other creases");
    else if (at.size() == 2 && 2 * (at[1] - at[0]) != static_cast<int>(sp.size()))
      out.push_back("the crease turns at " + cage.vertexName(v) +
                    ": the faces on its outer side meet only about G1 there (1e-2 rad); run creases straight through regular vertices");
  }
  return out;
}

}  // namespace

struct G2GnurbsBuilder::Cache : SolverCacheImpl {};

G2GnurbsBuilder::G2GnurbsBuilder(const G2GnurbsOptions& options) : options_(options), cache_(std::make_unique<Cache>()) {}
G2GnurbsBuilder::~G2GnurbsBuilder() = default;

G2GnurbsResult buildG2Gnurbs(const QuadCage& input, const G2GnurbsOptions& options) { return G2GnurbsBuilder(options).build(input); }

G2GnurbsResult G2GnurbsBuilder::build(const QuadCage& input) {
  const G2GnurbsOptions& options = options_;
  G2GnurbsResult result;
  result.cage = input;
  if (options.maxValence > 0) {
    const CageTopology topo(input);
    for (int v : topo.extraordinaryPoints())
      if (topo.valence(v) > options.maxValence)
        throw Error("vertex " + std::to_string(v + 1) + " has valence " + std::to_string(topo.valence(v)) + ", above the limit of " +
                    std::to_string(options.maxValence) + " (its solve grows as the valence to the 3.5th power: split it, or raise the limit)");
  }
  for (;;) {
    const std::string why = refinementNeed(result.cage, CageTopology(result.cage));
    if (why.empty()) break;
    // One step always suffices: afterwards every EP is an original vertex two edges from any
    // other, and the children of a sharp edge are two edges from every EP's new 1-ring.
    if (!options.refineWhenNeeded || result.refinements > 0)
      throw Error(why + "; refine the cage (one Catmull-Clark step) first");
    result.cage = catmullClarkStep(result.cage, CageTopology(result.cage));
    ++result.refinements;
    result.refinementReason = why;
  }
  const QuadCage& cage = result.cage;
  const CageTopology topo(cage);
  const GuidanceSurface guidance = extractGuidanceSurface(cage, topo);
  result.extraordinaryPoints = topo.extraordinaryPoints();
  const auto& eps = result.extraordinaryPoints;
  const int nf = topo.faceCount();
  std::vector<bool> isEP(topo.vertexCount(), false);
  for (int v : eps) isEP[v] = true;

  for (std::string& w : creaseWarnings(cage, topo)) result.warnings.push_back(std::move(w));
  // Clusters: single EPs and pairs joined by an edge (refinementNeed ruled out the rest).
  UnionFind uf(topo.vertexCount());
  for (int v : eps)
    for (int w : topo.spokes(v))
      if (isEP[w]) uf.join(v, w);
  std::map<int, std::vector<int>> clusterEPs;
  for (int v : eps) clusterEPs[uf.find(v)].push_back(v);
  std::vector<int> faceCluster(nf, -1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k)
      if (isEP[cage.quads(f, k)]) faceCluster[f] = uf.find(cage.quads(f, k));

  std::vector<Eigen::MatrixX3d> grids(nf);
  for (const auto& [root, members] : clusterEPs) {
    ClusterSolve cs{cage, topo, guidance, options, *cache_, members, {}, {}, {}};
    for (int v : members)
      for (const auto& c : topo.facesAround(v))
        if (cs.localFace.emplace(c.face, static_cast<int>(cs.faces.size())).second) cs.faces.push_back(c.face);
    cs.solve(grids, result);
    ++result.clusters;
  }
  for (int f = 0; f < nf; ++f) {
    if (faceCluster[f] < 0) {
      result.patches.push_back({f, -1, guidance.patches[f]});
      continue;
    }
    ++result.irregularFaces;
    for (int sub = 0; sub < 4; ++sub) result.patches.push_back({f, sub, subPatch(grids[f], sub)});
  }
  return result;
}

FaceJetFunction faceJets(const G2GnurbsResult& result) {
  std::vector<int> first;
  for (size_t i = 0; i < result.patches.size(); ++i) {
    const int f = result.patches[i].face;
    if (f >= static_cast<int>(first.size())) first.resize(f + 1, -1);
    if (first[f] < 0) first[f] = static_cast<int>(i);
  }
  return [&result, first](int f, double u, double v) {
    const GnurbsPatch& head = result.patches[first.at(f)];
    double scale = 1;
    const BSplineSurface* s = &head.surface;
    if (head.sub >= 0) {  // sub-patches: pick the quarter, map to its [0,1]², chain-rule factor 2 per derivative
      const int su = u > 0.5 ? 1 : 0, sv = v > 0.5 ? 1 : 0;
      s = &result.patches[first[f] + 2 * sv + su].surface;
      u = 2 * u - su;
      v = 2 * v - sv;
      scale = 2;
    }
    const auto d = s->derivatives(u, v, 2);
    return SurfaceJet{d[0][0], scale * d[1][0], scale * d[0][1], scale * scale * d[2][0], scale * scale * d[1][1], scale * scale * d[0][2]};
  };
}

}  // namespace holefill
