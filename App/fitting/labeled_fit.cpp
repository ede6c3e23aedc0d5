#include "fitting/labeled_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>

#include "geometry/error.h"
#include "geometry/json_reader.h"
#include "geometry/json_writer.h"
#include "fitting/residual_bias.h"
#include "fitting/thb_spline.h"

namespace holefill {

namespace {

// Whether the region's scan noise (σ, of the diagonal) could be what a fit misses: 5 σ, about the
// largest of 20,000 normal deviates, above the tolerance. Such a fit is refined no further than
// noisyMaxControl, and the relaxed map is tried for fewer control points.
bool noiseCouldBeTheMiss(double noise, const LabeledFitOptions& o) { return 5 * noise > o.relativeTolerance; }

// Extension, fit and refinement over one map of the region: the labeled one, or the labels
// relaxed (relaxLabels).
LabeledFitResult fitOnMap(const TriangleMesh& region, LabeledParameterization map, const LabeledFitOptions& o) {
  LabeledFitResult r;
  r.parameterization = std::move(map);
  const LabeledParameterization& p = r.parameterization;
  const double reachWidth = o.reach * std::max(p.width, p.height);
  // The extension of the mapped (smoothed) region, the region's own vertices put back in it; its
  // new vertices are placed when a fit is asked for (sampleExtensionFor).
  const Eigen::Index nr = region.vertices.rows();
  const auto extendedAt = [&](const DomainExtensionOptions& eo) {
    DomainExtension e = extendToRectangle(TriangleMesh{p.mapped, region.triangles}, p.uv, p.width, p.height, eo);
    e.mesh.vertices.topRows(nr) = region.vertices;
    return e;
  };
  const bool sampled = o.extensionSource == LabeledFitOptions::ExtensionSource::SmoothFit;
  if (o.extend) {
    // The extension continues the surface the map was made of (the region smoothed along the
    // normal where it is noisy): continued from the noisy vertices, scan noise at the boundary was
    // carried out into the extension, and the fit with it missed the data (median data max
    // 1.1e-2 with the extension against 5.3e-3 without, on the corpus). The region's own vertices
    // are then fitted where they are.
    DomainExtensionOptions eo = o.extension;
    eo.continueSurface = !sampled;
    eo.marginWidth = std::max(eo.marginWidth, reachWidth);
    r.extension = extendedAt(eo);
  }
  bool extended = o.extend;
  // The extension's new vertices are sampled from a fit of the region alone over the whole
  // rectangle with the thin plate extensionSmoothing, at the control points of the fit they serve:
  // sampled once from a coarse fit, a concave region's extension kept that fit's bias where the
  // finer fit bends (bspline_corner_clean: the extension given up, 1.3e-2 of the diagonal and 11
  // weak control points; sampled per fit: kept, 7.4e-4 and none).
  // The extension's grid is as fine as the region's edges; a refined control net outgrows it
  // (27 × 27 over a grid of 0.2 with knot spans of 0.38: the cells at the domain's rim held 4 to 7
  // samples on the grid's lines, and the data's normal matrix was singular there, bspline_notch_n0p05).
  // Past half a knot span it is rebuilt at a third of one, so each cell holds nine samples or more.
  // The new samples keep the first grid's clearance from the region: closer in, where the region's
  // own vertices decide the surface, they pulled scan_bunny1500_blob_clean's fit from 9.7e-4 to
  // 1.5e-3 at the same 40 × 40. Each weighs as the area it stands for against the first grid's
  // samples, so that the extension pulls per unit of area as it did before the grid was refined.
  const double firstSpacing = r.extension.spacing;
  // The margin the first grid got, kept by a finer one (in layers it would shrink with the grid,
  // and the surface's domain would change between refinements).
  const double firstMargin = std::max({o.extension.marginLayers * firstSpacing, o.extension.marginWidth, reachWidth});
  const auto sampleExtensionFor = [&](TensorFitOptions& fo) {
    if (!sampled || r.extension.mesh.vertices.rows() <= nr) return;
    // The narrowest knot span decides (knots inserted locally make some narrower than the rest).
    const auto narrowest = [](const std::vector<double>& interior, int control) {
      if (interior.empty()) return 1.0 / (control - 3);
      double w = std::min(interior.front(), 1 - interior.back());
      for (size_t k = 1; k < interior.size(); ++k) w = std::min(w, interior[k] - interior[k - 1]);
      return w;
    };
    // Cells refined locally (THB) are halved per level.
    int levels = 0;
    for (const auto& c : fo.refinedCells) levels = std::max(levels, c[0] + 1);
    const double span = std::min((r.extension.u1 - r.extension.u0) * narrowest(fo.knotsU, fo.controlU),
                                 (r.extension.v1 - r.extension.v0) * narrowest(fo.knotsV, fo.controlV)) / (1 << levels);
    if (r.extension.spacing > 0.5 * span) {
      DomainExtensionOptions eo = o.extension;
      eo.continueSurface = false;
      eo.spacing = span / 3;
      eo.clearance = 0.5 * firstSpacing;
      eo.marginLayers = 0;
      eo.marginWidth = firstMargin;
      r.extension = extendedAt(eo);
    }
    TensorFitOptions so = fo;
    so.smoothing = o.extensionSmoothing;
    so.parameterCorrections = 0;
    so.u0 = r.extension.u0, so.u1 = r.extension.u1, so.v0 = r.extension.v0, so.v1 = r.extension.v1;
    const BSplineSurface smooth = fitTensorProduct(region.vertices, p.uv, region, p.uv, so).surface;
    for (Eigen::Index k = nr; k < r.extension.mesh.vertices.rows(); ++k)
      r.extension.mesh.vertices.row(k) = smooth.point(r.extension.uv(k, 0), r.extension.uv(k, 1)).transpose();
    if (r.extension.spacing < firstSpacing) fo.extraWeight *= std::pow(r.extension.spacing / firstSpacing, 2);
  };
  auto fitWith = [&](TensorFitOptions fo) {
    if (!extended) return fitTensorProduct(region.vertices, p.uv, region, p.uv, fo);
    sampleExtensionFor(fo);
    return fitTensorProduct(r.extension.mesh.vertices, r.extension.uv, region, p.uv, fo);
  };
  TensorFitOptions fo = o.fit;
  if (o.maxControl > 0 && p.width > 0 && p.height > 0) {
    // Chosen by the data: the control cells start square, the larger count along the longer
    // side. 12 x 12 over a 10:1 strip put 12 control points across 0.77 units of noisy scan,
    // which the fit followed (data max against the truth 2.1e-2, ten times the noise).
    // The domain is the rectangle and whatever of the map lies past it (stretches left free,
    // an L's other arm beyond a held inner leg).
    const double width = std::max(p.width, p.uv.col(0).maxCoeff()) - std::min(0.0, p.uv.col(0).minCoeff());
    const double height = std::max(p.height, p.uv.col(1).maxCoeff()) - std::min(0.0, p.uv.col(1).minCoeff());
    // A margin (reach) widens the domain, and the counts grow with it, so that the knots are as
    // fine over the region as without: spread over a domain 40% larger, a bitten wavy field's
    // fit missed by three times more and its extension was given up with the margin.
    const double margin = o.extend ? firstMargin : 0.0;
    const int most = margin > 0 ? static_cast<int>(std::ceil(std::max(fo.controlU, fo.controlV) * (std::max(width, height) + 2 * margin) /
                                                             std::max(width, height)))
                                : std::max(fo.controlU, fo.controlV);
    const double ratio = (std::min(width, height) + 2 * margin) / (std::max(width, height) + 2 * margin);
    const int fewer = std::max(4, static_cast<int>(std::ceil(most * ratio)));
    fo.controlU = width >= height ? most : fewer;
    fo.controlV = width >= height ? fewer : most;
  }
  r.fit = fitWith(fo);
  if (o.extend) {
    // The extension only supplies data where the region has none; where it pulls the fit off the
    // region's own data instead, it has failed (a G2 extension of a noisy boundary into a thin
    // strip, a Cauchy problem, swung 0.87 of the diagonal away and the fit missed by 0.40). The
    // fit without it, at the same control points, tells: an extended fit whose data RMS or max
    // exceeds twice the bare fit's (the max: a failure is often local, a G1 extension into the
    // same strip left the RMS within 8% and the max 3.2 times the bare fit's) is tried at G1,
    // then left without extension, with a warning.
    // Over the same knots: with a margin (reach) the extension's domain is wider than the
    // region's, and the bare fit over the region alone, its knots finer there, gave the margin up.
    TensorFitOptions bo = fo;
    if (firstMargin > 0) bo.u0 = r.extension.u0, bo.u1 = r.extension.u1, bo.v0 = r.extension.v0, bo.v1 = r.extension.v1;
    const TensorFitResult bare = fitTensorProduct(region.vertices, p.uv, region, p.uv, bo);
    // Within the tolerance it has pulled nothing off: with parameter correction the bare fit of
    // a clean region reaches 1e-6, and twice that is no failure (the extension was given up on
    // clean regions, and their weak control points came back).
    const auto fails = [&](const TensorFitResult& f) {
      return f.dataMax > o.relativeTolerance && (f.dataRms > 2 * bare.dataRms || f.dataMax > 2 * bare.dataMax);
    };
    if (fails(r.fit)) {
      char line[200];
      const std::string which = o.extensionSource == LabeledFitOptions::ExtensionSource::Continuation
                                    ? "G" + std::to_string(o.extension.order - 1) + " extension"
                                    : "extension sampled from the thin-plate fit";
      std::snprintf(line, sizeof line, "the %s pulled the fit off the region's data (max %.2e, rms %.2e against %.2e, %.2e without it)",
                    which.c_str(), r.fit.dataMax, r.fit.dataRms, bare.dataMax, bare.dataRms);
      std::string why = line;
      bool kept = false;
      if (o.extension.order > 2 && o.extensionSource == LabeledFitOptions::ExtensionSource::Continuation) {
        DomainExtensionOptions lower = o.extension;
        lower.order = 2;
        r.extension = extendedAt(lower);
        r.fit = fitWith(fo);
        kept = !fails(r.fit);
        why += kept ? "; extended at G1 instead" : "; so did G1";
      }
      if (!kept) {
        r.extension = DomainExtension{};
        extended = false;
        r.fit = firstMargin > 0 ? fitTensorProduct(region.vertices, p.uv, region, p.uv, fo) : bare;
        why += "; fitted without extension";
      }
      r.warnings.push_back(why);
    }
  }
  const double diagonal = (region.vertices.colwise().maxCoeff() - region.vertices.colwise().minCoeff()).norm();
  r.noise = diagonal > 0 ? p.noise.sigma / diagonal : 0;
  const Eigen::MatrixX3d normals = vertexNormals(region);
  const auto residualOf = [&](const TensorFitResult& f) {
    Eigen::VectorXd residual(region.vertices.rows());
    for (Eigen::Index i = 0; i < residual.size(); ++i)
      residual(i) = normals.row(i).dot(f.surface.point(f.regionUV(i, 0), f.regionUV(i, 1)).transpose() - region.vertices.row(i));
    return residual;
  };
  const auto biasOf = [&](const TensorFitResult& f) {
    ResidualBias b = residualBias(region, residualOf(f));
    b.max = diagonal > 0 ? b.max / diagonal : 0;
    return b;
  };
  auto describe = [](const TensorFitOptions& f, const TensorFitResult& t, const ResidualBias& b) {
    char line[200];
    std::snprintf(line, sizeof line, "%dx%d: data max %.2e, rms %.2e, bias %.2e, %d weak, log10 condition %.1f", f.controlU, f.controlV,
                  t.dataMax, t.dataRms, b.max, t.weakControlPoints, t.log10Condition);
    std::string out = line;
    if (!f.refinedCells.empty())
      out.insert(out.find(':'), " + " + std::to_string(f.refinedCells.size()) + " cells refined (" + std::to_string(t.unknowns) + " functions)");
    return out;
  };
  ResidualBias bias = biasOf(r.fit);
  r.refinements.push_back(describe(fo, r.fit, bias));
  // Refined while the data max exceeds the tolerance, unless what is left is noise: the data rms
  // within 1.5 σ of the scan noise (mesh/scan_noise.h; more control points would follow the
  // noise, Morozov's discrepancy principle) and no neighbourhood of the region's vertices off the
  // surface by more than σ on average (fitting/residual_bias.h: where the fit cuts a bump off,
  // the rms stays near σ and the neighbourhood's mean does not). A clean region is refined as
  // long as the max falls: its misses are local (a horn, a reflex corner) and hardly move the
  // rms, which the earlier rule (stop unless the rms falls by a third) read as noise. Nor is a
  // max past 5 σ noise (the largest of 20,000 normal deviates is about 4.4 σ): a single vertex
  // missed by more, at a horn's tip or a corner, moves neither the rms nor any neighbourhood's
  // mean (measured: cone_corner_n0p05_cw stopped at 9 × 12 with max 5.6 σ, rms 1.0 σ).
  const bool noisy = noiseCouldBeTheMiss(r.noise, o);
  const int most = noisy ? std::min(o.maxControl, o.noisyMaxControl) : o.maxControl;
  const auto onlyNoiseLeft = [&] {
    if (!(r.fit.dataRms <= 1.5 * r.noise && bias.max <= r.noise && r.fit.dataMax <= 5 * r.noise)) return false;
    char line[200];
    std::snprintf(line, sizeof line, "stopped: what is left is scan noise (max within 5 σ, rms within 1.5 σ, no neighbourhood off by σ; σ %.2e of the diagonal)",
                  r.noise);
    r.refinements.push_back(line);
    return true;
  };
  // A refinement is kept where it brings no weak control point nor a condition of 1e8, and lowers
  // the data max, or the rms or the bias by a third (under noise the max is the noise's and stays;
  // the bias falls where the fit was short).
  // `then`: what follows a refinement not kept ("stopped", or the next thing tried).
  const auto keep = [&](const TensorFitOptions& next, TensorFitResult t, const std::string& then = "stopped") {
    const ResidualBias tb = biasOf(t);
    r.refinements.push_back(describe(next, t, tb));
    if (t.weakControlPoints > r.fit.weakControlPoints || !(t.log10Condition < 8)) {
      r.refinements.push_back(then + ": weak control points or ill-conditioned; the previous kept");
      return false;
    }
    if (!(t.dataMax < r.fit.dataMax) && !(t.dataRms < r.fit.dataRms * (2.0 / 3.0)) && !(tb.max < bias.max * (2.0 / 3.0))) {
      r.refinements.push_back(then + ": neither the data max, the rms nor the bias fell; the previous kept");
      return false;
    }
    // Cells refined locally can leave a boundary vertex, whose parameters the correction holds
    // back, off the new surface: the face's edge then misses it (bspline_notch_n0p05: 2.6e-3 ->
    // 4.5e-3 of the diagonal, 8.7 σ, kept for its bias and reported as missing the data).
    if (!next.refinedCells.empty() && t.dataMax > r.fit.dataMax && t.dataMax > std::max(o.relativeTolerance, 5 * r.noise)) {
      r.refinements.push_back(then + ": the data max rose past the noise; the previous kept");
      return false;
    }
    r.fit = std::move(t);
    bias = tb;
    fo = next;
    ++r.refinementsKept;
    return true;
  };
  // Where a noisy fit misses by more than the noise explains (residual_bias.h).
  const std::vector<MeshHole> boundary = findMeshHoles(region).holes;
  const auto missedVertices = [&](const TensorFitResult& t) {
    return verticesMissedPastNoise(region, boundary, residualOf(t), r.noise * diagonal);
  };
  // Under scan noise, refined locally where the fit misses (missedVertices): each such vertex's
  // finest cell and its eight neighbours are refined (THB, TensorFitOptions::refinedCells; nine
  // cells are the fewest that add a function), no cell more than localLevels times, at most
  // localRefinements steps, each kept as a refinement is. First where only single vertices miss
  // (the whole net refined for them follows the noise everywhere else: bspline_notch_n0p05 went
  // from 32 × 32 to 40 × 40 for one corner, its vertices 3.7 σ from the truth), the whole net
  // refined where that is not kept; then wherever the whole net's refinement has stopped.
  // Measured on the corpus's 86 noisy regions (docs/benchmarks.md, fifteenth round), with the
  // data error at closest points (tensor_fit.h): nearer the truth on 13 (bumps_crescent_n0p05
  // 9.1e-4 -> 4.7e-4 of the diagonal, torus_ring_n0p2_cw 2.8e-3 -> 7.6e-4), further on 2 (by 3%).
  const auto cellsToRefine = [&](const TensorFitOptions& f, const TensorFitResult& t) {
    const std::vector<char> flagged = missedVertices(t);
    const Eigen::Index nv = region.vertices.rows();
    const ThbSpace space = refinedThbSpace(3, f.controlU - 3, f.controlV - 3, f.refinedCells);
    std::set<std::array<int, 3>> fresh;
    const BSplineSurface& s = t.surface;
    for (Eigen::Index v = 0; v < nv; ++v) {
      if (!flagged[v]) continue;
      const double fu = std::clamp((t.regionUV(v, 0) - s.knotsU.front()) / (s.knotsU.back() - s.knotsU.front()), 0.0, 1.0);
      const double fv = std::clamp((t.regionUV(v, 1) - s.knotsV.front()) / (s.knotsV.back() - s.knotsV.front()), 0.0, 1.0);
      for (int l = std::min(space.levels() - 1, o.localLevels - 1); l >= 0; --l) {
        const int i = std::min(space.cellsU(l) - 1, static_cast<int>(fu * space.cellsU(l)));
        const int j = std::min(space.cellsV(l) - 1, static_cast<int>(fv * space.cellsV(l)));
        if (!space.inDomain(l, i, j)) continue;
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            if (space.inDomain(l, i + di, j + dj) && !space.inDomain(l + 1, 2 * (i + di), 2 * (j + dj))) fresh.insert({l, i + di, j + dj});
        break;
      }
    }
    std::vector<std::array<int, 3>> out = f.refinedCells;
    out.insert(out.end(), fresh.begin(), fresh.end());
    return std::pair<std::vector<std::array<int, 3>>, size_t>{out, fresh.size()};
  };
  // Impossible: not under noise, the steps spent, knots inserted, or too few cells; Nothing: no
  // vertex misses.
  enum class Local { Impossible, Nothing, Kept, Refused };
  int localSteps = 0;
  const auto refineLocally = [&](const std::string& then) {
    if (!noisy || localSteps >= o.localRefinements || !fo.knotsU.empty() || !fo.knotsV.empty() || std::min(fo.controlU, fo.controlV) < 6)
      return Local::Impossible;
    auto [cells, added] = cellsToRefine(fo, r.fit);
    if (added == 0) return Local::Nothing;
    ++localSteps;
    TensorFitOptions next = fo;
    next.refinedCells = std::move(cells);
    return keep(next, fitWith(next), then) ? Local::Kept : Local::Refused;
  };
  const char* nothingMissed = "stopped: no neighbourhood misses by more than the scan noise explains";
  bool noiseLeft = false, nothingLeftToRefine = false;
  while (o.maxControl > 0 && r.fit.dataMax > o.relativeTolerance) {
    if ((noiseLeft = onlyNoiseLeft())) break;
    // Only the max is past the noise: where no neighbourhood misses by more than the noise
    // explains (missedVertices), a finer net only follows more of the noise (bumps_crescent_n0p05
    // 4.7e-4 of the diagonal off the truth stopped here, 9.1e-4 refined on; torus_crescent_n0p2
    // 2.3e-3 and 3.6e-3).
    if (noisy && r.fit.dataRms <= 1.5 * r.noise && bias.max <= r.noise) {
      const Local step = refineLocally("not kept, the whole net refined instead");
      if (step == Local::Kept) continue;
      if ((nothingLeftToRefine = step == Local::Nothing)) {
        r.refinements.push_back(nothingMissed);
        break;
      }
    }
    TensorFitOptions next = fo;
    next.refinedCells.clear();  // a finer uniform net; cells are refined again where it still misses
    next.controlU = std::min(most, (3 * fo.controlU + 1) / 2);
    next.controlV = std::min(most, (3 * fo.controlV + 1) / 2);
    if (next.controlU == fo.controlU && next.controlV == fo.controlV) {
      r.refinements.push_back("stopped: " + std::to_string(most) + " control points per direction at most" +
                              (noisy && most < o.maxControl ? " under scan noise" : ""));
      break;
    }
    if (!keep(next, fitWith(next))) break;
  }
  while (o.maxControl > 0 && noisy && !nothingLeftToRefine && r.fit.dataMax > o.relativeTolerance) {
    const Local step = refineLocally("stopped");
    if (step == Local::Nothing) r.refinements.push_back(nothingMissed);
    if (step != Local::Kept) break;
  }
  // Then, on a clean region, knots where the fit misses: the worst vertex's knot spans split, in u
  // and in v. Not under scan noise: there the worst vertex is mostly the noise's, and knots put
  // where it is follow it (waves_corner_n0p05_cw 1.28e-3 -> 1.89e-3 off the truth, cone_corner_n0p05_cw
  // 2.6e-4 -> 9.9e-4; no noisy region of the corpus gained its goal by them).
  const auto interior = [](const std::vector<double>& given, int control) {
    if (!given.empty()) return given;
    std::vector<double> f;
    for (int k = 1; k < control - 3; ++k) f.push_back(static_cast<double>(k) / (control - 3));
    return f;
  };
  const auto split = [](std::vector<double> f, double x) {
    double a = 0, b = 1;
    for (double k : f) {
      if (k <= x) a = k;
      else { b = k; break; }
    }
    f.insert(std::upper_bound(f.begin(), f.end(), a), 0.5 * (a + b));
    return f;
  };
  for (int step = 0; o.maxControl > 0 && !noisy && !noiseLeft && step < o.localRefinements && r.fit.dataMax > o.relativeTolerance; ++step) {
    const Eigen::Index worst = r.fit.dataMaxAt;
    const BSplineSurface& s = r.fit.surface;
    const double fu = (r.fit.regionUV(worst, 0) - s.knotsU.front()) / (s.knotsU.back() - s.knotsU.front());
    const double fv = (r.fit.regionUV(worst, 1) - s.knotsV.front()) / (s.knotsV.back() - s.knotsV.front());
    TensorFitOptions next = fo;
    next.knotsU = split(interior(fo.knotsU, fo.controlU), std::clamp(fu, 0.0, 1.0));
    next.knotsV = split(interior(fo.knotsV, fo.controlV), std::clamp(fv, 0.0, 1.0));
    next.controlU = static_cast<int>(next.knotsU.size()) + 4;
    next.controlV = static_cast<int>(next.knotsV.size()) + 4;
    if (!keep(next, fitWith(next))) break;
  }
  r.dataBias = bias.max;
  r.metTolerance = r.fit.dataMax <= std::max(o.relativeTolerance, 5 * r.noise);
  if (!r.metTolerance) {
    char line[240];
    std::snprintf(line, sizeof line,
                  "the fit misses the region's data: max %.2e of the diagonal, above the tolerance %.2e and 5 times the scan noise (%.2e)",
                  r.fit.dataMax, o.relativeTolerance, r.noise);
    r.warnings.push_back(line);
  }
  return r;
}

}  // namespace

void checkLabeledFitOptions(const LabeledFitOptions& o) {
  if (!(o.relativeTolerance > 0)) throw Error("the relative tolerance must be positive");
  if (!(o.tolerance >= 0)) throw Error("the tolerance must be zero (the relative tolerance) or positive");
  if (o.fit.controlU < 4 || o.fit.controlV < 4) throw Error("a cubic fit needs at least 4 control points a direction");
  if (o.maxControl != 0 && o.maxControl < std::max(o.fit.controlU, o.fit.controlV))
    throw Error("maxControl (the most control points a direction) must be 0 (exactly the start's) or at least the larger of controlU and controlV");
  if (!(o.fit.smoothing >= 0 && o.extension.fairness >= 0 && o.parameterization.framePlacement >= 0 && o.extension.meshFairness >= 0 &&
        o.extensionSmoothing >= 0))
    throw Error("the weights (smoothing, fairness, frame placement, mesh fairness) must be zero or positive");
  if (!(o.reach >= 0 && o.reach <= 10)) throw Error("the reach past the domain must be between 0 and 10 times its larger side");
  if (o.localRefinements < 0 || o.localLevels < 0) throw Error("the local refinements and localLevels must be zero (none) or positive");
  if (o.extend && o.extensionSource == LabeledFitOptions::ExtensionSource::SmoothFit &&
      (o.extension.meshFairness > 0 || o.extension.paperIsocurves))
    throw Error("mesh fairness and the paper's isocurves shape the continuation extension (G2 or G1), not the fitted one: "
                "ask for extension G2 or G1 with them");
}

LabeledFitResult fitLabeled(const TriangleMesh& region, const std::vector<LabeledSegment>& segments, const LabeledFitOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  checkLabeledFitOptions(options);
  LabeledFitOptions o = options;
  if (const double diagonal = boundingDiagonal(region.vertices); o.tolerance > 0 && diagonal > 0) o.relativeTolerance = o.tolerance / diagonal;
  const LabeledParameterization labeled = parameterizeLabeled(region, segments, o.parameterization);
  LabeledFitResult r;
  try {
    r = fitOnMap(region, labeled, o);
  } catch (const Error& e) {
    // The labeled map could not be fitted at all (its boundary crosses itself in the domain, so
    // no extension can be built: a noisy ring on a cone, its inner loop pressed between held
    // sides): the relaxed map is the repair, and the labeled map's own error stands where the
    // relaxed one fails too.
    if (!o.relaxLabels) throw;
    try {
      r = fitOnMap(region, relaxLabels(region, segments, labeled, o.parameterization), o);
    } catch (const Error&) {
      throw e;
    }
    r.labelsRelaxed = true;
    r.warnings.insert(r.warnings.begin(), std::string("the labeled map could not be fitted (") + e.what() +
                                              "); the labels were relaxed (the region's free flattening, turned as the labels say)");
  }
  // A fit that does all that is asked of it: the data within the tolerance (or the noise), no
  // weak control point, a condition below 1e8, a valid face.
  const auto sound = [](const LabeledFitResult& f) {
    return f.metTolerance && f.fit.weakControlPoints == 0 && f.fit.log10Condition < 8 && f.fit.valid;
  };
  // Under scan noise a sound fit may still follow the noise: each refinement adds control points
  // and each of them follows it more (bspline_ring_n0p2, 0.2% noise: refined to 40 × 40 on its
  // labeled map, 3.4 σ off the truth; 21 × 21 on the relaxed map, 2.5 σ). Where the labeled map
  // needed refinement and the noise, not the tolerance, decides soundness, the relaxed map is
  // tried too; of two sound fits the one with fewer control points is kept, since both meet the
  // data within the noise and fewer degrees of freedom follow less of it.
  const auto controlPoints = [](const LabeledFitResult& f) { return static_cast<long>(f.fit.unknowns); };
  const bool noiseDecides = noiseCouldBeTheMiss(r.noise, o) && r.refinementsKept > 0;
  if (o.relaxLabels && !r.labelsRelaxed && (!sound(r) || noiseDecides)) {
    // The labeled map is singular where labels press a boundary that turns onto a straight side
    // (a crescent's inner arc, a slot's walls, an L's inner corner under the bounding-box rule),
    // and no tensor-product surface of reasonable size follows it there; or it leaves corners of
    // the rectangle the extension cannot fill (weak control points). The free flattening, oriented
    // by the labels, is tried, and kept where it does all that is asked and the labeled fit does
    // not, or, neither doing it, where it meets the data better without more weak control points,
    // a worse condition or an invalid face.
    char line[400];
    try {
      LabeledFitResult relaxed = fitOnMap(region, relaxLabels(region, segments, labeled, o.parameterization), o);
      const TensorFitResult &a = r.fit, &b = relaxed.fit;
      const bool heldSound = sound(r), relaxedSound = sound(relaxed);
      const bool better = heldSound ? relaxedSound && controlPoints(relaxed) < controlPoints(r)
                                    : relaxedSound || (b.dataMax < a.dataMax && b.weakControlPoints <= a.weakControlPoints &&
                                                       (b.log10Condition < 8 || !(a.log10Condition < 8)) && (b.valid || !a.valid));
      if (heldSound)
        std::snprintf(line, sizeof line,
                      "the labeled map's fit meets the data within the scan noise with %ld control points (max %.2e of the diagonal); "
                      "with the labels relaxed (the region's free flattening, turned as the labels say): %ld, max %.2e%s: %s",
                      static_cast<long>(controlPoints(r)), a.dataMax, static_cast<long>(controlPoints(relaxed)), b.dataMax,
                      relaxedSound ? "" : ", not sound",
                      better ? "the relaxed fit, following less of the noise, is kept" : "the labeled fit is kept");
      else
        std::snprintf(line, sizeof line,
                      "the labeled map's fit %s (max %.2e of the diagonal, %d weak control points); with the labels relaxed (the "
                      "region's free flattening, turned as the labels say): max %.2e, %d weak: %s",
                      r.metTolerance ? "falls short" : "misses the data", a.dataMax, a.weakControlPoints, b.dataMax, b.weakControlPoints,
                      better ? "the relaxed fit is kept" : "the labeled fit is kept");
      if (better) {
        relaxed.labelsRelaxed = true;
        relaxed.warnings.insert(relaxed.warnings.begin(), line);
        r = std::move(relaxed);
      } else if (heldSound) {
        r.refinements.push_back(line);  // a sound fit kept: no warning
      } else {
        // Why the relaxed fit fell short, in its own words (its extension given up, its miss).
        std::string why = line;
        for (const std::string& w : relaxed.allWarnings()) why += "; relaxed: " + w;
        r.warnings.push_back(why);
      }
    } catch (const Error& e) {
      std::snprintf(line, sizeof line, "the labels could not be relaxed (%s); the labeled fit is kept", e.what());
      r.warnings.push_back(line);
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void setExtensionByName(LabeledFitOptions& o, const std::string& name) {
  o.extend = name != "none";
  if (name == "fit") {
    o.extensionSource = LabeledFitOptions::ExtensionSource::SmoothFit;
  } else if (name == "G2" || name == "G1") {
    o.extensionSource = LabeledFitOptions::ExtensionSource::Continuation;
    o.extension.order = name == "G2" ? 3 : 2;
  } else if (name != "none") {
    throw Error("the extension must be fit, G2, G1 or none, got '" + name + "'");
  }
}

std::string extensionName(const LabeledFitOptions& o) {
  if (!o.extend) return "none";
  if (o.extensionSource == LabeledFitOptions::ExtensionSource::SmoothFit) return "fit";
  return o.extension.order == 2 ? "G1" : "G2";
}

std::vector<std::string> LabeledFitResult::allWarnings() const {
  std::vector<std::string> all = parameterization.warnings;
  all.insert(all.end(), warnings.begin(), warnings.end());
  return all;
}

Outcome LabeledFitResult::outcome() const {
  Outcome o;
  o.warnings = allWarnings();
  std::vector<std::string> missed;
  if (parameterization.flippedTriangles > 0) missed.push_back(std::to_string(parameterization.flippedTriangles) + " folded triangles in the map");
  if (!fit.valid) missed.push_back("the trimmed face is invalid");
  if (!metTolerance) missed.push_back("the data is missed");
  o.status = missed.empty() ? Status::Ok : Status::Warned;
  char line[120];
  std::snprintf(line, sizeof line, "%dx%d control points, data max %.2e of the diagonal", fit.surface.numU(), fit.surface.numV(), fit.dataMax);
  o.message = line;
  if (fit.unknowns != fit.surface.numU() * fit.surface.numV())
    o.message += " (" + std::to_string(fit.unknowns) + " of them free: cells refined locally)";
  for (const auto& m : missed) o.message += "; " + m;
  return o;
}

std::string LabeledFitResult::toJson() const {
  JsonWriter j;
  j.beginObject();
  writeOutcomeFields(j, outcome());
  j.field("width", parameterization.width)
      .field("height", parameterization.height)
      .field("frame_degree", parameterization.frame.degree)
      .field("frame_max_deviation", parameterization.frame.maxDeviation)
      .field("flipped_triangles", parameterization.flippedTriangles)
      .field("arap_energy", parameterization.arapEnergy)
      .field("extended_vertices", static_cast<int>(extension.mesh.vertices.rows()) - extension.regionVertices)
      .field("control_points_u", fit.surface.numU())
      .field("control_points_v", fit.surface.numV())
      .field("unknowns", fit.unknowns)
      .field("data_max", fit.dataMax)
      .field("data_rms", fit.dataRms)
      .field("weak_control_points", fit.weakControlPoints)
      .field("log10_condition", fit.log10Condition)
      .field("parameter_corrections", fit.correctionRounds)
      .field("data_bias", dataBias)
      .field("noise_estimate", noise)
      .field("met_tolerance", metTolerance)
      .field("labels_relaxed", labelsRelaxed)
      .field("face_valid", fit.valid)
      .field("seconds", seconds)
      .field("refinements", refinements)
      .field("warnings", allWarnings())
      .endObject();
  return j.str();
}

std::vector<LabeledSegment> parseLabelsJson(const std::string& text, const std::string& name) {
  const JsonValue root = parseJson(text, name);
  const JsonValue* segs = root.find("segments");
  if (!segs || segs->type != JsonValue::Type::Array)
    throw Error("'" + name + "' needs {\"segments\": [{\"label\": \"N\", \"vertices\": [i, j, ...]}, ...]}");
  std::vector<LabeledSegment> out;
  for (size_t k = 0; k < segs->array.size(); ++k) {
    const JsonValue& s = segs->array[k];
    const std::string who = "'" + name + "' segment " + std::to_string(k + 1);
    const JsonValue* label = s.find("label");
    const JsonValue* vertices = s.find("vertices");
    if (!label || label->type != JsonValue::Type::String) throw Error(who + " has no \"label\" string");
    if (!vertices || vertices->type != JsonValue::Type::Array) throw Error(who + " has no \"vertices\" list");
    LabeledSegment seg{Side::South, {}};
    const std::string& l = label->string;
    if (l == "N" || l == "North") seg.side = Side::North;
    else if (l == "E" || l == "East") seg.side = Side::East;
    else if (l == "S" || l == "South") seg.side = Side::South;
    else if (l == "W" || l == "West") seg.side = Side::West;
    else throw Error(who + ": label '" + l + "' is not N, E, S or W");
    for (const JsonValue& v : vertices->array) {
      if (v.type != JsonValue::Type::Number || v.number != std::floor(v.number) || v.number < 0 || v.number > 2147483647.0)
        throw Error(who + ": vertex indices are non-negative integers (0-based)");
      seg.vertices.push_back(static_cast<int>(v.number));
    }
    out.push_back(seg);
  }
  return out;
}

}  // namespace holefill
