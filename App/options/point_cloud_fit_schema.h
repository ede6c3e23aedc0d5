// The options of the point-cloud fit (fitting/point_cloud_fit.h's PointCloudFitOptions, bidgcn.md
// secs. 3.2 and 5) as every door offers them: how the interior is parameterized (meshless weights
// or the learned BIDGCN network, and its neighbourhood radius), the THB-spline fit (degree, base
// cells, the thin-plate term, iterations, adaptive or one uniform level), the tolerance — in the
// cloud's units, or relative to its diagonal where none is given — and the shape written (one
// face, or one per hierarchical cell). The boundary's corners are the call's data, not an option.
#pragma once

#include "fitting/point_cloud_fit.h"
#include "options/option_schema.h"

namespace holefill {

const OptionSchema<PointCloudFitOptions>& pointCloudFitSchema();

}  // namespace holefill
