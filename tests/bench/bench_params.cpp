// Benchmark 1 of issue 3 (uvtran.md Table 2): parameter error on the synthetic test split,
// UVTran vs MVC vs NP, side by side on the same boundaries, with time per hole. UVTran runs
// through the public path a fill uses (canonicalize, network in libholefill_learn.so, Newton
// projection); NP and MVC are given their most favourable similarity placement (see
// learn/parameter_error.h). Prints a markdown table. Usage: holefill_bench_params [N] [weights]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>

#include "geometry/error.h"
#include "geometry/surface_projection.h"
#include "learn/learn_library.h"
#include "learn/parameter_error.h"
#include "learn/uvtran.h"
#include "learn/uvtran_data.h"
#include "learn/voxel.h"

using namespace holefill;
using namespace holefill::learn;
using Clock = std::chrono::steady_clock;

namespace {
struct Stat {
  std::vector<double> raw, aligned, ms;
  int failures = 0;
  void add(double r, double a, double t) { raw.push_back(r); aligned.push_back(a); ms.push_back(t); }
};
double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / v.size();
}
double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}  // namespace

int main(int argc, char** argv) {
  const int N = argc > 1 ? std::atoi(argv[1]) : 1000;
  UvtranOptions uo;
  uo.weights = argc > 2 ? argv[2] : defaultUvtranWeights();
  uo.threads = 1;
  std::map<std::string, std::map<std::string, Stat>> stats;  // method -> family -> stat
  for (int i = 0; i < N; ++i) {
    const UvtranSample x = makeUvtranSample(uvtranSeed(UvtranSplit::Test, i));
    for (const std::string m : {"uvtran", "uvtran-single", "mvc", "np", "voxel-oracle", "uniform-knot-oracle"}) {
      Stat& all = stats[m]["all"];
      Stat& fam = stats[m][x.family];
      try {
        const auto t = Clock::now();
        std::vector<Eigen::Vector2d> uv;
        if (m == "uvtran" || m == "uvtran-single") {
          UvtranOptions o = uo;
          o.augment = m == "uvtran";
          uv = predictUvtran(x.boundary, o).uv;
        } else if (m == "voxel-oracle") {
          // The truth's poles rounded to dv = 0.01 voxel centres: the best a perfect classifier can do.
          BSplineSurface s = x.surface;
          for (int r = 0; r < s.poles.rows(); ++r)
            for (int c = 0; c < 3; ++c) s.poles(r, c) = voxelCentre(voxelIndex(s.poles(r, c), 100), 100);
          uv = projectSequence(s, x.boundary).uv;
        } else if (m == "uniform-knot-oracle") {
          // The truth's poles with uniform interior knots: what the unobservable knot jitter alone costs.
          BSplineSurface s = x.surface;
          s.knotsU = s.knotsV = clampedCubicKnots({0.2, 0.4, 0.6, 0.8});
          uv = projectSequence(s, x.boundary).uv;
        } else {
          uv = classicalParameters(x, paramMethodFromString(m));
        }
        const double ms = 1e3 * std::chrono::duration<double>(Clock::now() - t).count();
        const double raw = parameterError(uv, x.params), al = alignedParameterError(uv, x.params);
        all.add(raw, al, ms);
        fam.add(raw, al, ms);
      } catch (const Error& e) {
        ++all.failures;
        ++fam.failures;
        if (all.failures <= 3) std::fprintf(stderr, "%s on test %d: %s\n", m.c_str(), i, e.what());
      }
    }
  }
  std::printf("Parameter error on %d synthetic test holes (mean |uv - uv*|; 'aligned' = after the best similarity)\n\n", N);
  std::printf("| method | parameter error | aligned | flat | bumpy | cylinder | dome | saddle | failed | median ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string m : {"uvtran", "uvtran-single", "mvc", "np", "voxel-oracle", "uniform-knot-oracle"}) {
    auto& s = stats[m];
    const bool own = m != "mvc" && m != "np";  // in the truth's own domain
    auto v = [&](const std::string& f) { return own ? mean(s[f].raw) : mean(s[f].aligned); };
    std::printf("| %s | %s | %.3e | %.3e | %.3e | %.3e | %.3e | %.3e | %d | %.2f |\n", m.c_str(),
                own ? (std::to_string(mean(s["all"].raw)).substr(0, 8)).c_str() : "n/a (own domain)",
                mean(s["all"].aligned), v("flat"), v("bumpy"), v("cylinder"), v("dome"), v("saddle"),
                s["all"].failures, median(s["all"].ms));
  }
  std::printf("\nFamilies: raw error for uvtran/oracle, aligned error for mvc/np. uvtran averages the predictions\n"
              "from the loop and the reversed loop (test-time augmentation), uvtran-single is one pass.\n"
              "voxel-oracle: the true poles rounded to dv = 0.01 with the true knots; uniform-knot-oracle: the true\n"
              "poles with uniform knots (the knots cannot be seen in the boundary).\n"
              "Times include canonicalization and Newton projection of the 128 points, 1 torch thread.\n"
              "Weights: %s\n", uo.weights.c_str());
  return 0;
}
