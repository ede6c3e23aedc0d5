#include "options/labeled_fit_schema.h"

#include <cmath>

namespace holefill {

namespace {

using O = LabeledFitOptions;

}  // namespace

const OptionSchema<LabeledFitOptions>& labeledFitSchema() {
  static const OptionSchema<O> s = [] {
    OptionField extension{"extension", "--extension", OptionKind::Choice, "",
                          "the region's extension to its four-sided domain: sampled from a thin-plate fit of the region (fit), the "
                          "paper's continuation of its boundary (G2, G1), or none (the region alone, for comparison)",
                          {"fit", "G2", "G1", "none"}};
    OptionField isocurves{"isocurves", "--isocurves", OptionKind::Choice, "",
                          "the continuation's fairness along the new grid lines (grid) or the paper's k-th differences along "
                          "the boundary and labeled isocurves (paper)",
                          {"grid", "paper"}};
    const OptionField relax = flagField("relaxLabels", "--hold-labels", false,
                                        "where the labeled map's fit misses the tolerance or has weak control points, fit over the "
                                        "region's free flattening turned as the labels say, if that is sound");
    return OptionSchema<O>{
        integerOption<O>(rangedField("controlU", "", "control points", "control points along u to start from (cubic, at least 4)", 4, 200),
                         [](O& o) -> int& { return o.fit.controlU; }),
        integerOption<O>(rangedField("controlV", "", "control points", "control points along v to start from (cubic, at least 4)", 4, 200),
                         [](O& o) -> int& { return o.fit.controlV; }),
        integerOption<O>(rangedField("maxControl", "--max-ctrl", "control points",
                               "control points are refined up to this many per direction while the data max exceeds the tolerance "
                               "(40 at most where scan noise could be the miss; 0: exactly the start's)",
                               0, 200),
                         [](O& o) -> int& { return o.maxControl; }),
        numberOption<O>(rangedField("tolerance", "--tolerance", "model units",
                                    "the data max that ends the refinement (0: the relative tolerance of the region's diagonal)", 0),
                        [](O& o) -> double& { return o.tolerance; }),
        numberOption<O>(rangedField("relativeTolerance", "--relative-tolerance", "of the diagonal",
                                    "the data max that ends the refinement where no tolerance in model units is given", 0, 1, true),
                        [](O& o) -> double& { return o.relativeTolerance; }),
        choiceOption<O>(extension, [](const O& o) { return extensionName(o); }, [](O& o, const std::string& t) { setExtensionByName(o, t); }),
        integerOption<O>(rangedField("margin", "--margin", "grid layers", "grid layers added around the domain", 0, 50),
                         [](O& o) -> int& { return o.extension.marginLayers; }),
        numberOption<O>(rangedField("reach", "--reach", "of the domain's larger side",
                              "how far the untrimmed surface reaches past the domain (0: to the domain)", 0, 10),
                        [](O& o) -> double& { return o.reach; }),
        numberOption<O>(rangedField("fairness", "--fairness", "relative", "isocurve fairness of the continuation, against its polyharmonic energy", 0),
                        [](O& o) -> double& { return o.extension.fairness; }),
        choiceOption<O>(isocurves, [](const O& o) { return std::string(o.extension.paperIsocurves ? "paper" : "grid"); },
               [](O& o, const std::string& t) { o.extension.paperIsocurves = t == "paper"; }),
        numberOption<O>(rangedField("meshFairness", "--mesh-fairness", "relative",
                              "the paper's E_Mesh: how evenly the continuation's triangles are distorted from their neighbours (0: off)", 0),
                        [](O& o) -> double& { return o.extension.meshFairness; }),
        numberOption<O>(rangedField("smoothing", "--smoothing", "relative", "thin-plate term of the fit, against its data term", 0),
                        [](O& o) -> double& { return o.fit.smoothing; }),
        numberOption<O>(rangedField("framePlacement", "--frame-placement", "relative",
                              "how firmly labeled vertices keep the guiding frame's placement along their sides", 0),
                        [](O& o) -> double& { return o.parameterization.framePlacement; }),
        numberOption<O>(rangedField("releaseDepth", "--release-depth", "of the side's chord",
                              "labeled vertices deeper than this inside their side's line, past a sharp turn, are left free "
                              "(negative: every labeled vertex held)"),
                        [](O& o) -> double& { return o.parameterization.releaseDepth; }),
        boolOption<O>(relax, [](O& o) -> bool& { return o.relaxLabels; }),
    };
  }();
  return s;
}

}  // namespace holefill
