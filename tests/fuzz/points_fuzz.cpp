// `param` and `fit-points`' core entries: a cloud, its boundary found when unflagged, its
// parameters, and a THB fit of two levels.
#include "fitting/cloud_boundary.h"
#include "fitting/cloud_parameterization.h"
#include "fitting/thb_fit.h"
#include "fuzz_guard.h"
#include "geometry/flagged_cloud.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  holefill::fuzz::guarded([&] {
    holefill::FlaggedCloud c = holefill::parseFlaggedCloud(holefill::fuzz::text(data, size));
    if (c.points.rows() > 2000) return;
    if (!c.flagsGiven) c.boundary = holefill::detectCloudBoundary(c.points).boundary;
    if (!c.boundaryUVGiven) c.uv = holefill::boundaryChordParameters(c.points, c.boundary);
    const holefill::CloudParameterization p = holefill::parameterizeCloud(c.points, c.boundary, c.uv);
    holefill::ThbFitOptions o;
    o.maxIterations = 2;
    o.maxLevels = 2;
    holefill::fitThb(c.points, p.uv, o);
  });
  return 0;
}
