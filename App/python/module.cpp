// HoleFillApp: the Python door into the core (DESIGN.md). Thin by design:
// shapes arrive and leave as BREP text, reports leave as JSON text (rendered
// once, in the core), errors leave as HoleFillApp.HoleFillError. OCCT and core
// exceptions are caught here so FreeCAD never goes down with a bad input.
#include <cmath>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <array>
#include <map>
#include <optional>
#include <memory>
#include <tuple>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <pybind11/eigen.h>
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
#include "geometry/polygon2d.h"
#include "fitting/cloud_parameterization.h"
#include "fitting/point_cloud_fit.h"
#include "fitting/labeled_fit.h"
#include "gnurbs/cage_io.h"
#include "fill/adjacent_holes.h"
#include "gnurbs/gnurbs_build.h"
#include "gnurbs/sample_cages.h"
#include "inspect/inspection_render.h"
#include "learn/learn_library.h"
#include "mesh/fill_metrics.h"
#include "mesh/mesh_hole_fill.h"
#include "mesh/mesh_io.h"
#include "mesh/self_intersection.h"
#include "options/gnurbs_build_schema.h"
#include "options/hole_fill_schema.h"
#include "options/labeled_fit_schema.h"
#include "options/mesh_fill_schema.h"
#include "options/option_sets.h"
#include "options/point_cloud_fit_schema.h"

namespace py = pybind11;
using namespace holefill;

namespace {

template <class F>
auto guarded(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Standard_Failure& e) {
    throw Error(occtFailure(e));
  }
}

// An option set from a Python dict {name: value} (options/option_schema.h): values cross as text,
// checked by the schema; bools as true/false, numbers in round-trip precision.
template <class O>
O optionsFromDict(const OptionSchema<O>& schema, const py::dict& d) {
  O o;
  for (const auto& item : d) {
    const py::handle v = item.second;
    const std::string name = py::str(item.first);
    std::string text;
    if (py::isinstance<py::bool_>(v)) text = py::cast<bool>(v) ? "true" : "false";
    else if (py::isinstance<py::int_>(v)) text = std::to_string(py::cast<long long>(v));
    else if (py::isinstance<py::float_>(v)) text = formatOptionNumber(py::cast<double>(v));
    else if (py::isinstance<py::str>(v)) text = py::cast<std::string>(v);
    else throw Error(name + " must be a number, a bool or a string, got " + std::string(py::str(py::type::of(v).attr("__name__"))));
    setOption(schema, o, name, text);
  }
  return o;
}

// (BREP of the face, BREP of the sewn model, report JSON).
py::tuple fillTuple(const HoleFillResult& r) {
  const std::string face = r.face.IsNull() ? "" : shapeToBrepString(r.face);
  const std::string shape = r.shape.IsNull() ? "" : shapeToBrepString(r.shape);
  return py::make_tuple(py::bytes(face), py::bytes(shape), toJson(r));
}

// One fill of a prepared hole (HoleFill.fillHole is PreparedHole(...).fill(...)).
py::tuple fillPrepared(PreparedHole& hole, const py::dict& options, const std::function<bool(double)>& progress, bool sew) {
  return guarded([&] {
    HoleFillOptions o = optionsFromDict(holeFillSchema(), options);
    o.progress = progress;
    o.sew = sew;
    return fillTuple(hole.fill(o));
  });
}

std::unique_ptr<PreparedHole> prepare(const std::string& brep, const std::vector<int>& edges) {
  return guarded([&] { return std::make_unique<PreparedHole>(shapeFromBrepString(brep), edges); });
}

