#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <GCPnts_AbscissaPoint.hxx>

#include "brep/boundary_sampling.h"
#include "brep/hole_detection.h"
#include "brep/sample_models.h"
#include "brep/shape_io.h"
#include "geometry/text_file.h"

using namespace holefill;

namespace {

// Arc lengths between consecutive samples of each edge (200 chords each), relative to their
// mean on that edge: the least and the largest.
std::pair<double, double> spacingSpread(const Hole& hole, const std::vector<BoundarySample>& samples) {
  double lo = 1e300, hi = 0;
  for (size_t a = 0; a < samples.size();) {
    size_t b = a;
    while (b < samples.size() && samples[b].edge == samples[a].edge) ++b;
    BRepAdaptor_Curve c(hole.edges[samples[a].edge].edge);
    std::vector<double> d;
    for (size_t k = a + 1; k < b; ++k) {
      double arc = 0;
      gp_Pnt prev = c.Value(samples[k - 1].t);
      for (int i = 1; i <= 200; ++i) {
        const gp_Pnt p = c.Value(samples[k - 1].t + (samples[k].t - samples[k - 1].t) * i / 200);
        arc += prev.Distance(p);
        prev = p;
      }
      d.push_back(arc);
    }
    double mean = 0;
    for (double x : d) mean += x / d.size();
    for (double x : d) lo = std::min(lo, x / mean), hi = std::max(hi, x / mean);
    a = b;
  }
  return {lo, hi};
}

}  // namespace

// Samples lie uniformly in arc length, and their weights add up to each edge's length as OCCT
// measures it.
TEST(BoundarySampling, SamplesAreUniformInArcLengthAndWeighTheEdgesLength) {
  const HoleDetectionResult holes = detectHoles(samples::panelWithHole(6));
  ASSERT_FALSE(holes.holes.empty());
  const Hole& hole = holes.holes[0];
  const std::vector<BoundarySample> s = sampleBoundary(hole);
  const auto [lo, hi] = spacingSpread(hole, s);
  EXPECT_GT(lo, 0.98);
  EXPECT_LT(hi, 1.02);
  for (size_t e = 0; e < hole.edges.size(); ++e) {
    double weight = 0;
    for (const BoundarySample& b : s)
      if (b.edge == static_cast<int>(e)) weight += b.weight;
    BRepAdaptor_Curve c(hole.edges[e].edge);
    EXPECT_NEAR(weight, GCPnts_AbscissaPoint::Length(c), 1e-4 * weight) << "edge " << e;
  }
}

// Found by fuzzing (tests/fuzz/corpus/fill/spiked_edge_slow_arc_length): one pole of a hole's
// B-spline edge thrown 100 times further out. OCCT's uniform abscissa integrated adaptively and
// spent seconds a call there (a fill took 13 s, 164 s under the sanitizers); the samples come
// from a polyline now, as uniform along the spike as along a plain edge.
TEST(BoundarySampling, AnEdgeWithASpikeIsSampledUniformly) {
  const TopoDS_Shape model = shapeFromBrepString(readFileBytes(std::string(HOLEFILL_FUZZ_CORPUS) + "/fill/spiked_edge_slow_arc_length"));
  const HoleDetectionResult holes = detectHoles(model);
  ASSERT_FALSE(holes.holes.empty());
  const std::vector<BoundarySample> s = sampleBoundary(holes.holes[0]);
  const auto [lo, hi] = spacingSpread(holes.holes[0], s);
  EXPECT_GT(lo, 0.9);
  EXPECT_LT(hi, 1.1);
}
