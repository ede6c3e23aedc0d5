#include "options/mesh_fill_schema.h"

#include <cmath>

namespace holefill {

namespace {

using O = MeshFillOptions;

OptionBinding<O> triangulationOption() {
  OptionField f{"triangulation", "--triangulation", OptionKind::Choice, "",
                "the initial triangulation: the paper's minimum-angle ear cutting (angle; better across creases), Liepa's "
                "minimum-dihedral program (dihedral; better on smooth curved holes), or per hole (auto: angle where a crease "
                "of the surrounding mesh reaches the hole)",
                {"angle", "dihedral", "auto"}};
  return {f,
          [](const O& o) {
            return std::string(o.initial == O::Triangulation::MinDihedral ? "dihedral" : o.initial == O::Triangulation::Auto ? "auto" : "angle");
          },
          [f](O& o, const std::string& t) {
            const std::string& c = checkOptionChoice(f, t);
            o.initial = c == "dihedral" ? O::Triangulation::MinDihedral : c == "auto" ? O::Triangulation::Auto : O::Triangulation::MinAngle;
          }};
}

// A preset over the fields below it in the schema (which, set after it, still override it).
OptionBinding<O> modeOption() {
  OptionField f{"mode", "--mode", OptionKind::Choice, "",
                "ours (the defaults below) or paper: Hu et al.'s pipeline exactly (minimum-angle triangulation, refinement, "
                "flat placement, no quality passes, bilateral filter with the paper's sigma_c = 0.1 d_v, no crossing check), "
                "for comparing with the paper's Table 1",
                {"ours", "paper"}};
  return {f, [](const O& o) { return std::string(isPaperPipeline(o) ? "paper" : "ours"); },
          [f](O& o, const std::string& t) {
            if (checkOptionChoice(f, t) == "paper") {
              o = paperPipeline(o);
              return;
            }
            MeshFillOptions d;  // ours: the defaults, keeping what says which holes and how far
            d.maxBoundary = o.maxBoundary, d.holes = o.holes, d.weld = o.weld, d.progress = o.progress;
            o = d;
          }};
}

}  // namespace

const OptionSchema<MeshFillOptions>& meshFillSchema() {
  static const OptionSchema<O> s = [] {
    const OptionField refine =
        flagField("refine", "--no-refine", false, "refine the new triangles to the surrounding density (off: the bare initial triangulation)");
    OptionField normals{"alongNormals", "", OptionKind::Bool, "", "the shape placement moves vertices along their normals only"};
    return OptionSchema<O>{
        modeOption(),
        integerOption<O>(rangedField("maxBoundary", "--max-boundary", "boundary vertices",
                               "holes with more boundary vertices stay open, e.g. the border of an open scan (0: no limit)", 0, 2e9),
                         [](O& o) -> int& { return o.maxBoundary; }),
        triangulationOption(),
        boolOption<O>(refine, [](O& o) -> bool& { return o.refine; }),
        numberOption<O>(rangedField("densityFactor", "--density-factor", "relative",
                              "α of the refinement: a triangle is split while α times the distance from its centroid to a corner "
                              "exceeds the spacing there (√2 matches the surrounding mesh; larger: denser)", 0, INFINITY, true),
                        [](O& o) -> double& { return o.refinement.densityFactor; }),
        integerOption<O>(rangedField("shapeOrder", "--shape-order", "",
                               "the shape the new vertices are placed on first: 0 flat (the paper's), 1 membrane, 2 thin plate, "
                               "3 minimum variation", 0, 3),
                         [](O& o) -> int& { return o.shape.order; }),
        integerOption<O>(rangedField("shapePasses", "--shape-passes", "passes", "solve, relax edges in the new shape, solve again ...", 1, 100),
                         [](O& o) -> int& { return o.shape.passes; }),
        boolOption<O>(normals, [](O& o) -> bool& { return o.shape.alongNormals; }),
        integerOption<O>(rangedField("smoothIterations", "--smooth-iterations", "sweeps",
                               "tangential smoothing sweeps of the quality pass (0: off)", 0, 1000),
                         [](O& o) -> int& { return o.quality.smoothing.iterations; }),
        integerOption<O>(rangedField("fairIterations", "--fair-iterations", "iterations", "bilateral fairing iterations (0: off)", 0, 1000),
                         [](O& o) -> int& { return o.fairing.iterations; }),
        numberOption<O>(rangedField("closenessScale", "--closeness-scale", "of the local spacing", "σ_c of the bilateral filter", 0, INFINITY, true),
                        [](O& o) -> double& { return o.fairing.closenessScale; }),
        numberOption<O>(rangedField("featureScale", "--feature-scale", "of the local spacing", "σ_s of the bilateral filter", 0, INFINITY, true),
                        [](O& o) -> double& { return o.fairing.featureScale; }),
        boolOption<O>(flagField("checkCrossings", "--no-crossing-check", false,
                                "test each hole's patch exactly for triangles crossing each other or the surface, and fill it "
                                "again plainer until none does (off: the paper's pipeline as it is)"),
                      [](O& o) -> bool& { return o.checkCrossings; }),
        numberOption<O>(rangedField("weld", "--weld", "of the diagonal",
                              "merge vertices closer than this first, so that seams of duplicated vertices close and only the "
                              "real holes are filled (hole numbers then count on the merged mesh; 0: the mesh as it is)", 0, 0.01),
                        [](O& o) -> double& { return o.weld; }),
    };
  }();
  return s;
}

}  // namespace holefill
