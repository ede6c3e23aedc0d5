// Filling one N-sided hole of a B-rep model with a single trimmed B-spline face,
// end to end: detect -> sample -> parameterize -> solve -> build -> check.
// The user's shape is never touched: the pipeline works on a deep copy, whose
// edges receive the new face's pcurves, and returns the face and the sewn model.
//
// Failure is reported, not thrown: the result names the stage that failed, the
// hole's edges that carry the largest errors, and which continuity was actually
// reached next to the one requested (STYLE.md #3). Holes that cannot be named
// (empty shape, no such edges) throw holefill::Error. OCCT exceptions never leave.
#pragma once

#include "geometry/outcome.h"

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "brep/boundary_sampling.h"
#include "brep/continuity_report.h"
#include "brep/edge_continuity.h"
#include "brep/hole_detection.h"
#include "fill/parameterizer.h"
#include "fill/variational_fill.h"

namespace holefill {

struct HoleFillOptions {
  ParamMethod method = ParamMethod::Auto;      // Auto: fill by result (fillByResult), see FillAttempt
  Continuity continuity = Continuity::G1;      // the most any edge is asked for (see edge_continuity.h)
  std::map<int, Continuity> edgeContinuity;    // explicit per-edge requests by 1-based model edge index
  EdgeContinuityOptions edges;                 // creases found at the loop's corners are asked G0
  double tolerance = 0.0;           // G0 tolerance, model units; 0 means 1e-6 x hole scale (DESIGN strict tier)
  double angularTolerance = 1e-3;   // G1 tolerance, radians
  double curvatureTolerance = 0.1;  // G2 tolerance, relative
  // Points inside the hole the face passes through, model units (Surface Filling's vertex
  // constraints): each placed on the domain where a fill without them comes nearest to it (it
  // must lie over the hole: its place inside the trimming loop), then held to the G0 tolerance
  // as the boundary is. A point the face misses by more makes the fill tolerance_not_met.
  std::vector<Eigen::Vector3d> points;
  bool modelAccuracy = true;        // judge each edge no stricter than the model is there: G0 within the edge's
                                    // own BRep tolerance where larger, G1 within angularTolerance beyond the angle
                                    // at which the neighbour meets the edge's curve (continuity_report.h g1Floor);
                                    // the message names the edges that pass only so. false: the tiers as they are
  HoleDetectionOptions detection;
  BoundarySamplingOptions sampling;
  ParameterizationOptions parameterization;
  VariationalFillOptions solver;    // its tolerances and continuity are set from the fields above
  double solverMargin = 0.95;       // the solver aims at this fraction of each tolerance at its samples
  int maxDenseSamples = 12000;      // a resampled (4x, 16x) attempt is not made past this many boundary samples
  bool fillByResult = true;         // Auto fills with its pick (parameterizer.h), then with the other of
                                    // NP/MVC when the pick's face misses the tolerances (judged by the
                                    // continuity report, between the samples too), and keeps the better;
                                    // false: Auto's pick alone
  bool autoUvtran = true;           // ... and UVTran too when both missed
  double autoTimeBudget = 2.0;      // seconds: UVTran is not started after this (0: no limit)
  bool sew = true;                  // also build the model with the face sewn in
  bool copyModel = true;            // false: with sew, the new pcurves go onto the given model's own edges
                                    // instead of a deep copy's (for a caller that read the model for this
                                    // fill alone, as the CLI does: the copy is a tenth of a fill's time on
                                    // a 1.5 MB model). The model is then shared with the result.
  bool computeVolume = false;       // volume of a closed result (costs a whole-model integration)
  bool checkModel = false;          // also list every face of the input that BRepCheck finds invalid
                                    // (costs a whole-model check; the fill itself is judged locally)
  std::function<bool(double)> progress;  // fraction in [0,1]; return false to cancel
};

enum class FillStatus { Ok, ToleranceNotMet, Failed, Cancelled };
enum class FillStage { None, Detect, Sample, Parameterize, Solve, Build, Check };
std::string toString(FillStatus s);
std::string toString(FillStage s);

struct FillTimings {
  double detect = 0, sample = 0, parameterize = 0, solve = 0, build = 0, check = 0, total = 0;  // seconds
};

// One parameterize + solve of a hole (Auto tries several; each is built and checked, the best kept).
struct FillAttempt {
  ParamMethod method = ParamMethod::Auto;  // the method used
  bool ok = false;
  std::string error;
  Parameterization P;
  VariationalFillResult vf;
  int level = -1;            // continuity level met at the samples (-1: G0 missed)
  double ratio = 0;          // worst error / its tolerance at the samples
  double energy = 0;         // trimmedBendingEnergy of the solved surface (normalized units)
  double seconds = 0, parameterizeSeconds = 0;
  int density = 1;           // boundary samples, as a multiple of the options' sampling
  // The face built from it, judged as the result is (the continuity report between the samples):
  bool built = false;
  FillStatus status = FillStatus::Failed;
  double reportRatio = 0;    // worst report error / its tolerance, over what each edge was asked
  bool kept = false;         // the one returned
};

struct HoleFillResult {
  FillStatus status = FillStatus::Failed;
  FillStage failedStage = FillStage::None;
  std::string message;
  std::vector<int> faultyEdges;  // 1-based model edge indices where the requested tolerances fail
  TopoDS_Face face;              // the filling face (shares edges with `shape`)
  TopoDS_Shape shape;            // the model copy with the face sewn in
  bool closedSolid = false;
  double volume = 0.0;
  bool faceValid = false, shapeValid = false;  // BRepCheck_Analyzer: the new face; it and the neighbours it changed
  std::vector<int> invalidBefore;  // 1-based faces of the input BRepCheck found invalid before the fill
                                   // (the hole's neighbours; with checkModel every face)
  Hole hole;
  int holeIndex = -1;            // 0-based index among detectHoles(model).holes, -1 for an outer boundary
  ContinuityReport report;
  std::string requested, achieved;  // "G0".."G2"; achieved may be "none": the highest k every edge reaches
                                    // as far as it was asked (min(k, asked)), so a crease at G0 does not lower it
  std::vector<double> pointDistances;     // per HoleFillOptions::points: its distance to the face's surface, model units
  std::vector<EdgeRequest> edgeRequests;  // per loop edge: what was asked and why
  std::vector<int> edgeReached;           // per loop edge (same order): highest level reached, -1 none
  double g0Tolerance = 0;           // model units, as applied
  int polesU = 0, polesV = 0, refinements = 0, samples = 0;
  std::vector<std::string> warnings;
  FillTimings timings;
  std::string methodName;           // "uvtran:mvc" when a request fell back, "auto:np" for the one Auto kept
  ParamMethod chosenMethod = ParamMethod::Auto;
  std::vector<FillAttempt> candidates;  // every attempt, in order (one for a named method that met the tolerances)
  BSplineSurface projectionSurface; // UVTran's predicted projection surface (model units), when it was used
};

// The boundary of a hole sampled at one density: in model units and normalized (centre at 0,
// scale 1: the coordinates the fill is solved in).
struct SampledBoundary {
  std::vector<BoundarySample> samples, unit;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

// What fills of one hole share: its boundary samples per density, its parameterizations per
// method and density, and the model's pre-existing state, each computed on first use. Valid
// for one set of sampling and parameterization options (a fill with others starts it afresh).
struct FillCache {
  std::map<int, SampledBoundary> sampled;                          // by density
  std::map<std::pair<int, int>, Parameterization> parameterized;  // by (method, density); successes only
  BoundarySamplingOptions sampling;
  ParameterizationOptions parameterization;
  int samplings = 0, parameterizations = 0;  // computed so far (not taken from the cache)
  // The model's pre-existing state (HoleFillResult::invalidBefore), checked once per hole; with
  // the whole model when checkedWholeModel.
  std::optional<std::vector<int>> invalidBefore;
  bool checkedWholeModel = false;
  int priorChecks = 0;  // times the pre-existing state was checked
};

// The hole is the loop holding all the given 1-based edge indices (FreeCAD "Edge<k>").
HoleFillResult fillHole(const TopoDS_Shape& model, const std::vector<int>& holeEdges, const HoleFillOptions& options = {});
// The hole by 0-based index in detectHoles(model).holes.
HoleFillResult fillHole(const TopoDS_Shape& model, int holeIndex, const HoleFillOptions& options = {});
// Every hole of `model`, one after the other, each filled into the model the one before returned
// (faces filled earlier are the neighbours of later holes, so options.sew is taken as true); the
// last result's shape is the model with all of them. Stops at the first fill that fails or is
// cancelled (its result is the last one). Throws Error for a model without holes.
std::vector<HoleFillResult> fillHoles(const TopoDS_Shape& model, const HoleFillOptions& options = {});
// A hole already found (or assembled, as fillAdjacentHoles does) whose edges and supports belong
// to `work`. With options.sew the new pcurves go onto those edges and the face is sewn into
// `work`: it must be the caller's private copy. `elapsed` (seconds already spent finding the
// hole) is added to the detect timing. holeIndex stays -1.
// `cache`: samples and parameterizations from earlier fills of this hole (PreparedHole); none: its own.
HoleFillResult fillHoleOf(const TopoDS_Shape& work, const Hole& hole, const HoleFillOptions& options = {},
                          double elapsed = 0.0, FillCache* cache = nullptr);

// A hole found once and filled as often as asked (issue 20, the precompute/solve split): the model
// is read and its hole detected once; the boundary samples and the parameterizations (UVTran's
// network, MVC's interior references) are kept from the first fill that needs them. A Preview
// that changes only the method, continuity, tolerances, per-edge requests or output reuses all
// of it and pays for the solve, build and check alone. The factorization is not kept: the
// continuity rows, per-edge orders and weights are what such a change changes, and the knot
// refinement follows the tolerances. Each fill works on its own copy of the hole's edges (of the
// whole model when sewn), so the prepared model is never modified and may be filled again; with
// options.copyModel false the model itself receives the face, and the hole can be filled once.
class PreparedHole {
 public:
  PreparedHole(const TopoDS_Shape& model, const std::vector<int>& holeEdges, const HoleDetectionOptions& detection = {});
  PreparedHole(const TopoDS_Shape& model, int holeIndex, const HoleDetectionOptions& detection = {});
  HoleFillResult fill(const HoleFillOptions& options);  // options.detection: the constructor's applies
  const Hole& hole() const { return hole_; }
  const FillCache& cache() const { return cache_; }
  double detectSeconds() const { return detectSeconds_; }

 private:
  TopoDS_Shape model_;
  HoleDetectionResult detection_;
  Hole hole_;
  FillCache cache_;
  double detectSeconds_ = 0;
  bool consumed_ = false;  // filled in place (copyModel false)
};

// UVTran's projection surface for the hole holding the given edges, in model units (what the
// "uvtran" method projects the boundary onto), for display. Throws when it cannot be predicted.
BSplineSurface uvtranProjectionSurface(const TopoDS_Shape& model, const std::vector<int>& holeEdges,
                                       const HoleFillOptions& options = {});

std::string toJson(const HoleFillResult& r);
// Ok, Warned (tolerance_not_met: the report's own, more precise name), Failed at its stage, Cancelled.
Status toStatus(FillStatus s);
Outcome outcome(const HoleFillResult& r);
std::string toJson(const HoleDetectionResult& r);

}  // namespace holefill
