// The options of labeled fitting (fitting/labeled_fit.h's LabeledFitOptions) as every door offers
// them (mesh-extension.md): the control points to start from and how far refinement may go, the
// extension to the four-sided domain and the weights that shape it (the paper's isocurve and mesh
// fairness, the frame placement, the fit's thin plate), the data tolerance, which labeled
// stretches are left free, whether the labels may be relaxed, and how far the surface reaches.
// The cross-field rules (maxControl against the start, fairness terms only with a continuation)
// are checkLabeledFitOptions', run by fitLabeled.
#pragma once

#include "fitting/labeled_fit.h"
#include "options/option_schema.h"

namespace holefill {

const OptionSchema<LabeledFitOptions>& labeledFitSchema();

}  // namespace holefill
