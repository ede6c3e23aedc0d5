// The options of the G-NURBS pipeline (gnurbs/gnurbs_build.h's GnurbsBuildOptions) as every door
// offers them (g2-gnurbs.md): whether a cage whose EPs are too close is refined once or refused,
// the highest valence solved, how an EP's 1-ring is solved (fair or the paper's stepwise), the
// B-rep's merged regular rectangles, and a fit's rounds. The cage itself (knots, sharp edges,
// anchors) and the fit's target are the call's data, not options.
#pragma once

#include "gnurbs/gnurbs_build.h"
#include "options/option_schema.h"

namespace holefill {

const OptionSchema<GnurbsBuildOptions>& gnurbsBuildSchema();

}  // namespace holefill
