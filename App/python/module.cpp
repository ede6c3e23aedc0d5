// HoleFillApp: the Python door into the core (DESIGN.md). Thin by design:
// shapes arrive and leave as BREP text, reports leave as JSON text (rendered
// once, in the core), errors leave as HoleFillApp.HoleFillError. OCCT and core
// exceptions are caught here so FreeCAD never goes down with a bad input.
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "brep/continuity_report.h"
#include "brep/hole_detection.h"
#include "brep/sample_models.h"
#include "brep/shape_io.h"
#include "fill/hole_fill.h"
#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "learn/learn_library.h"

namespace py = pybind11;
using namespace holefill;

namespace {

template <class F>
auto guarded(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Standard_Failure& e) {
    throw Error(std::string("OpenCASCADE failed: ") + e.GetMessageString());
  }
}

py::tuple fill(const std::string& brep, const std::vector<int>& edges, const std::string& method,
               const std::string& continuity, double tolerance, double angularTolerance, double curvatureTolerance,
               int maxControlPoints, const std::function<bool(double)>& progress, bool sew) {
  return guarded([&] {
    const TopoDS_Shape model = shapeFromBrepString(brep);
    HoleFillOptions o;
    o.method = paramMethodFromString(method);
    o.continuity = continuityFromString(continuity);
    o.tolerance = tolerance;
    o.angularTolerance = angularTolerance;
    o.curvatureTolerance = curvatureTolerance;
    if (maxControlPoints > 0) o.solver.maxControlPoints = maxControlPoints;
    o.progress = progress;
    o.sew = sew;
    const HoleFillResult r = fillHole(model, edges, o);
    const std::string face = r.face.IsNull() ? "" : shapeToBrepString(r.face);
    const std::string shape = r.shape.IsNull() ? "" : shapeToBrepString(r.shape);
    return py::make_tuple(py::bytes(face), py::bytes(shape), toJson(r));
  });
}

std::string report(const std::string& faceBrep, const std::string& modelBrep, const std::vector<int>& edges) {
  return guarded([&] {
    const TopoDS_Shape face = shapeFromBrepString(faceBrep), model = shapeFromBrepString(modelBrep);
    TopoDS_Face f;
    int faces = 0;
    for (TopExp_Explorer ex(face, TopAbs_FACE); ex.More(); ex.Next(), ++faces) f = TopoDS::Face(ex.Current());
    if (faces != 1) throw Error("continuityReport needs exactly one face, got " + std::to_string(faces));
    HoleDetectionOptions d;
    d.includeOuterBoundary = true;
    const HoleDetectionResult detection = detectHoles(model, d);
    const Hole& hole = holeContainingEdges(detection, edges);
    const ContinuityReport r = continuityReport(f, hole);
    JsonWriter j;
    j.beginObject();
    writeJsonFields(j, r);
    j.endObject();
    return j.str();
  });
}

}  // namespace

PYBIND11_MODULE(HoleFillApp, m) {
  m.doc() = "HoleFill core: N-sided hole filling with trimmed B-spline faces (BREP text in and out, JSON reports)";
  static py::exception<Error> exc(m, "HoleFillError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      exc(e.what());
    } catch (const Standard_Failure& e) {
      exc((std::string("OpenCASCADE failed: ") + e.GetMessageString()).c_str());
    }
  });
  m.def("findHoles", [](const std::string& brep, bool includeOuter, double cornerAngleDeg) {
    return guarded([&] {
      HoleDetectionOptions o;
      o.includeOuterBoundary = includeOuter;
      o.cornerAngleDeg = cornerAngleDeg;
      return toJson(detectHoles(shapeFromBrepString(brep), o));
    });
  }, py::arg("brep"), py::arg("includeOuter") = false, py::arg("cornerAngleDeg") = 5.0,
     "Holes of a BREP shape as JSON text.");
  m.def("fillHole", &fill, py::arg("brep"), py::arg("edges"), py::arg("method") = "auto", py::arg("continuity") = "G1",
        py::arg("tolerance") = 0.0, py::arg("angularTolerance") = 1e-3, py::arg("curvatureTolerance") = 0.1,
        py::arg("maxControlPoints") = 0, py::arg("progress") = std::function<bool(double)>(), py::arg("sew") = true,
        "Fill the hole holding the given 1-based edge indices: (face BREP, sewn model BREP, report JSON).");
  m.def("uvtranSurface", [](const std::string& brep, const std::vector<int>& edges, const std::string& weights) {
    return guarded([&] {
      HoleFillOptions o;
      o.parameterization.uvtranWeights = weights;
      const BSplineSurface s = uvtranProjectionSurface(shapeFromBrepString(brep), edges, o);
      return py::bytes(shapeToBrepString(BRepBuilderAPI_MakeFace(toOcct(s), 1e-7).Face()));
    });
  }, py::arg("brep"), py::arg("edges"), py::arg("weights") = "",
     "BREP of UVTran's projection surface (a face on its whole domain) for the hole holding the given edges.");
  m.def("learnInfo", [] {
    try {
      return std::string(learn::learnLibrary().info()) + " from " + learn::learnLibrary().path;
    } catch (const Error& e) {
      return std::string("unavailable: ") + e.what();
    }
  }, "The learned-model backend (loads libtorch on first call).");
  m.def("continuityReport", &report, py::arg("faceBrep"), py::arg("modelBrep"), py::arg("edges"),
        "G0/G1/G2 of a face against the hole of the model holding the given edges, as JSON.");
  m.def("sampleModel", [](const std::string& name) {
    return guarded([&] { return py::bytes(shapeToBrepString(samples::byName(name))); });
  }, py::arg("name"), "BREP text of a built-in sample model.");
  m.def("sampleNames", &samples::names);
  m.def("ccHole", [](int valence, int rings, double bend, double jitter, unsigned seed) {
    return guarded([&] { return py::bytes(shapeToBrepString(samples::ccExtraordinaryHole(valence, rings, bend, 10.0, jitter, seed))); });
  }, py::arg("valence"), py::arg("rings") = 4, py::arg("bend") = 1.0, py::arg("jitter") = 0.0, py::arg("seed") = 0u,
     "BREP of a Catmull-Clark extraordinary-point hole ring (bicubic patches around a valence-N hole).");
  m.attr("__version__") = "0.1.0";
}