// (BREP of the two faces as a compound, BREP of the model with both, report JSON).
py::tuple fillAdjacent(const std::string& brep, const std::vector<int>& edges, const std::string& dividerBrep, const py::dict& options,
                       const std::function<bool(double)>& progress) {
  return guarded([&] {
    const TopoDS_Shape model = shapeFromBrepString(brep), divider = shapeFromBrepString(dividerBrep);
    TopTools_IndexedMapOfShape curveEdges;
    TopExp::MapShapes(divider, TopAbs_EDGE, curveEdges);
    if (curveEdges.Extent() != 1)
      throw Error("the dividing curve must be one edge; the shape given has " + std::to_string(curveEdges.Extent()));
    HoleFillOptions o = optionsFromDict(holeFillSchema(), options);
    o.progress = progress;
    const AdjacentFillResult r = fillAdjacentHoles(model, edges, TopoDS::Edge(curveEdges(1)), o);
    std::string faces;
    if (!r.first.face.IsNull() && !r.second.face.IsNull()) {
      BRep_Builder B;
      TopoDS_Compound c;
      B.MakeCompound(c);
      B.Add(c, r.first.face);
      B.Add(c, r.second.face);
      faces = shapeToBrepString(c);
    }
    return py::make_tuple(py::bytes(faces), py::bytes(r.shape.IsNull() ? "" : shapeToBrepString(r.shape)), toJson(r));
  });
}

ContinuityReport reportOnHole(const std::string& faceBrep, const std::string& modelBrep, const std::vector<int>& edges) {
  const TopoDS_Shape face = shapeFromBrepString(faceBrep), model = shapeFromBrepString(modelBrep);
  TopoDS_Face f;
  int faces = 0;
  for (TopExp_Explorer ex(face, TopAbs_FACE); ex.More(); ex.Next(), ++faces) f = TopoDS::Face(ex.Current());
  if (faces != 1) throw Error("continuityReport needs exactly one face, got " + std::to_string(faces));
  HoleDetectionOptions d;
  d.includeOuterBoundary = true;
  const HoleDetectionResult detection = detectHoles(model, d);
  return continuityReport(f, holeContainingEdges(detection, edges));
}

std::string report(const std::string& faceBrep, const std::string& modelBrep, const std::vector<int>& edges) {
  return guarded([&] {
    JsonWriter j;
    j.beginObject();
    writeJsonFields(j, reportOnHole(faceBrep, modelBrep, edges));
    j.endObject();
    return j.str();
  });
}

// Continuity report as (JSON text, samples (k x 11: x y z g0 g1 g2, the face's normal nx ny nz,
// the normal curvatures across the boundary of the face and of the support, NaN where not
// measured), edge index per sample).
py::tuple continuityTuple(const ContinuityReport& r) {
  JsonWriter j;
  j.beginObject();
  writeJsonFields(j, r);
  j.endObject();
  Eigen::MatrixXd samples(static_cast<Eigen::Index>(r.along.size()), 11);
  std::vector<int> edges;
  for (size_t i = 0; i < r.along.size(); ++i) {
    const auto& a = r.along[i];
    samples.row(static_cast<Eigen::Index>(i)) << a.point.transpose(), a.g0, a.g1, a.g2, a.normal.transpose(), a.curvatureFace,
        a.curvatureSupport;
    edges.push_back(a.edgeIndex);
  }
  return py::make_tuple(j.str(), samples, edges);
}

