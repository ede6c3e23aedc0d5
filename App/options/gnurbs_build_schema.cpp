#include "options/gnurbs_build_schema.h"

namespace holefill {

namespace {

using O = GnurbsBuildOptions;

}  // namespace

const OptionSchema<GnurbsBuildOptions>& gnurbsBuildSchema() {
  static const OptionSchema<O> s = [] {
    const OptionField refine = flagField("refine", "--no-refine", false,
                                         "refine the cage once (Catmull–Clark) when its EPs are too close or a crease touches an EP's "
                                         "1-ring; off: refuse such a cage");
    const OptionField merge = flagField("mergeRegular", "--merge-regular", true,
                                        "merge rectangles of regular faces into one C² B-spline face each (off: one B-rep face per patch)");
    OptionField solve{"solve", "--solve", OptionKind::Choice, "",
                      "how an EP's 1-ring is solved under the G² constraints: fair (least thin-plate change from the guidance) "
                      "or stepwise (the paper's sec. 4.1 steps)",
                      {"fair", "stepwise"}};
    return OptionSchema<O>{
        boolOption<O>(refine, [](O& o) -> bool& { return o.surface.refineWhenNeeded; }),
        integerOption<O>(rangedField("maxValence", "--max-valence", "", "extraordinary points of higher valence are refused (0: no limit)", 0, 1e6),
                         [](O& o) -> int& { return o.surface.maxValence; }),
        choiceOption<O>(solve, [](const O& o) { return std::string(o.surface.solve == G2GnurbsOptions::Solve::Stepwise ? "stepwise" : "fair"); },
                        [](O& o, const std::string& t) {
                          o.surface.solve = t == "stepwise" ? G2GnurbsOptions::Solve::Stepwise : G2GnurbsOptions::Solve::Fair;
                        }),
        boolOption<O>(merge, [](O& o) -> bool& { return o.brep.mergeRegular; }),
        integerOption<O>(rangedField("fitRounds", "--fit-rounds", "rounds", "least-squares and closest-point rounds of a fit to target points", 0, 1000),
                         [](O& o) -> int& { return o.fit.iterations; }),
    };
  }();
  return s;
}

}  // namespace holefill
