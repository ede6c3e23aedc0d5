#include "options/hole_fill_schema.h"

#include <cmath>
#include <sstream>

#include "brep/edge_continuity.h"
#include "geometry/error.h"
#include "geometry/text_file.h"

namespace holefill {

namespace {

using O = HoleFillOptions;

// "x,y,z;x,y,z;..." (spaces allowed around the numbers); empty: none.
std::vector<Eigen::Vector3d> parsePointList(const std::string& text, const std::string& name) {
  std::vector<Eigen::Vector3d> out;
  std::stringstream points(text);
  std::string item;
  while (std::getline(points, item, ';')) {
    if (item.find_first_not_of(" \t") == std::string::npos) continue;
    std::stringstream coords(item);
    std::string c;
    Eigen::Vector3d p;
    int n = 0;
    while (std::getline(coords, c, ',')) {
      const size_t a = c.find_first_not_of(" \t"), b = c.find_last_not_of(" \t");
      double x = 0;
      if (n >= 3 || a == std::string::npos || !parseDouble(c.substr(a, b - a + 1), x) || !std::isfinite(x))
        throw Error(name + ": '" + item + "' is not a point x,y,z of three finite numbers");
      p(n++) = x;
    }
    if (n != 3) throw Error(name + ": '" + item + "' is not a point x,y,z of three finite numbers");
    out.push_back(p);
  }
  return out;
}

OptionBinding<O> methodOption() {
  OptionField f{"method", "--method", OptionKind::Choice, "",
                "parameterization of the trimming curve: auto (np or mvc, whichever distorts the boundary less), np (nearest plane), "
                "mvc (regular N-gon, mean value mapping), uvtran (learned projection surface; falls back to mvc, and says so)",
                {"auto", "np", "mvc", "uvtran"}};
  return {f, [](const O& o) { return toString(o.method); },
          [f](O& o, const std::string& t) { o.method = paramMethodFromString(checkOptionChoice(f, t)); }};
}

OptionBinding<O> continuityOption() {
  OptionField f{"continuity", "--continuity", OptionKind::Choice, "",
                "the most continuity any edge is asked for (creases found at the loop's corners are asked G0)", {"G0", "G1", "G2"}};
  return {f, [](const O& o) { return toString(o.continuity); },
          [f](O& o, const std::string& t) { o.continuity = continuityFromString(checkOptionChoice(f, t)); }};
}

OptionBinding<O> edgeContinuityOption() {
  OptionField f{"edgeContinuity", "--edge-continuity", OptionKind::Text, "",
                "per-edge requests by the model's 1-based edge names, e.g. Edge5=G0,Edge7=G1 (other edges: continuity)"};
  return {f,
          [](const O& o) {
            std::string s;
            for (const auto& [edge, c] : o.edgeContinuity) s += (s.empty() ? "" : ",") + ("Edge" + std::to_string(edge)) + "=" + toString(c);
            return s;
          },
          [](O& o, const std::string& t) {
            if (t.empty()) o.edgeContinuity.clear();
            else o.edgeContinuity = parseEdgeContinuity(t);
          }};
}

OptionBinding<O> pointsOption() {
  OptionField f{"points", "--points", OptionKind::Text, "",
                "points inside the hole the face passes through, model units: x,y,z;x,y,z;... (Surface Filling's vertex constraints)"};
  return {f,
          [](const O& o) {
            std::string s;
            for (const Eigen::Vector3d& p : o.points)
              s += (s.empty() ? "" : ";") + formatOptionNumber(p.x()) + "," + formatOptionNumber(p.y()) + "," + formatOptionNumber(p.z());
            return s;
          },
          [](O& o, const std::string& t) { o.points = parsePointList(t, "points"); }};
}

}  // namespace

const OptionSchema<HoleFillOptions>& holeFillSchema() {
  static const OptionSchema<O> s = [] {
    return OptionSchema<O>{
        methodOption(),
        continuityOption(),
        numberOption<O>(rangedField("tolerance", "--tolerance", "model units",
                               "G0 tolerance: the largest gap between the face and the hole's edges (0: 1e-6 of the hole's size)", 0, INFINITY, false),
                        [](O& o) -> double& { return o.tolerance; }),
        numberOption<O>(rangedField("angularTolerance", "--angular-tolerance", "radians",
                               "G1 tolerance: the largest angle between the face's and its neighbours' normals along the edges", 0, INFINITY, true),
                        [](O& o) -> double& { return o.angularTolerance; }),
        numberOption<O>(rangedField("curvatureTolerance", "--curvature-tolerance", "relative",
                               "G2 tolerance: the largest difference of normal curvature across the edges, relative to the larger", 0, INFINITY, true),
                        [](O& o) -> double& { return o.curvatureTolerance; }),
        integerOption<O>(rangedField("maxControlPoints", "--max-control-points", "poles",
                                     "the most poles the solver's refinement may reach (a cubic patch has 16 at least)", 16),
                         [](O& o) -> int& { return o.solver.maxControlPoints; }),
        edgeContinuityOption(),
        pointsOption(),
        boolOption<O>(flagField("detectCreases", "--no-crease-detection", false,
                              "ask G0 of the edges where the loop's corners show the model was sharp"),
                      [](O& o) -> bool& { return o.edges.detectCreases; }),
        boolOption<O>(flagField("modelAccuracy", "--no-model-accuracy", false,
                              "judge each edge no stricter than the model is there (its own tolerance, the angle its neighbour meets it at)"),
                      [](O& o) -> bool& { return o.modelAccuracy; }),
        textOption<O>(OptionField{"weights", "--weights", OptionKind::Text, "",
                                  "UVTran's weights file (.pt, from holefill train uvtran) for the uvtran method; empty: the shipped one"},
                      [](O& o) -> std::string& { return o.parameterization.uvtranWeights; }),
        boolOption<O>(flagField("computeVolume", "--volume", true, "also the volume of a closed result (a whole-model integration)"),
                      [](O& o) -> bool& { return o.computeVolume; }),
        boolOption<O>(flagField("checkModel", "--check-model", true, "also list every face of the input that BRepCheck finds invalid"),
                      [](O& o) -> bool& { return o.checkModel; }),
    };
  }();
  return s;
}

}  // namespace holefill
