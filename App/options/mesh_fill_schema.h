// The options of triangle-mesh hole filling (mesh/mesh_hole_fill.h's MeshFillOptions, after Hu et
// al.) as every door offers them: which holes are too long to close, the initial triangulation,
// the density refinement and its α, the shape placement (Δᵏ order and passes) and the bilateral
// fairing (iterations, σ_c and σ_s scales). Which holes to fill is the call's, not an option.
#pragma once

#include "mesh/mesh_hole_fill.h"
#include "options/option_schema.h"

namespace holefill {

const OptionSchema<MeshFillOptions>& meshFillSchema();

}  // namespace holefill
