// Labeled fitting of a trimmed mesh region, end to end (mesh-extension.md): labeled
// parameterization on the guiding frame's rectangle (labeled_parameterization.h), extension of
// the region to that rectangle (domain_extension.h), and the cubic tensor-product fit trimmed by
// the region's boundary (tensor_fit.h). `extend = false` fits the region alone, for comparison.
// The control net is chosen by the data: refined while the fit misses and what is left is not
// scan noise, then, on a clean region, knots inserted where it still misses (localRefinements), or
// under scan noise cells refined there (truncated hierarchical B-splines, bidgcn.md sec. 5's space).
#pragma once

#include "geometry/outcome.h"

#include <string>
#include <vector>

#include "fitting/domain_extension.h"
#include "fitting/labeled_parameterization.h"
#include "fitting/tensor_fit.h"

namespace holefill {

struct LabeledFitOptions {
  LabeledParameterizationOptions parameterization;
  DomainExtensionOptions extension;  // order 3 (G2) by default
  // fit.controlU × fit.controlV: the control points to start from. Three rounds of parameter
  // correction (tensor_fit.h): the labeled map is distorted most at reflex corners and horns.
  TensorFitOptions fit = [] { TensorFitOptions f; f.parameterCorrections = 3; return f; }();
  bool extend = true;
  // Where the extension's new vertices get their places. SmoothFit (the default): a fit of the
  // region alone over the whole rectangle with thin plate `extensionSmoothing` (relative, as
  // TensorFitOptions::smoothing), at the control points of each fit the extension serves (so
  // again at each refinement), sampled at the new vertices; once the control net's knot spans
  // fall below twice the extension's grid spacing, the grid is rebuilt at a third of a span
  // (keeping its first clearance from the region, each sample weighted by its area). Continuation: the paper's
  // polyharmonic continuation of the region's boundary rings at extension.order (G2: 3, G1: 2),
  // shaped by extension.fairness, meshFairness and paperIsocurves (which SmoothFit refuses:
  // they would change nothing). The continuation is a Cauchy problem: scan noise at the boundary
  // is carried out and grows; the thin plate reads the whole region and carries it on as flat as
  // it can. Measured on the 117-region corpus (docs/benchmarks.md, fifth round): data goal 49%
  // → 56%, no weak control points 90% → 96%, condition < 1e8 89% → 95%; sampled per refinement
  // rather than once at fit's counts (ninth round): 73% → 75%, 95% → 99%, 91% → 97%.
  enum class ExtensionSource { Continuation, SmoothFit };
  ExtensionSource extensionSource = ExtensionSource::SmoothFit;
  double extensionSmoothing = 1e-4;
  // Control points chosen by the data: from the larger of fit.controlU and fit.controlV along the
  // rectangle's longer side and as many as keep the cells square along the other (4 at least),
  // refined by half again per
  // direction while the region's data max exceeds `relativeTolerance` (of its diagonal) and what is left
  // is more than noise (which more control points would follow): the data RMS above 1.5 times
  // the region's scan noise σ, a neighbourhood of vertices off the surface by more than σ on
  // average (fitting/residual_bias.h), or the max above 5 σ, up to maxControl per direction. A refinement is undone,
  // and ends the search, when it brings weak control points or a condition of 1e8 or more, or
  // lowers neither the data max nor (by a third) the RMS or the bias. maxControl 0: exactly
  // fit.controlU × controlV.
  // Where scan noise could be what the fit misses (5 σ above the tolerance), refinement stops at
  // noisyMaxControl (if maxControl is larger): each step past it follows the noise more than the
  // surface (bspline_notch_n0p05, 0.05% noise: 1.78e-3 of the diagonal off the truth at 40 × 40,
  // 3.05e-3 at 48 × 48). A clean region that still misses goes on to maxControl: its misses are the
  // map's distortion at reflex corners and slots, which finer knots follow (bspline_corner_clean_corners
  // 1.35e-3 at 40 × 40, 7.3e-4 at 60 × 60; docs/benchmarks.md, twelfth round).
  double relativeTolerance = 1e-3;
  // The same goal in the region's own units; > 0: used instead of relativeTolerance (what the
  // doors' `tolerance` sets), 0: relativeTolerance of the region's bounding-box diagonal.
  double tolerance = 0;
  int maxControl = 60;
  int noisyMaxControl = 40;
  // Where the control net of a clean region has stopped growing (at maxControl, or gaining
  // nothing more) and the fit still misses, knots are inserted where it misses: in the middle of
  // the knot spans, in u and in v, holding the worst vertex, each insertion kept as a refinement
  // is (the data max, rms or bias falls; no weak control point; condition below 1e8). Not under
  // scan noise, where the worst vertex is mostly the noise's and a knot line follows it across the
  // whole domain. At most this many; 0: none.
  // Measured on the 131-region corpus (docs/benchmarks.md, thirteenth round): every clean region
  // meets the data goal with them (bspline_uslot_clean_cw 1.79e-3 -> 8.8e-4 of the diagonal
  // off the truth; 45 of 45 clean regions, 44 without).
  int localRefinements = 8;
  // Under scan noise the same number of steps refine cells instead (THB: TensorFitOptions::
  // refinedCells) around the vertices whose neighbourhoods, or runs along the boundary, miss by
  // more than the noise explains (a χ² test on their residuals), first where only such single
  // misses are left and then where the whole net stops; a cell is refined at most localLevels
  // times (its knot spans halved each time); 0: never. Measured on the corpus's 86 noisy regions
  // (docs/benchmarks.md, fifteenth round).
  int localLevels = 3;
  // How far the untrimmed surface reaches past the domain rectangle, as a fraction of the
  // rectangle's larger side: the extension's margin (a width, kept when its grid is rebuilt
  // finer). Reverse engineering extends a fitted surface past its region so that its neighbours
  // can be intersected with it; 0: to the rectangle (and extension.marginLayers grid layers).
  // Needs the extension. Measured on the 131-region corpus (docs/benchmarks.md, tenth round),
  // against 0: data goal 113 -> 120 regions, band deviation median 0.126 -> 0.078 at 0.05 (one
  // region worse past its goal); at 0.1, 117 and 0.072: the thin plate's extrapolation grows
  // with the distance, and the shorter reach is kept.
  double reach = 0.05;
  // Where the fit over the labeled map misses the tolerance, has weak control points, a condition
  // of 1e8 or more or an invalid face: the fit over the labels relaxed (labeled_parameterization.h
  // relaxLabels: the region's free flattening turned as the labels say) is tried, and kept, with a
  // warning, where it has none of those faults, or else meets the data better without more of
  // the others. Under scan noise (5 σ above the tolerance) a labeled fit that needed refining is
  // sound yet may follow the noise: the relaxed map is tried too and kept where it is sound with
  // fewer control points. A labeled map that cannot be fitted at all (its boundary crosses itself
  // in the domain) is replaced by the relaxed one, or its error stands. False: the labeled map
  // is kept whatever its fit.
  bool relaxLabels = true;
};

struct LabeledFitResult {
  LabeledParameterization parameterization;
  DomainExtension extension;         // empty when not extended
  TensorFitResult fit;
  std::vector<std::string> refinements;  // control points tried, with their data max, and why the search stopped
  double noise = 0;                      // the region's scan noise σ (mesh/scan_noise.h) / its diagonal
  double dataBias = 0;                   // the fit's residual bias (fitting/residual_bias.h) / the region's diagonal
  // The data max within the tolerance, or within 5 σ of the scan noise (the largest of 20,000
  // normal deviates is about 4.4 σ): what a fit that follows the surface leaves. Otherwise a
  // warning says by how much it misses, and the CLI exits 3.
  bool metTolerance = false;
  // The fit is over the labels relaxed (LabeledFitOptions::relaxLabels), not the labeled map.
  bool labelsRelaxed = false;
  int refinementsKept = 0;               // refinements of the control net kept past the first fit
  std::vector<std::string> warnings;     // the fit's own (an extension given up); allWarnings() adds the parameterization's
  std::vector<std::string> allWarnings() const;
  double seconds = 0;
  // Warned where the map keeps folded triangles, the trimmed face is invalid or the data is missed.
  Outcome outcome() const;
  std::string toJson() const;
};

// Throws Error for options out of range (checkLabeledFitOptions) and as the stages do.
LabeledFitResult fitLabeled(const TriangleMesh& region, const std::vector<LabeledSegment>& segments, const LabeledFitOptions& options = {});

// The options' ranges, checked once for every door: a positive relative tolerance, a tolerance zero or positive, at least 4 control points a
// direction, maxControl 0 or at least the larger start count, weights zero or positive, the reach
// within 0 to 10, and no continuation shaping (mesh fairness, the paper's isocurves) asked of the
// sampled extension. Throws Error naming the option.
void checkLabeledFitOptions(const LabeledFitOptions& options);

// The extension by the name the doors take: "fit" (SmoothFit, the default), "G2" or "G1" (the
// paper's continuation at that order), "none" (the region alone); Error for another name.
void setExtensionByName(LabeledFitOptions& options, const std::string& name);
std::string extensionName(const LabeledFitOptions& options);  // the name setExtensionByName takes back

// Labels as the CLI and Python take them: {"segments": [{"label": "N", "vertices": [i, j, ...]}, ...]},
// labels N, E, S, W (or North, East, South, West), 0-based vertex indices along the boundary.
std::vector<LabeledSegment> parseLabelsJson(const std::string& text, const std::string& name = "labels");

}  // namespace holefill
