// The options of an N-sided fill (fill/hole_fill.h's HoleFillOptions) as every door offers them:
// the parameterization, the continuity asked and its three tolerances, the solver's pole budget,
// per-edge requests, crease detection, the model's own accuracy, UVTran's weights, and the two
// whole-model extras (volume, check). What a door does with the result (sew it into the model,
// report progress) is the door's, not an option of the fill.
#pragma once

#include "fill/hole_fill.h"
#include "options/option_schema.h"

namespace holefill {

const OptionSchema<HoleFillOptions>& holeFillSchema();

}  // namespace holefill
