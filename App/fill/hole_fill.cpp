#include "fill/hole_fill.h"

#include "learn/uvtran.h"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopExp.hxx>
#include <algorithm>
#include <Standard_Failure.hxx>
#include <chrono>
#include <optional>
#include <cmath>

#include "brep/face_building.h"
#include "brep/opening_loops.h"
#include "fill/bending_energy.h"
#include "fill/reachable_normals.h"
#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "geometry/polygon2d.h"
#include "geometry/surface_projection.h"
#include "geometry/tolerances.h"

namespace holefill {

std::string toString(FillStatus s) {
  switch (s) {
    case FillStatus::Ok: return "ok";
    case FillStatus::ToleranceNotMet: return "tolerance_not_met";
    case FillStatus::Failed: return "failed";
    case FillStatus::Cancelled: return "cancelled";
  }
  return "?";
}

std::string toString(FillStage s) {
  switch (s) {
    case FillStage::None: return "none";
    case FillStage::Detect: return "detect";
    case FillStage::Sample: return "sample";
    case FillStage::Parameterize: return "parameterize";
    case FillStage::Solve: return "solve";
    case FillStage::Build: return "build";
    case FillStage::Check: return "check";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string edgeList(const std::vector<int>& e) {
  std::string s;
  for (int i : e) s += (s.empty() ? "Edge" : ", Edge") + std::to_string(i);
  return s;
}

int statusRank(FillStatus s) { return s == FillStatus::Ok ? 0 : s == FillStatus::ToleranceNotMet ? 1 : 2; }

// What loop edge i is judged against. With opt.modelAccuracy no stricter than the model itself is
// there: G0 within the edge's own tolerance where that is the larger, G1 within the tolerance
// beyond the angle at which the neighbour meets the edge's curve (its g1Floor). `relaxed`: the
// edge passes only thanks to that.
struct EdgeAllowance {
  double g0, g1, g2;
  bool relaxed = false;
};

EdgeAllowance allowance(const HoleFillResult& r, const HoleFillOptions& opt, size_t i) {
  EdgeAllowance a{r.g0Tolerance, opt.angularTolerance, opt.curvatureTolerance};
  if (!opt.modelAccuracy || i >= r.report.edges.size() || i >= r.hole.edges.size()) return a;
  const EdgeContinuity& e = r.report.edges[i];
  a.g0 = std::max(a.g0, r.hole.edges[i].tolerance);
  a.g1 += e.g1Floor;
  a.relaxed = (e.g0 > r.g0Tolerance && e.g0 <= a.g0) ||
              (r.edgeRequests[i].asked >= Continuity::G1 && e.g1 > opt.angularTolerance && e.g1 <= a.g1);
  return a;
}

// The worst error of a fill's report relative to what each edge was asked and is allowed.
double reportRatio(const HoleFillResult& r, const HoleFillOptions& opt) {
  double w = 0;
  for (size_t i = 0; i < r.edgeRequests.size() && i < r.report.edges.size(); ++i) {
    const EdgeRequest& q = r.edgeRequests[i];
    const EdgeContinuity& e = r.report.edges[i];
    const EdgeAllowance a = allowance(r, opt, i);
    w = std::max(w, e.g0 / a.g0);
    if (q.asked >= Continuity::G1) w = std::max(w, e.g1 / a.g1);
    if (q.asked == Continuity::G2) w = std::max(w, e.g2 / a.g2);
  }
  return w;
}

// a better than b: a valid face, then a better status, then the smaller worst error ratio.
bool betterFill(const HoleFillResult& a, const HoleFillResult& b, const HoleFillOptions& opt) {
  const bool va = a.faceValid && a.shapeValid, vb = b.faceValid && b.shapeValid;
  if (va != vb) return va;
  if (statusRank(a.status) != statusRank(b.status)) return statusRank(a.status) < statusRank(b.status);
  return reportRatio(a, opt) < reportRatio(b, opt);
}

void classify(HoleFillResult& r, const HoleFillOptions& opt);

// Checks a built face (not yet sewn): validity of the face and of the neighbours whose edges
// received its pcurves, the continuity report, then classify.
void judge(HoleFillResult& r, const HoleFillOptions& opt, bool checkNeighbours) {
  r.faceValid = BRepCheck_Analyzer(r.face).IsValid();
  // The model is judged on what the fill changed: the new face and the neighbours whose edges
  // received its pcurves, each of them only if it was valid before (an imported model is often
  // invalid somewhere, which no fill can be blamed for, nor can it tell from a whole-model check).
  r.shapeValid = r.faceValid;
  std::vector<int> checked = r.invalidBefore;  // each neighbour once, and none that was invalid before
  if (checkNeighbours)
    for (const auto& he : r.hole.edges) {
      const int f = he.supportIndex;
      // 0: a support that is not a face of the model (fillAdjacentHoles' provisional face).
      if (f < 1 || std::find(checked.begin(), checked.end(), f) != checked.end()) continue;
      checked.push_back(f);
      if (!BRepCheck_Analyzer(he.support).IsValid()) {
        r.shapeValid = false;
        r.warnings.push_back("Face" + std::to_string(f) + " (a neighbour of the hole) is not valid after the fill (BRepCheck)");
      }
    }
  r.report = continuityReport(r.face, r.hole);
  classify(r, opt);
}

// From a judged face's validity and report: per-edge levels reached, status and message.
void classify(HoleFillResult& r, const HoleFillOptions& opt) {
  r.faultyEdges.clear();
  // Per edge: the highest level reached. The fill reaches k when every edge reaches k, or as
  // much as was asked of it where that is less than the request (a crease asked G0).
  r.edgeReached.assign(r.edgeRequests.size(), -1);
  std::vector<int> relaxed;
  for (size_t i = 0; i < r.edgeRequests.size() && i < r.report.edges.size(); ++i) {
    const EdgeRequest& q = r.edgeRequests[i];
    const EdgeContinuity& e = r.report.edges[i];
    const EdgeAllowance a = allowance(r, opt, i);
    r.edgeReached[i] = e.g0 > a.g0 ? -1 : (e.g1 > a.g1 ? 0 : (e.g2 > a.g2 ? 1 : 2));
    if (r.edgeReached[i] < static_cast<int>(q.asked)) r.faultyEdges.push_back(q.edgeIndex);
    else if (a.relaxed) relaxed.push_back(q.edgeIndex);
  }
  int reached = -1;
  for (int k = 2; k >= 0 && reached < 0; --k) {
    bool all = true;
    for (size_t i = 0; i < r.edgeRequests.size(); ++i) {
      const int asked = static_cast<int>(r.edgeRequests[i].asked);
      all = all && r.edgeReached[i] >= (asked < static_cast<int>(opt.continuity) ? std::min(k, asked) : k);
    }
    if (all) reached = k;
  }
  r.achieved = reached < 0 ? "none" : "G" + std::to_string(reached);
  if (!r.faceValid || !r.shapeValid) {
    r.status = FillStatus::Failed;
    r.failedStage = FillStage::Check;
    r.message = std::string("the filled ") + (!r.faceValid ? "face" : "model") + " is not a valid B-rep (BRepCheck)";
  } else if (!r.faultyEdges.empty()) {
    r.status = FillStatus::ToleranceNotMet;
    r.failedStage = FillStage::Solve;
    r.message = "requested " + r.requested + " but reached " + r.achieved + " (G0 " + std::to_string(r.report.g0) +
                ", G1 " + std::to_string(r.report.g1) + " rad, G2 " + std::to_string(r.report.g2) +
                "); worst at " + edgeList(r.faultyEdges);
  } else if (!r.pointDistances.empty() &&
             *std::max_element(r.pointDistances.begin(), r.pointDistances.end()) > r.g0Tolerance) {
    const auto worst = std::max_element(r.pointDistances.begin(), r.pointDistances.end());
    r.status = FillStatus::ToleranceNotMet;
    r.failedStage = FillStage::Solve;
    r.message = "reached " + r.achieved + " at the boundary, but passes point " + std::to_string(worst - r.pointDistances.begin() + 1) +
                " of " + std::to_string(r.pointDistances.size()) + " at " + std::to_string(*worst) + " (G0 tolerance " +
                std::to_string(r.g0Tolerance) + ")";
  } else {
    r.status = FillStatus::Ok;
    r.failedStage = FillStage::None;
    r.message = "reached " + r.achieved + " (requested " + r.requested + ")";
    int creases = 0, lowered = 0;
    for (const auto& q : r.edgeRequests)
      if (q.asked < opt.continuity) ++(q.source == "crease" ? creases : lowered);
    if (creases) r.message += "; G0 asked on " + std::to_string(creases) + " crease edge(s)";
    if (lowered) r.message += "; less than " + r.requested + " asked on " + std::to_string(lowered) + " edge(s)";
    if (!relaxed.empty())
      r.message += "; " + edgeList(relaxed) + " met only to the model's own accuracy there (its edge tolerance, "
                   "or the angle at which its neighbour meets it or its corners: tolerance_before and g1_floor per edge)";
  }
}

// The points' distances to the face's surface (model units).
std::vector<double> passDistances(const BSplineSurface& surface, const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> d;
  for (const Eigen::Vector3d& p : points) d.push_back(projectSequence(surface, {p}).distance[0]);
  return d;
}

// The pass points (HoleFillOptions::points, model units) on the domain: where a fill without them
// comes nearest to each (a quick solve: one refinement round), which must lie inside the
// trimming loop. Normalized as the samples are; Error for a point that is not over the hole.
void placePassPoints(FillConstraints& c, const std::vector<Eigen::Vector3d>& points, const Parameterization& P,
                     const Eigen::Vector3d& centre, double scale, const VariationalFillOptions& so) {
  VariationalFillOptions quick = so;
  quick.maxRefinements = 1;
  quick.progress = nullptr;
  c.passUV.clear();
  c.passXYZ.clear();
  const BSplineSurface first = solveVariationalFill(c, P.u0, P.u1, P.v0, P.v1, P.knotsU, P.knotsV, quick).surface;
  const Polygon2 loop(P.uv.begin(), P.uv.end());
  for (size_t k = 0; k < points.size(); ++k) {
    if (!points[k].allFinite()) throw Error("point " + std::to_string(k + 1) + " to pass through is not finite");
    const Eigen::Vector3d unit = (points[k] - centre) / scale;
    const Eigen::Vector2d uv = projectSequence(first, {unit}).uv[0];
    if (!contains(loop, uv)) {
      char xyz[120];
      std::snprintf(xyz, sizeof xyz, "(%.6g, %.6g, %.6g)", points[k].x(), points[k].y(), points[k].z());
      throw Error("point " + std::to_string(k + 1) + " " + xyz + " to pass through is not over the hole: the fill nearest to it " +
                  "is outside its boundary; pick points inside the hole");
    }
    c.passUV.push_back(uv);
    c.passXYZ.push_back(unit);
  }
}

// An opening bounded by more than one loop (brep/opening_loops.h) is refused: one face with one
// loop would cap one of them over the other, and say it reached its tier.
void refuseSharedOpening(const HoleDetectionResult& detection, const Hole& hole) {
  const std::vector<const Hole*> others = loopsSharingOpening(detection, hole);
  if (others.empty()) return;
  std::string message = "this opening has " + std::to_string(others.size() + 1) + " boundary loops: the one picked (" +
                        edgeList(hole.edgeIndices()) + ")";
  for (const Hole* o : others) message += " and " + edgeList(o->edgeIndices());
  throw Error(message + "; a face with one loop would cap one of them over the other: build a face bounded by all of them instead");
}

}  // namespace

PreparedHole::PreparedHole(const TopoDS_Shape& model, const std::vector<int>& holeEdges, const HoleDetectionOptions& d)
    : model_(model) {
  if (model.IsNull()) throw Error("the shape is empty: nothing to fill");
  const auto t0 = Clock::now();
  detection_ = detectHoles(model, d);
  hole_ = holeContainingEdges(detection_, holeEdges);
  refuseSharedOpening(detection_, hole_);
  detectSeconds_ = since(t0);
}

PreparedHole::PreparedHole(const TopoDS_Shape& model, int holeIndex, const HoleDetectionOptions& d) : model_(model) {
  if (model.IsNull()) throw Error("the shape is empty: nothing to fill");
  const auto t0 = Clock::now();
  detection_ = detectHoles(model, d);
  if (detection_.holes.empty())
    throw Error("the shape has no holes (no closed free-boundary loop besides outer sheet boundaries)");
  if (holeIndex < 0 || holeIndex >= static_cast<int>(detection_.holes.size()))
    throw Error("hole " + std::to_string(holeIndex + 1) + " does not exist: the shape has " +
                std::to_string(detection_.holes.size()) + " hole(s)");
  hole_ = detection_.holes[holeIndex];
  refuseSharedOpening(detection_, hole_);
  detectSeconds_ = since(t0);
}

HoleFillResult PreparedHole::fill(const HoleFillOptions& opt) {
  if (consumed_)
    throw Error("the prepared model already holds a fill made in place (copyModel false): prepare the hole again");
  const auto t0 = Clock::now();
  // The new pcurves and tolerances go onto edges the prepared model does not own: a deep copy of
  // the model when the face is sewn into it, else copies of the hole's supports alone (one copy,
  // so consecutive edges keep sharing their vertices), which costs nothing on large models.
  TopoDS_Shape work = model_;
  Hole hole = hole_;
  auto ontoCopy = [&hole](BRepBuilderAPI_Copy&& copier) {
    for (auto& he : hole.edges) {
      he.edge = TopoDS::Edge(copier.ModifiedShape(he.edge).Oriented(he.edge.Orientation()));
      he.support = TopoDS::Face(copier.ModifiedShape(he.support).Oriented(he.support.Orientation()));
    }
  };
  if (opt.sew && opt.copyModel) {
    BRepBuilderAPI_Copy copier(model_, Standard_True, Standard_False);
    work = copier.Shape();
    ontoCopy(std::move(copier));
  } else if (!opt.sew) {
    // Copy the support faces (which carry the edges' pcurves), sharing their geometry.
    BRep_Builder B;
    TopoDS_Compound supports;
    B.MakeCompound(supports);
    TopTools_IndexedMapOfShape seen;
    std::vector<std::pair<TopoDS_Shape, bool>> freeBefore;  // Add marks a face as held: not the user's
    for (const auto& he : hole.edges)
      if (!seen.Contains(he.support)) {
        seen.Add(he.support);
        freeBefore.emplace_back(he.support, he.support.Free());
        B.Add(supports, he.support);
      }
    ontoCopy(BRepBuilderAPI_Copy(supports, Standard_False, Standard_False));
    for (auto& [face, wasFree] : freeBefore) face.Free(wasFree);
  } else {
    consumed_ = true;
  }
  // Detection is paid by the first fill only; later ones reuse it.
  HoleFillResult r = fillHoleOf(work, hole, opt, detectSeconds_ + since(t0), &cache_);
  detectSeconds_ = 0;
  r.warnings.insert(r.warnings.begin(), detection_.warnings.begin(), detection_.warnings.end());
  for (size_t i = 0; i < detection_.holes.size(); ++i)
    if (detection_.holes[i].edgeIndices() == r.hole.edgeIndices()) r.holeIndex = static_cast<int>(i);
  return r;
}

HoleFillResult fillHole(const TopoDS_Shape& model, int holeIndex, const HoleFillOptions& opt) {
  return PreparedHole(model, holeIndex, opt.detection).fill(opt);
}

HoleFillResult fillHole(const TopoDS_Shape& model, const std::vector<int>& holeEdges, const HoleFillOptions& opt) {
  return PreparedHole(model, holeEdges, opt.detection).fill(opt);
}

namespace {

// The faces of `model` that BRepCheck finds invalid before the fill: the hole's neighbours, and
// every face when wholeModel. Sorted 1-based face indices.
std::vector<int> invalidFacesBefore(const TopoDS_Shape& model, const Hole& hole, bool wholeModel) {
  TopTools_IndexedMapOfShape modelFaces;
  TopExp::MapShapes(model, TopAbs_FACE, modelFaces);
  auto valid = [&](int f) {
    try {
      return BRepCheck_Analyzer(modelFaces(f)).IsValid() == Standard_True;
    } catch (const Standard_Failure&) {
      return false;  // a face the checker cannot even analyse is not valid
    }
  };
  std::vector<int> checked, invalid;
  for (const auto& he : hole.edges) {
    if (std::find(checked.begin(), checked.end(), he.supportIndex) != checked.end()) continue;
    checked.push_back(he.supportIndex);
    if (he.supportIndex >= 1 && he.supportIndex <= modelFaces.Extent() && !valid(he.supportIndex))
      invalid.push_back(he.supportIndex);
  }
  if (wholeModel)
    for (int f = 1; f <= modelFaces.Extent(); ++f)
      if (std::find(checked.begin(), checked.end(), f) == checked.end() && !valid(f)) invalid.push_back(f);
  std::sort(invalid.begin(), invalid.end());
  return invalid;
}

}  // namespace

HoleFillResult fillHoleOf(const TopoDS_Shape& work, const Hole& givenHole, const HoleFillOptions& opt, double elapsed,
                          FillCache* cache) {
  if (work.IsNull()) throw Error("the shape is empty: nothing to fill");
  HoleFillResult r;
  r.requested = toString(opt.continuity);
  r.methodName = toString(opt.method);
  const auto t0 = Clock::now() - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(elapsed));
  FillStage stage = FillStage::Detect;
  auto progress = [&](double f) { return !opt.progress || opt.progress(f); };
  const TopoDS_Shape& model = work;  // as it is before the fill: the pre-existing state is checked on it
  try {
    auto t = Clock::now();
    r.hole = givenHole;
    r.edgeRequests = edgeRequests(r.hole, opt.continuity, opt.edgeContinuity, opt.edges);
    Continuity highest = Continuity::G0;
    for (const auto& q : r.edgeRequests) highest = std::max(highest, q.asked, [](Continuity a, Continuity b) { return int(a) < int(b); });
    for (const auto& q : r.edgeRequests)
      if (q.source == "crease")
        r.warnings.push_back("Edge" + std::to_string(q.edgeIndex) + " is a crease (its support is " +
                             std::to_string(q.cornerMismatch * 180 / M_PI) + " deg off the corner plane): asked G0 there");
    r.timings.detect = elapsed + since(t);
    auto cancelled = [&] {
      r.status = FillStatus::Cancelled;
      r.failedStage = stage;
      r.message = "cancelled by the user";
      r.timings.total = since(t0);
      return r;
    };
    if (!progress(0.05)) return cancelled();

    // Attempts, each complete (parameterize, solve, build, check): the method at the base
    // sampling density, then at kDensify x (and kDensify² x) the density when it met the
    // tolerances at its samples but the report found the boundary missed between them, or its
    // knot refinement ran out of samples to split spans by. Auto (fill by result) starts with its
    // own pick (it also refuses a planar loop whose projection folds, which MVC alone would map onto
    // its N-gon and fill as if it were a hole), then the other of NP/MVC, then UVTran while the time
    // budget allows, each while nothing so far passed the report; the best by the report is kept
    // (betterFill). Judging candidates at their samples only, as this did before, kept fills that
    // the report then failed where another method passed (docs/benchmarks.md).
    constexpr int kDensify = 4;
    HF_CHECK(r.hole.scale > 0, "the hole has zero size");
    const Hole& hole = r.hole;
    const double scale = hole.scale;
    r.g0Tolerance = opt.tolerance > 0 ? opt.tolerance : tol::kG0Strict * scale;
    VariationalFillOptions so = opt.solver;
    so.continuity = highest;
    // The solver meets slightly tighter targets at its samples than the report checks between them.
    so.g0Tolerance = std::min(so.g0Tolerance, opt.solverMargin * r.g0Tolerance / scale);
    so.g1Tolerance = std::min(so.g1Tolerance, opt.solverMargin * opt.angularTolerance);
    so.g2Tolerance = std::min(so.g2Tolerance, opt.solverMargin * opt.curvatureTolerance);

    FillCache own;
    FillCache& fc = cache ? *cache : own;
    if (!(fc.sampling == opt.sampling) || !(fc.parameterization == opt.parameterization)) {
      fc = FillCache();
      fc.sampling = opt.sampling;
      fc.parameterization = opt.parameterization;
    }
    // The pre-existing state, checked once per hole (a Preview that changes only weights does not
    // pay for it again), before the first candidate face goes onto the loop's edges. Checking it on
    // a thread beside the solve was tried: on this 2-core machine the solve slowed by as much.
    bool priorStateKnown = false;
    auto knowPriorState = [&] {
      if (priorStateKnown) return;
      priorStateKnown = true;
      if (!fc.invalidBefore || (opt.checkModel && !fc.checkedWholeModel)) {
        const auto tc = Clock::now();
        fc.invalidBefore = invalidFacesBefore(model, hole, opt.checkModel);
        fc.checkedWholeModel = opt.checkModel;
        ++fc.priorChecks;
        r.timings.detect += since(tc);
      }
      r.invalidBefore = *fc.invalidBefore;
      if (!opt.checkModel)  // a whole-model check kept from an earlier fill names more than asked
        r.invalidBefore.erase(std::remove_if(r.invalidBefore.begin(), r.invalidBefore.end(),
                                             [&](int f) {
                                               return std::none_of(hole.edges.begin(), hole.edges.end(),
                                                                   [f](const HoleEdge& he) { return he.supportIndex == f; });
                                             }),
                              r.invalidBefore.end());
      if (!r.invalidBefore.empty()) {
        std::string names;
        for (int f : r.invalidBefore) names += (names.empty() ? "Face" : ", Face") + std::to_string(f);
        r.warnings.push_back("the input model was already invalid before the fill (BRepCheck) at " + names +
                             "; the fill is judged on the faces it changes");
      }
    };
    using Sampled = SampledBoundary;
    auto sampled = [&](int density) -> const Sampled& {
      auto it = fc.sampled.find(density);
      if (it != fc.sampled.end()) return it->second;
      stage = FillStage::Sample;
      const auto ts = Clock::now();
      BoundarySamplingOptions sampling = opt.sampling;
      sampling.minSamplesPerEdge *= density;
      sampling.maxSamplesPerEdge *= density;
      Sampled sd;
      sd.samples = sampleBoundary(hole, sampling);
      for (const auto& x : sd.samples)
        if (!x.point.allFinite() || !x.normal.allFinite() || !std::isfinite(x.curvature))
          throw Error("the hole boundary has non-finite coordinates (NaN or infinity) at Edge" +
                      std::to_string(hole.edges[x.edge].edgeIndex));
      Eigen::Vector3d lo = sd.samples[0].point, hi = sd.samples[0].point;
      for (const auto& x : sd.samples) { lo = lo.cwiseMin(x.point); hi = hi.cwiseMax(x.point); }
      sd.centre = 0.5 * (lo + hi);
      sd.unit = sd.samples;
      for (auto& x : sd.unit) {
        x.point = (x.point - sd.centre) / scale;
        x.curvature *= scale;
        x.weight /= scale;
      }
      r.timings.sample += since(ts);
      ++fc.samplings;
      return fc.sampled.emplace(density, std::move(sd)).first->second;
    };
    // A method's parameterization at one density, computed once per cache.
    auto parameterized = [&](ParamMethod m, int density) -> Parameterization {
      const auto key = std::make_pair(static_cast<int>(m), density);
      auto it = fc.parameterized.find(key);
      if (it != fc.parameterized.end()) return it->second;
      const Sampled& sd = sampled(density);
      stage = FillStage::Parameterize;
      Parameterization P = parameterize(hole, sd.unit, m, opt.parameterization);
      ++fc.parameterizations;
      return fc.parameterized.emplace(key, std::move(P)).first->second;
    };

    // Parameterize (unless `given` already is that parameterization) and solve at one density's
    // samples. Worker threads get no progress callback (it may be a Python callable, which only
    // the calling thread may run).
    auto solveWith = [&](ParamMethod m, int density, bool report, const Parameterization* given) {
      const Sampled& sd = sampled(density);
      FillAttempt a;
      a.method = m;
      const auto ta = Clock::now();
      try {
        a.P = given ? *given : parameterized(m, density);
        a.method = a.P.chosen;
        a.parameterizeSeconds = since(ta);
        FillConstraints c;
        // Normals a surface through the loop's curves can have (chasing the support's own beside
        // G0 on an inexact edge made the fill ripple; at a tilted corner of a G2 edge, spike in
        // curvature).
        std::vector<bool> easeCorners;
        for (const auto& q : r.edgeRequests) easeCorners.push_back(q.asked == Continuity::G2);
        c.normal = reachableNormals(hole, sd.unit, easeCorners);
        for (const auto& x : sd.unit) {
          c.uv.push_back(a.P.uv[c.uv.size()]);
          c.point.push_back(x.point);
          c.across.push_back(x.across);
          c.curvature.push_back(x.curvature);
          c.weight.push_back(x.weight);
          c.normalValid.push_back(x.normalValid);
          c.edge.push_back(x.edge);
          c.order.push_back(static_cast<int>(r.edgeRequests[x.edge].asked));
        }
        // Where one edge ends and the next begins, an inexact model's two curves may stop apart
        // (within their vertex's tolerance), and the pcurve sends both ends to one corner of the
        // domain: no surface meets both, and chasing them rippled the fill around the corner.
        // Both aim at the midpoint, which the vertex's tolerance covers.
        for (size_t k = 0; k < c.point.size(); ++k) {
          const size_t next = (k + 1) % c.point.size();
          if (c.edge[next] == c.edge[k]) continue;
          const Eigen::Vector3d mid = 0.5 * (c.point[k] + c.point[next]);
          c.point[k] = c.point[next] = mid;
        }
        c.referenceUV = a.P.interiorUV;
        c.referenceXYZ = a.P.interiorXYZ;
        if (!opt.points.empty()) placePassPoints(c, opt.points, a.P, sd.centre, scale, so);
        VariationalFillOptions sa = so;
        if (report) sa.progress = [&](double f) { return progress(0.1 + 0.75 * f); };
        a.vf = solveVariationalFill(c, a.P.u0, a.P.u1, a.P.v0, a.P.v1, a.P.knotsU, a.P.knotsV, sa);
        a.level = a.vf.levelMet;
        a.ratio = a.vf.worstRatio;
        a.energy = trimmedBendingEnergy(a.vf.surface, a.P.uv);
        a.ok = true;
      } catch (const Error& e) {
        a.error = e.what();
      } catch (const Standard_Failure& e) {
        a.error = occtFailure(e);
      }
      a.seconds = since(ta);
      r.timings.parameterize += a.parameterizeSeconds;
      r.timings.solve += a.seconds - a.parameterizeSeconds;
      return a;
    };

    // Build and check one solved attempt: a complete result (r's hole, requests and warnings so
    // far, plus this attempt's face, report and status). The face leaves the edges again
    // (detachFace), so the next candidate is built and judged on the edges as the model had them;
    // the one kept is put back on and sewn. Candidates are compared, and resampled, by the tiers
    // as they are, so that a model's own inaccuracy never stops the search at a worse face; the
    // one kept is then classified as asked.
    HoleFillOptions strict = opt;
    strict.modelAccuracy = false;
    auto judged = [&](const FillAttempt& a, const Sampled& sd, FaceBuildResult& built) {
      knowPriorState();
      HoleFillResult ri = r;
      ri.chosenMethod = a.method;
      const Parameterization& P = a.P;
      const VariationalFillResult& vf = a.vf;
      for (const auto& w : P.warnings) ri.warnings.push_back(w);
      for (const auto& w : vf.warnings) ri.warnings.push_back(w);
      if (P.chosen != opt.method) ri.methodName = toString(opt.method) + ":" + toString(P.chosen);
      if (P.chosen == ParamMethod::Uvtran) {
        ri.projectionSurface = P.projectionSurface;
        for (int i = 0; i < ri.projectionSurface.poles.rows(); ++i)
          ri.projectionSurface.poles.row(i) = (sd.centre + scale * P.projectionSurface.poles.row(i).transpose()).transpose();
      }
      BSplineSurface surf = vf.surface;
      for (int i = 0; i < surf.poles.rows(); ++i) surf.poles.row(i) = (sd.centre + scale * surf.poles.row(i).transpose()).transpose();
      ri.polesU = surf.numU();
      ri.polesV = surf.numV();
      ri.refinements = vf.refinements;
      ri.samples = static_cast<int>(sd.samples.size());
      FillStage at = FillStage::Build;
      auto fail = [&](const std::string& message) {
        if (!built.face.IsNull()) detachFace(hole, built);
        built = FaceBuildResult();
        ri.status = FillStatus::Failed;
        ri.failedStage = at;
        ri.message = message;
      };
      try {
        auto tb = Clock::now();
        built = buildTrimmedFace(hole, toOcct(surf), sd.samples, P.uv);
        ri.face = built.face;
        r.timings.build += since(tb);
        at = FillStage::Check;
        tb = Clock::now();
        ri.pointDistances = passDistances(surf, opt.points);
        judge(ri, strict, opt.sew);
        detachFace(hole, built);
        r.timings.check += since(tb);
      } catch (const Error& e) {
        fail(e.what());
      } catch (const Standard_Failure& e) {
        fail(occtFailure(e));
      }
      return ri;
    };

    std::vector<ParamMethod> methods{opt.method};
    std::optional<Parameterization> picked;  // Auto's own parameterization: its first attempt's
    if (opt.method == ParamMethod::Auto && opt.fillByResult) {
      stage = FillStage::Parameterize;
      picked = parameterized(ParamMethod::Auto, 1);
      // The note on why Auto picked it: the attempts' report line says what was tried instead.
      auto& w = picked->warnings;
      w.erase(std::remove_if(w.begin(), w.end(), [](const std::string& x) { return x.rfind("auto: ", 0) == 0; }), w.end());
      const ParamMethod pick = picked->chosen;
      methods = {pick, pick == ParamMethod::NearestPlane ? ParamMethod::MeanValue : ParamMethod::NearestPlane};
      if (opt.autoUvtran) methods.push_back(ParamMethod::Uvtran);
    }
    std::vector<HoleFillResult> results;  // every attempt that built a face or failed trying
    std::vector<FaceBuildResult> builds;  // the same attempts' faces, detached from the edges
    std::vector<std::string> tries;       // one line per attempt, for the report
    std::optional<size_t> best;
    size_t keptCandidate = 0;
    std::string firstError;
    bool cancel = false;
    for (size_t mi = 0; mi < methods.size() && !cancel; ++mi) {
      const ParamMethod m = methods[mi];
      if (m == ParamMethod::Uvtran && mi > 0 && opt.autoTimeBudget > 0 && since(t0) >= opt.autoTimeBudget) break;
      double lastRatio = 0;
      for (int density : {1, kDensify, kDensify * kDensify}) {
        const Sampled& sd = sampled(density);
        // Resampling is bounded: past this many samples a solve takes seconds and memory grows
        // with it, where the user waits on an interactive fill.
        if (density > 1 && static_cast<int>(sd.samples.size()) > opt.maxDenseSamples) {
          tries.push_back(toString(m) + " (" + std::to_string(density) + "x samples): not tried, " +
                          std::to_string(sd.samples.size()) + " samples exceed maxDenseSamples");
          break;
        }
        stage = FillStage::Parameterize;
        FillAttempt a = solveWith(m, density, mi == 0 && density == 1, mi == 0 && density == 1 && picked ? &*picked : nullptr);
        if (mi > 0 && m == ParamMethod::Uvtran && a.ok && a.method != ParamMethod::Uvtran) break;  // not MVC again
        a.density = density;
        if (a.ok && a.vf.cancelled) { cancel = true; break; }
        if (!a.ok) {
          if (firstError.empty()) firstError = a.error, stage = a.P.uv.empty() ? FillStage::Parameterize : FillStage::Solve;
          tries.push_back(toString(m) + " failed: " + a.error.substr(0, 80));
          r.candidates.push_back(std::move(a));
          break;
        }
        builds.emplace_back();
        results.push_back(judged(a, sd, builds.back()));
        const HoleFillResult& ri = results.back();
        a.built = !builds.back().face.IsNull();
        a.status = ri.status;
        a.reportRatio = reportRatio(ri, strict);
        // Denser samples pay for a fill that met its tolerances at its samples but not between
        // them, that misses them between its samples by far more than at them (the samples do not
        // resolve the boundary: seen on G2 requests along long B-spline strips, 0.33 at the samples
        // and 5.4 between them), or whose refinement ran out of samples to split spans by; a third
        // density only when the second did better than the first.
        const bool underResolved = a.reportRatio > kDensify * std::max(a.ratio, 1.0);
        const bool denser = ri.status == FillStatus::ToleranceNotMet &&
                            (a.vf.toleranceMet || a.vf.samplesTooSparse || underResolved) &&
                            (density == 1 || a.reportRatio < 0.5 * lastRatio);
        lastRatio = a.reportRatio;
        tries.push_back(toString(a.method) + (density > 1 ? " (" + std::to_string(density) + "x samples)" : "") + ": " +
                        toString(ri.status) + ", worst " + std::to_string(a.reportRatio) + " x tolerance");
        r.candidates.push_back(std::move(a));
        if (!best || betterFill(ri, results[*best], strict)) best = results.size() - 1, keptCandidate = r.candidates.size() - 1;
        if (!denser) break;
      }
      if (best && results[*best].status == FillStatus::Ok) break;
      if (!progress(0.85)) cancel = true;
    }
    knowPriorState();
    if (cancel) return cancelled();
    if (!best) throw Error(firstError);
    // The one kept goes back onto the edges and is sewn into the model.
    if (!builds[*best].face.IsNull()) {
      stage = FillStage::Build;
      const auto tb = Clock::now();
      attachFace(hole, builds[*best]);
      if (opt.sew) {
        const SewResult sr = sewFace(work, builds[*best].face, opt.computeVolume);
        results[*best].shape = sr.shape;
        results[*best].closedSolid = sr.closedSolid;
        results[*best].volume = sr.volume;
      }
      r.timings.build += since(tb);
    }
    if (results[*best].status != FillStatus::Failed) classify(results[*best], opt);
    r.candidates[keptCandidate].kept = true;
    std::vector<FillAttempt> candidates = std::move(r.candidates);
    FillTimings timings = r.timings;
    r = std::move(results[*best]);
    r.candidates = std::move(candidates);
    r.timings = timings;
    if (tries.size() > 1) {
      std::string line = toString(opt.method) + " tried ";
      for (const auto& x : tries) line += x + "; ";
      r.warnings.push_back(line + "kept " + toString(r.chosenMethod));
    }
  } catch (const Error& e) {
    if (stage == FillStage::Detect) throw;  // the hole could not be named: the caller's mistake
    r.status = FillStatus::Failed;
    r.failedStage = stage;
    r.message = e.what();
  } catch (const Standard_Failure& e) {
    r.status = FillStatus::Failed;
    r.failedStage = stage;
    r.message = occtFailure(e);
  } catch (const std::exception& e) {
    r.status = FillStatus::Failed;
    r.failedStage = stage;
    r.message = e.what();
  }
  if (r.status == FillStatus::Failed && r.faultyEdges.empty()) r.faultyEdges = r.hole.edgeIndices();
  r.timings.total = since(t0);
  progress(1.0);
  return r;
}

BSplineSurface uvtranProjectionSurface(const TopoDS_Shape& model, const std::vector<int>& holeEdges,
                                       const HoleFillOptions& opt) {
  if (model.IsNull()) throw Error("the shape is empty");
  const Hole hole = holeContainingEdges(detectHoles(model, opt.detection), holeEdges);
  std::vector<Eigen::Vector3d> loop;
  for (const auto& s : sampleBoundary(hole, opt.sampling)) loop.push_back(s.point);
  learn::UvtranOptions uo;
  uo.weights = opt.parameterization.uvtranWeights;
  return learn::predictUvtran(loop, uo).surface;
}

namespace {
std::vector<std::string> edgeNames(const Hole& h) {
  std::vector<std::string> names;
  for (int e : h.edgeIndices()) names.push_back("Edge" + std::to_string(e));
  return names;
}

void holeJson(JsonWriter& j, const Hole& h, const std::vector<const Hole*>& openingLoops, int index) {
  j.beginObject();
  j.field("index", index);
  std::vector<int> supports;
  for (const auto& e : h.edges) supports.push_back(e.supportIndex);
  j.field("edges", edgeNames(h)).field("edge_indices", h.edgeIndices()).field("support_faces", supports);
  j.field("corners", h.corners).field("length", h.length).field("scale", h.scale);
  j.field("outer_boundary", h.outerBoundary).field("outer_score", h.outerScore);
  // The other loops of its opening (brep/opening_loops.h), edge names each: a fill refuses it.
  j.key("opening_loops").beginArray();
  for (const Hole* o : openingLoops) j.value(edgeNames(*o));
  j.endArray();
  j.endObject();
}
}  // namespace

std::string toJson(const HoleDetectionResult& d) {
  JsonWriter j;
  // Each loop sampled once for all the loops' nesting, not once per loop it is compared with.
  const std::vector<std::vector<const Hole*>> openings = loopsSharingOpenings(d);
  j.beginObject().key("holes").beginArray();
  for (size_t i = 0; i < d.holes.size(); ++i) holeJson(j, d.holes[i], openings[i], static_cast<int>(i) + 1);
  j.endArray().key("outer_boundaries").beginArray();
  for (size_t i = 0; i < d.outerBoundaries.size(); ++i)
    holeJson(j, d.outerBoundaries[i], openings[d.holes.size() + i], static_cast<int>(i) + 1);
  j.endArray();
  j.field("non_manifold_edges", d.nonManifoldEdges).field("warnings", d.warnings);
  j.endObject();
  return j.str();
}

std::vector<HoleFillResult> fillHoles(const TopoDS_Shape& model, const HoleFillOptions& options) {
  const size_t n = detectHoles(model, options.detection).holes.size();
  if (n == 0) throw Error("the shape has no holes");
  HoleFillOptions o = options;
  o.sew = true;
  std::vector<HoleFillResult> results;
  TopoDS_Shape shape = model;
  for (size_t i = 0; i < n; ++i) {
    results.push_back(fillHole(shape, 0, o));
    const HoleFillResult& r = results.back();
    if (r.status == FillStatus::Failed || r.status == FillStatus::Cancelled) break;
    shape = r.shape;
    if (detectHoles(shape, options.detection).holes.empty()) break;
  }
  return results;
}

Status toStatus(FillStatus s) {
  switch (s) {
    case FillStatus::Ok: return Status::Ok;
    case FillStatus::ToleranceNotMet: return Status::Warned;
    case FillStatus::Cancelled: return Status::Cancelled;
    case FillStatus::Failed: return Status::Failed;
  }
  return Status::Failed;
}

Outcome outcome(const HoleFillResult& r) {
  Outcome o;
  o.status = toStatus(r.status);
  if (o.status == Status::Failed || o.status == Status::Cancelled) o.stage = toString(r.failedStage);
  o.message = r.message;
  o.warnings = r.warnings;
  o.faulting = r.faultyEdges;
  return o;
}

std::string toJson(const HoleFillResult& r) {
  JsonWriter j;
  j.beginObject();
  j.field("status", toString(r.status)).field("failed_stage", toString(r.failedStage)).field("message", r.message);
  j.field("method", r.methodName).field("requested", r.requested).field("achieved", r.achieved);
  j.field("hole", r.holeIndex + 1).field("corners", r.hole.corners).field("edges", r.hole.edgeIndices());
  j.field("faulty_edges", r.faultyEdges);
  j.key("candidates").beginArray();
  for (const auto& a : r.candidates) {
    j.beginObject().field("method", toString(a.method)).field("ok", a.ok).field("density", a.density);
    if (a.ok) {
      j.field("level_at_samples", a.level).field("tolerance_met_at_samples", a.vf.toleranceMet);
      j.field("g0", a.vf.g0).field("g1", a.vf.g1).field("g2", a.vf.g2).field("bending_energy", a.energy);
      j.field("built", a.built).field("status", toString(a.status)).field("report_worst_ratio", a.reportRatio);
      j.field("kept", a.kept);
    } else {
      j.field("error", a.error);
    }
    j.field("seconds", a.seconds).endObject();
  }
  j.endArray();
  j.key("edge_continuity").beginArray();
  for (size_t i = 0; i < r.edgeRequests.size(); ++i) {
    const EdgeRequest& q = r.edgeRequests[i];
    const int lv = i < r.edgeReached.size() ? r.edgeReached[i] : -1;
    j.beginObject().field("edge", q.edgeIndex).field("asked", toString(q.asked)).field("source", q.source);
    j.field("reached", lv < 0 ? std::string("none") : "G" + std::to_string(lv)).field("corner_mismatch", q.cornerMismatch);
    j.endObject();
  }
  j.endArray();
  writeJsonFields(j, r.report);
  j.field("g0_tolerance", r.g0Tolerance);
  j.key("point_distances").beginArray();  // per point to pass through, model units
  for (double d : r.pointDistances) j.value(d);
  j.endArray();
  j.field("invalid_before", r.invalidBefore);
  j.field("face_valid", r.faceValid).field("shape_valid", r.shapeValid).field("closed_solid", r.closedSolid);
  j.field("volume", r.volume).field("poles_u", r.polesU).field("poles_v", r.polesV).field("refinements", r.refinements);
  j.field("boundary_samples", r.samples);
  j.key("timings").beginObject();
  j.field("detect", r.timings.detect).field("sample", r.timings.sample).field("parameterize", r.timings.parameterize);
  j.field("solve", r.timings.solve).field("build", r.timings.build).field("check", r.timings.check).field("total", r.timings.total);
  j.endObject();
  j.field("warnings", r.warnings);
  j.endObject();
  return j.str();
}

}  // namespace holefill