std::map<std::string, std::string> stringOptions(const py::dict& d) {
  std::map<std::string, std::string> m;
  for (const auto& kv : d) m[py::str(kv.first)] = py::str(kv.second);
  return m;
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
      exc(occtFailure(e).c_str());
    }
  });
  m.def("leastAreaRectangleAngle", [](const Eigen::MatrixX2d& points) {
    return guarded([&] {
      std::vector<Eigen::Vector2d> p;
      for (Eigen::Index k = 0; k < points.rows(); ++k) p.emplace_back(points.row(k).transpose());
      return leastAreaRectangleAngle(p);
    });
  }, py::arg("points"), "The angle (radians, in [0, pi/2)) by which the 2D points (n x 2), turned anticlockwise, have the "
     "least-area axis-aligned bounding rectangle (geometry/polygon2d.h).");
  m.def("findHoles", [](const std::string& brep, bool includeOuter, double cornerAngleDeg) {
    return guarded([&] {
      HoleDetectionOptions o;
      o.includeOuterBoundary = includeOuter;
      o.cornerAngleDeg = cornerAngleDeg;
      return toJson(detectHoles(shapeFromBrepString(brep), o));
    });
  }, py::arg("brep"), py::arg("includeOuter") = false, py::arg("cornerAngleDeg") = 5.0,
     "Holes of a BREP shape as JSON text.");
  py::class_<PreparedHole>(m, "PreparedHole",
                           "A hole read and found once, filled as often as asked: its boundary samples and "
                           "parameterizations are kept between fills (a Preview that changes only the method, "
                           "continuity, tolerances or edge requests pays for the solve alone).")
      .def(py::init(&prepare), py::arg("brep"), py::arg("edges"))
      .def("fill", &fillPrepared, py::arg("options") = py::dict(), py::arg("progress") = std::function<bool(double)>(),
           py::arg("sew") = true,
           "Fill it: (face BREP, sewn model BREP or empty without sew, report JSON). options: {name: value} of the "
           "fill's option set (optionSchema('fill')); those left out keep their defaults.")
      .def("computed", [](const PreparedHole& h) { return py::make_tuple(h.cache().samplings, h.cache().parameterizations); },
           "(boundary samplings, parameterizations) computed so far; the rest came from the kept ones.");
  m.def("fillHoles", [](const std::string& brep, const py::dict& options, const std::function<bool(double)>& progress) {
    return guarded([&] {
      HoleFillOptions o = optionsFromDict(holeFillSchema(), options);
      o.progress = progress;
      const std::vector<HoleFillResult> all = fillHoles(shapeFromBrepString(brep), o);
      py::list reports;
      for (const HoleFillResult& r : all) reports.append(toJson(r));
      const TopoDS_Shape& last = all.back().shape;
      return py::make_tuple(py::bytes(last.IsNull() ? "" : shapeToBrepString(last)), reports);
    });
  }, py::arg("brep"), py::arg("options") = py::dict(), py::arg("progress") = std::function<bool(double)>(),
     "Every hole, one after the other into the model the one before returned: (BREP of the model with all of them, "
     "[report JSON per hole]); it stops at the first fill that fails.");
  m.def("fillAdjacentHoles", &fillAdjacent, py::arg("brep"), py::arg("edges"), py::arg("divider"), py::arg("options") = py::dict(),
        py::arg("progress") = std::function<bool(double)>(),
        "Split the hole holding the given edges by the one edge in `divider` (BREP) and fill both sides as two "
        "faces sharing it: (BREP of the two faces, BREP of the model, report JSON).");
  m.def("uvtranSurface", [](const std::string& brep, const std::vector<int>& edges, const std::string& weights) {
    return guarded([&] {
      HoleFillOptions o;
      o.parameterization.uvtranWeights = weights;
      const BSplineSurface s = uvtranProjectionSurface(shapeFromBrepString(brep), edges, o);
      return py::bytes(shapeToBrepString(BRepBuilderAPI_MakeFace(toOcct(s), 1e-7).Face()));
    });
  }, py::arg("brep"), py::arg("edges"), py::arg("weights") = "",
     "BREP of UVTran's projection surface (a face on its whole domain) for the hole holding the given edges.");
  m.def("optionSetNames", &optionSetNames, "The option sets optionSchema describes.");
  m.def("optionSchema", [](const std::string& set) { return optionSetJson(set); }, py::arg("set"),
        "An option set's fields as JSON: [{name, flag, kind, unit, doc, choices, minimum, maximum, minimum_excluded, flag_sets, "
        "default}, ...], the defaults the core's own.");
  m.def("learnInfo", [] {
    try {
      return std::string(learn::learnLibrary().info()) + " from " + learn::learnLibrary().path;
    } catch (const Error& e) {
      return std::string("unavailable: ") + e.what();
    }
  }, "The learned-model backend (loads libtorch on first call).");
  m.def("continuityReport", &report, py::arg("faceBrep"), py::arg("modelBrep"), py::arg("edges"),
        "G0/G1/G2 of a face against the hole of the model holding the given edges, as JSON.");
  m.def("inspectionMesh", [](const std::string& brep, const std::vector<int>& faces, double maxNormalAngleDeg, long long maxVertices,
                             double timeLimit, const std::function<bool(double)>& progress) {
    return guarded([&] {
      TessellationOptions o;
      o.faces = faces;
      o.maxNormalAngle = maxNormalAngleDeg * M_PI / 180.0;
      if (maxVertices > 0) o.maxVertices = maxVertices;
      o.timeLimit = timeLimit;
      if (progress) o.progress = [&](double f) { py::gil_scoped_acquire g; return progress(f); };
      TessellationResult t;
      {
        py::gil_scoped_release release;
        t = tessellateForInspection(shapeFromBrepString(brep), o);
      }
      const InspectionMesh& m = t.mesh;
      py::dict d;
      d["points"] = m.fields.points;
      d["normals"] = m.fields.normals;
      d["k1"] = m.fields.k1;
      d["k2"] = m.fields.k2;
      d["d1"] = m.fields.d1;
      d["regular"] = std::vector<int>(m.fields.regular.begin(), m.fields.regular.end());
      d["triangles"] = Eigen::MatrixX3i(m.triangles);
      d["triangleFace"] = m.triangleFace;
      d["vertexFace"] = m.vertexFace;
      py::list edges;
      for (size_t i = 0; i < m.edgePolylines.size(); ++i) edges.append(py::make_tuple(m.edgeIndex[i], m.edgePolylines[i]));
      d["edges"] = edges;
      d["diagonal"] = m.diagonal;
      d["maxInteriorNormalAngle"] = t.maxInteriorNormalAngle;
      d["maxBoundaryNormalAngle"] = t.maxBoundaryNormalAngle;
      d["warnings"] = t.warnings;
      d["stoppedByBudget"] = t.stoppedByBudget;
      d["seconds"] = t.seconds;
      return d;
    });
  }, py::arg("brep"), py::arg("faces") = std::vector<int>(), py::arg("maxNormalAngleDeg") = 2.0, py::arg("maxVertices") = 0,
     py::arg("timeLimit") = 0.0, py::arg("progress") = nullptr,
     "Adaptive tessellation with exact per-vertex fields (points, normals, k1 >= k2, d1, ...) as a dict of arrays;\n"
     "maxVertices (0: the core's 1,000,000) and timeLimit (s, 0: none) bound it, progress(f) -> False cancels.");
  m.def("curvatureValues", [](const Eigen::MatrixX3d& normals, const Eigen::VectorXd& k1, const Eigen::VectorXd& k2,
                              const Eigen::MatrixX3d& d1, const std::string& quantity, const Eigen::Vector3d& direction) {
    return guarded([&] {
      const Eigen::Index n = normals.rows();
      if (k1.size() != n || k2.size() != n || d1.rows() != n) throw Error("curvatureValues: arrays of different lengths");
      SurfaceFields f;
      f.resize(n);
      f.normals = normals;
      f.k1 = k1;
      f.k2 = k2;
      f.d1 = d1;
      for (Eigen::Index i = 0; i < n; ++i) f.regular[static_cast<size_t>(i)] = std::isfinite(k1(i)) ? 1 : 0;
      const CurvatureQuantity q = curvatureQuantityFromString(quantity);
      return py::make_tuple(curvatureValues(f, q, direction), isSigned(q));
    });
  }, py::arg("normals"), py::arg("k1"), py::arg("k2"), py::arg("d1"), py::arg("quantity"),
     py::arg("direction") = Eigen::Vector3d(1, 0, 0), "(values, signed) of a curvature quantity per vertex.");
  m.def("colorScale", [](const Eigen::VectorXd& values, bool signedQuantity, double lowPercentile, double highPercentile,
                         py::object low, py::object high, int symmetric) {
    return guarded([&] {
      ColorScaleOptions o;
      o.lowPercentile = lowPercentile;
      o.highPercentile = highPercentile;
      o.symmetric = symmetric;
      if (!low.is_none() || !high.is_none()) {
        if (low.is_none() || high.is_none()) throw Error("a colour range by value needs both low and high");
        o.byValue = true;
        o.low = low.cast<double>();
        o.high = high.cast<double>();
      }
      const ColorScale s = makeColorScale(values, signedQuantity, o);
      Eigen::MatrixX3f colors(values.size(), 3);
      for (Eigen::Index i = 0; i < values.size(); ++i) {
        const auto c = s.color(values(i));
        colors.row(i) << c[0], c[1], c[2];
      }
      py::dict d;
      d["low"] = s.low;
      d["high"] = s.high;
      d["diverging"] = s.diverging;
      d["colors"] = colors;
      const auto ticks = s.ticks(6);
      d["ticks"] = ticks;
      std::vector<std::string> labels;
      for (double t : ticks) labels.push_back(tickLabel(t));
      d["labels"] = labels;
      Eigen::MatrixX3f ramp(64, 3);
      for (int i = 0; i < 64; ++i) {
        const auto c = s.color(s.low + (s.high - s.low) * i / 63.0);
        ramp.row(i) << c[0], c[1], c[2];
      }
      d["ramp"] = ramp;
      return d;
    });
  }, py::arg("values"), py::arg("signedQuantity"), py::arg("lowPercentile") = 2.0, py::arg("highPercentile") = 98.0,
     py::arg("low") = py::none(), py::arg("high") = py::none(), py::arg("symmetric") = -1,
     "Colour scale (low, high, diverging, per-value colors, ticks, labels, 64-step ramp) of curvature values.");
  m.def("renderImage", [](const std::string& brep, const py::dict& options, const std::string& path) {
    return guarded([&] {
      const RenderOptions o = parseRenderOptions(stringOptions(options));
      RenderResult r;
      {
        py::gil_scoped_release release;
        r = renderInspection(shapeFromBrepString(brep), o);
        if (!path.empty()) writePng(r.image, path);
      }
      return py::make_tuple(path.empty() ? py::bytes(encodePng(r.image)) : py::bytes(), toJson(r, o));
    });
  }, py::arg("brep"), py::arg("options"), py::arg("path") = "",
     "Render a zebra/curvature/shaded PNG headless: (PNG bytes or b'' when written to path, report JSON).");
  m.def("faceContinuity", [](const std::string& brep, int a, int b, int samplesPerEdge) {
    return guarded([&] {
      ContinuityOptions o;
      o.samplesPerEdge = samplesPerEdge;
      return continuityTuple(faceContinuity(shapeFromBrepString(brep), a, b, o));
    });
  }, py::arg("brep"), py::arg("faceA"), py::arg("faceB"), py::arg("samplesPerEdge") = 200,
     "Continuity of Face<faceB> against Face<faceA> along their shared edges: (JSON, samples k x 11: x y z g0 g1 g2 nx ny nz curvature across of the face and of the support, edge per sample).");
  m.def("continuityAlong", [](const std::string& faceBrep, const std::string& modelBrep, const std::vector<int>& edges) {
    return guarded([&] { return continuityTuple(reportOnHole(faceBrep, modelBrep, edges)); });
  }, py::arg("faceBrep"), py::arg("modelBrep"), py::arg("edges"),
     "Like continuityReport, with the samples: (JSON, samples k x 11: x y z g0 g1 g2 nx ny nz curvature across of the face and of the support, edge per sample).");
  m.def("meshHoles", [](const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles) {
    return guarded([&] { return toJson(findMeshHoles(TriangleMesh{vertices, triangles})); });
  }, py::arg("vertices"), py::arg("triangles"), "Boundary loops of a triangle mesh (JSON: holes longest first, topology counts).");
  m.def("weldVertices", [](const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles, double weld) {
    return guarded([&] {
      if (!(weld >= 0) || !std::isfinite(weld)) throw Error("weld: a fraction of the diagonal, 0 or more");
      VertexWeld w = weldVertices(TriangleMesh{vertices, triangles}, weld * boundingDiagonal(vertices));
      return py::make_tuple(w.mesh.vertices, w.mesh.triangles, w.mergedVertices, w.droppedTriangles);
    });
  }, py::arg("vertices"), py::arg("triangles"), py::arg("weld"),
     "Coincident vertices (within weld × the bounding-box diagonal) merged: (vertices, triangles, merged vertices, dropped "
     "triangles), as the mesh fill's weld option does first.");
  m.def("fillMeshHoles", [](const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles, const std::vector<int>& holes,
                            const py::dict& options, const std::function<bool(double)>& progress) {
    return guarded([&] {
      MeshFillOptions o = optionsFromDict(meshFillSchema(), options);
      o.holes = holes;
      if (progress) o.progress = [&](double f) { py::gil_scoped_acquire g; return progress(f); };
      MeshFillResult r;
      {
        py::gil_scoped_release release;
        r = fillMeshHoles(TriangleMesh{vertices, triangles}, o);
      }
      return py::make_tuple(r.mesh.vertices, r.mesh.triangles, r.toJson());
    });
  }, py::arg("vertices"), py::arg("triangles"), py::arg("holes") = std::vector<int>{}, py::arg("options") = py::dict(),
     py::arg("progress") = nullptr,
     "Fill holes of a triangle mesh (Hu et al.), options {name: value} of optionSchema('mesh_fill'): (vertices, triangles, "
     "report JSON); the input rows come first, unchanged.");
  m.def("selfIntersections", [](const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles, const std::vector<bool>& subject) {
    return guarded([&] {
      const TriangleMesh mesh{vertices, triangles};
      validateMesh(mesh);
      if (!subject.empty() && subject.size() != static_cast<size_t>(triangles.rows()))
        throw Error("subject: one flag per triangle, or none");
      py::gil_scoped_release release;
      const SelfIntersections r = selfIntersections(mesh, subject, SIZE_MAX);
      return std::make_pair(r.pairs, r.skippedTriangles);
    });
  }, py::arg("vertices"), py::arg("triangles"), py::arg("subject") = std::vector<bool>{},
     "Pairs of triangles that cross (exactly; at least one of each a subject, all when none given) and the triangles "
     "left out of the test (not manifold with the others): (pairs, skipped).");
  m.def("measureMeshFill", [](const Eigen::MatrixX3d& inV, const Eigen::MatrixX3i& inT, const Eigen::MatrixX3d& outV,
                              const Eigen::MatrixX3i& outT, const Eigen::MatrixX3d& gtV, const Eigen::MatrixX3i& gtT) {
    return guarded([&] {
      py::gil_scoped_release release;
      return toJson(measureFill(TriangleMesh{inV, inT}, TriangleMesh{outV, outT}, TriangleMesh{gtV, gtT}));
    });
  }, py::arg("inputVertices"), py::arg("inputTriangles"), py::arg("outputVertices"), py::arg("outputTriangles"),
     py::arg("truthVertices"), py::arg("truthTriangles"),
     "Metrics of any filler's output against its input and a ground truth (may be empty): JSON.");
  m.def("readMesh", [](const std::string& path) {
    return guarded([&] {
      const TriangleMesh mesh = readMesh(path);
      return py::make_tuple(mesh.vertices, mesh.triangles);
    });
  }, py::arg("path"), "Read .obj/.off/.ply/.stl as (vertices, triangles), with the core's validation.");
  m.def("writeMesh", [](const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles, const std::string& path) {
    return guarded([&] { writeMesh(TriangleMesh{vertices, triangles}, path); return 0; });
  }, py::arg("vertices"), py::arg("triangles"), py::arg("path"), "Write .obj/.off/.ply/.stl atomically.");
  m.def("sampleModel", [](const std::string& name) {
    return guarded([&] { return py::bytes(shapeToBrepString(samples::byName(name))); });
  }, py::arg("name"), "BREP text of a built-in sample model.");
  m.def("sampleNames", &samples::names);
  m.def("ccHole", [](int valence, int rings, double bend, double jitter, unsigned seed) {
    return guarded([&] { return py::bytes(shapeToBrepString(samples::ccExtraordinaryHole(valence, rings, bend, 10.0, jitter, seed))); });
  }, py::arg("valence"), py::arg("rings") = 4, py::arg("bend") = 1.0, py::arg("jitter") = 0.0, py::arg("seed") = 0u,
     "BREP of a Catmull-Clark extraordinary-point hole ring (bicubic patches around a valence-N hole).");
  m.def("gnurbsSurface", [](const Eigen::MatrixX3d& vertices, const Eigen::MatrixXi& quads,
                            const std::vector<std::tuple<int, int, double>>& knots, const std::vector<std::pair<int, int>>& sharpEdges,
                            const std::map<int, std::array<double, 3>>& anchors, const py::dict& options, int numberBase,
                            const std::optional<Eigen::MatrixX3d>& target) {
    return guarded([&] {
      if (quads.cols() != 4) throw Error("quads must have 4 columns (one row per quad), got " + std::to_string(quads.cols()));
      QuadCage cage;
      cage.vertices = vertices;
      cage.quads = quads;
      cage.numberBase = numberBase;
      for (const auto& [a, b, d] : knots) cage.setKnot(a, b, d);
      for (const auto& [a, b] : sharpEdges) cage.setSharp(a, b);
      for (const auto& [v, p] : anchors) cage.anchors[v] = Eigen::Vector3d(p[0], p[1], p[2]);
      const GnurbsBuildOptions o = optionsFromDict(gnurbsBuildSchema(), options);
      GnurbsBuildResult r;
      {
        py::gil_scoped_release release;
        r = buildGnurbs(cage, o, target ? &*target : nullptr);
      }
      return py::make_tuple(py::bytes(shapeToBrepString(r.brep.shape)), r.brep.sidecarJson, r.toJson(), r.cage.vertices);
    });
  }, py::arg("vertices"), py::arg("quads"), py::arg("knots") = std::vector<std::tuple<int, int, double>>{},
     py::arg("sharpEdges") = std::vector<std::pair<int, int>>{}, py::arg("anchors") = std::map<int, std::array<double, 3>>{},
     py::arg("options") = py::dict(), py::arg("numberBase") = 0, py::arg("target") = std::nullopt,
     "G² G-NURBS surface over a quad cage (0-based indices), options {name: value} of optionSchema('gnurbs'), fitted to `target` "
     "points first when given: (BREP text of the shell, faces sidecar JSON, report JSON, the cage's vertices as built: fitted, or as given).");
  m.def("readCage", [](const std::string& path) {
    return guarded([&] {
      const QuadCage c = readCage(path);
      std::vector<std::tuple<int, int, double>> knots;
      for (const auto& [key, d] : c.knots) knots.emplace_back(static_cast<int>(key & 0xffffffffu), static_cast<int>(key >> 32), d);
      std::vector<std::pair<int, int>> sharp;
      for (std::uint64_t key : c.sharp) sharp.emplace_back(static_cast<int>(key & 0xffffffffu), static_cast<int>(key >> 32));
      std::map<int, std::array<double, 3>> anchors;
      for (const auto& [v, a] : c.anchors) anchors[v] = {a.x(), a.y(), a.z()};
      return py::make_tuple(c.vertices, Eigen::MatrixXi(c.quads), knots, sharp, anchors);
    });
  }, py::arg("path"), "A quad cage OBJ (with # sharp/# knot/# anchor lines) as 0-based (vertices, quads, knots, sharp, anchors).");
  m.def("fitLabeled", [](const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles, const std::string& labelsJson,
                         const py::dict& options) {
    return guarded([&] {
      const LabeledFitOptions o = optionsFromDict(labeledFitSchema(), options);
      const std::vector<LabeledSegment> labels = parseLabelsJson(labelsJson);
      LabeledFitResult r;
      {
        py::gil_scoped_release release;
        r = fitLabeled(TriangleMesh{vertices, triangles}, labels, o);
      }
      const TopoDS_Face untrimmed = BRepBuilderAPI_MakeFace(toOcct(r.fit.surface), 1e-7).Face();
      // Previews: the guiding frame's curves (64 points per labeled side) and the extended mesh.
      py::list frame;
      const GuidingFrame& f = r.parameterization.frame;
      for (int side = 0; side < 4; ++side) {
        if (!f.labeled[side]) continue;
        Eigen::MatrixX3d pts(65, 3);
        for (int k = 0; k <= 64; ++k) pts.row(k) = f.point(static_cast<Side>(side), k / 64.0).transpose();
        frame.append(py::make_tuple("SENW"[side], pts));
      }
      return py::make_tuple(py::bytes(shapeToBrepString(r.fit.face)), py::bytes(shapeToBrepString(untrimmed)), r.toJson(), r.parameterization.uv,
                            frame, r.extension.mesh.vertices, Eigen::MatrixXi(r.extension.mesh.triangles));
    });
  }, py::arg("vertices"), py::arg("triangles"), py::arg("labelsJson"), py::arg("options") = py::dict(),
     "Labeled fitting of a trimmed mesh region, options {name: value} of optionSchema('labeled_fit'): (trimmed face BREP, untrimmed surface BREP, report JSON, uv per vertex, "
     "guiding frame [(side, points)], extended mesh vertices, extended mesh triangles).");
  m.def("parameterizeCloud", [](const Eigen::MatrixX3d& points, const std::vector<bool>& boundary, const Eigen::MatrixX2d& boundaryUV,
                                const std::string& method, double radius, const std::string& weights) {
    return guarded([&] {
      CloudParameterizationOptions o;
      o.weights = cloudWeightsByName(method);
      o.radius = radius;
      o.weightsFile = weights;
      CloudParameterization p;
      {
        py::gil_scoped_release release;
        p = parameterizeCloud(points, boundary, boundaryUV, o);
      }
      return py::make_tuple(p.uv, p.toJson());
    });
  }, py::arg("points"), py::arg("boundary"), py::arg("boundaryUV"), py::arg("method") = "shape", py::arg("radius") = 0.0,
     py::arg("weights") = "", "Meshless or learned (bidgcn) parameterization of a point cloud with fixed boundary parameters: (uv per point, report JSON).");
  m.def("fitPointCloud", [](const Eigen::MatrixX3d& points, const std::vector<bool>& boundary, const Eigen::MatrixX2d& boundaryUV, bool uvGiven,
                            const std::vector<int>& corners, const py::dict& options) {
    return guarded([&] {
      PointCloudFitOptions o = optionsFromDict(pointCloudFitSchema(), options);
      o.corners = corners;
      FlaggedCloud cloud;
      cloud.points = points;
      cloud.boundary = boundary;
      cloud.uv = boundaryUV;
      cloud.flagsGiven = !boundary.empty();
      cloud.boundaryUVGiven = uvGiven;
      PointCloudFitResult f;
      {
        py::gil_scoped_release release;
        f = fitPointCloud(cloud, o);
      }
      const ThbFitResult& r = f.fit;
      // The hierarchical mesh as parameter rectangles (level, u0, v0, u1, v1).
      const auto leaves = r.space.leafCells();
      Eigen::MatrixXd rects(leaves.size(), 5);
      for (size_t k = 0; k < leaves.size(); ++k) {
        const auto [l, i, j] = leaves[k];
        const double du = 1.0 / r.space.cellsU(l), dv = 1.0 / r.space.cellsV(l);
        rects.row(k) << l, i * du, j * dv, (i + 1) * du, (j + 1) * dv;
      }
      const std::vector<bool>& used = f.cloud.boundary;
      Eigen::Matrix<bool, Eigen::Dynamic, 1> flags(used.size());
      for (size_t k = 0; k < used.size(); ++k) flags[k] = used[k];
      return py::make_tuple(py::bytes(shapeToBrepString(f.shape)), f.toJson(), r.uv, Eigen::VectorXd(r.errors * r.diagonal), rects, flags);
    });
  }, py::arg("points"), py::arg("boundary"), py::arg("boundaryUV"), py::arg("uvGiven"), py::arg("corners"), py::arg("options") = py::dict(),
     "Point-cloud fit, options {name: value} of optionSchema('point_fit'): boundary (found when `boundary` is empty), parameters, "
     "adaptive THB fit with parameter correction: "
     "(face BREP, report JSON, uv per point, error per point in model units, leaf cells [level, u0, v0, u1, v1], boundary flags).");
  m.def("sampleCageNames", &cages::sampleCageNames);
  m.def("sampleCageObj", [](const std::string& name) { return guarded([&] { return formatCageObj(cages::sampleCage(name)); }); },
        py::arg("name"), "OBJ text of a bundled sample cage.");
  m.attr("__version__") = "0.1.0";
}
