#include "options/point_cloud_fit_schema.h"

#include <cmath>

namespace holefill {

namespace {

using O = PointCloudFitOptions;

}  // namespace

const OptionSchema<PointCloudFitOptions>& pointCloudFitSchema() {
  static const OptionSchema<O> s = [] {
    OptionField method{"method", "--method", OptionKind::Choice, "",
                       "the interior's parameterization: shape-preserving convex combinations (they cannot cross), the learned "
                       "BIDGCN network, inverse-distance or uniform weights",
                       {"shape", "bidgcn", "invdist", "uniform"}};
    return OptionSchema<O>{
        choiceOption<O>(method, [](const O& o) { return cloudWeightsName(o.parameterization.weights); },
                        [](O& o, const std::string& t) { o.parameterization.weights = cloudWeightsByName(t); }),
        numberOption<O>(rangedField("radius", "--radius", "of the unit cube",
                                    "neighbourhood radius in the cloud scaled into the unit cube (0: 3/sqrt(points))", 0, 1),
                        [](O& o) -> double& { return o.parameterization.radius; }),
        textOption<O>(OptionField{"weights", "--weights", OptionKind::Text, "",
                                  "BIDGCN's weights file (.pt, from holefill train bidgcn) for the bidgcn method; empty: the shipped one"},
                      [](O& o) -> std::string& { return o.parameterization.weightsFile; }),
        integerOption<O>(rangedField("degree", "--degree", "", "the spline's degree", 1, 7), [](O& o) -> int& { return o.fit.degree; }),
        integerOption<O>(rangedField("cells", "--cells", "cells", "cells per direction of the base level", 1, 64),
                         [](O& o) -> int& { return o.fit.baseCells; }),
        integerOption<O>(rangedField("iterations", "--iterations", "", "fit, refine and correct parameters this many times at most", 1, 30),
                         [](O& o) -> int& { return o.fit.maxIterations; }),
        numberOption<O>(rangedField("tolerance", "--tolerance", "model units",
                                    "the largest point error wanted (0: the relative tolerance of the cloud's diagonal)", 0),
                        [](O& o) -> double& { return o.tolerance; }),
        numberOption<O>(rangedField("relativeTolerance", "--relative-tolerance", "of the diagonal",
                                    "the largest point error wanted where no tolerance in model units is given", 0, 1, true),
                        [](O& o) -> double& { return o.fit.relativeTolerance; }),
        numberOption<O>(rangedField("smoothing", "--smoothing", "relative", "thin-plate term of the fit, against its data term", 0),
                        [](O& o) -> double& { return o.fit.smoothing; }),
        boolOption<O>(flagField("adaptive", "--uniform", false,
                                "refine adaptively (THB-splines) where points miss the tolerance; off: one uniform level with parameter correction"),
                      [](O& o) -> bool& { return o.adaptive; }),
        boolOption<O>(flagField("cellFaces", "--faces", true, "write one face per hierarchical cell, not the finest-level B-spline face"),
                      [](O& o) -> bool& { return o.cellFaces; }),
    };
  }();
  return s;
}

}  // namespace holefill
