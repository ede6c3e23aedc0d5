// holefill: the command-line door into the core (DESIGN.md), as thin as the
// Python one. Exit codes, one rule for every verb (geometry/outcome.h's exitCode of the verb's
// Result): 0 done; 3 written, but a goal was missed (a tolerance, the data, a valid shell, a hole
// left open: the report and stderr say which); 2 failed or cancelled (nothing written); 1 bad usage
// or input (one clear line on stderr, nothing written); 4 holefill crashed on a step that is not
// reading the input (a bug; nothing left written).
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "brep/hole_detection.h"
#include "brep/sample_models.h"
#include "brep/shape_io.h"
#include "fill/adjacent_holes.h"
#include "fill/hole_fill.h"
#include "geometry/text_file.h"
#include "fitting/cloud_parameterization.h"
#include "fitting/labeled_fit.h"
#include "fitting/point_cloud_fit.h"
#include "geometry/flagged_cloud.h"
#include "gnurbs/cage_io.h"
#include "gnurbs/gnurbs_build.h"
#include "gnurbs/sample_cages.h"
#include "geometry/atomic_file.h"
#include "geometry/bspline_surface.h"
#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "geometry/supervised_child.h"
#include "inspect/inspection_render.h"
#include "learn/learn_library.h"
#include "mesh/mesh_hole_fill.h"
#include "mesh/mesh_io.h"
#include "mesh/sample_meshes.h"
#include "options/gnurbs_build_schema.h"
#include "options/hole_fill_schema.h"
#include "options/labeled_fit_schema.h"
#include "options/mesh_fill_schema.h"
#include "options/option_sets.h"
#include "options/point_cloud_fit_schema.h"

using namespace holefill;

namespace {

const char* kUsage =
    "usage:\n"
    "  holefill holes FILE [--all] [--json]\n"
    "  holefill fill FILE --out OUT [--hole K | --hole all | --edges Edge3,Edge7,...] [--face-out FACE.brep] [--json]\n"
    "                [the fill's options, `holefill options fill`: --method, --continuity, --tolerance,\n"
    "                --angular-tolerance, --curvature-tolerance, --edge-continuity, --no-crease-detection, ...]\n"
    "                [--divide CURVE.brep]  two adjacent holes: the loop split by the one edge in CURVE.brep\n"
    "                (running from one loop vertex to another), filled as two faces sharing it\n"
    "  holefill options [SET] [--json]   an option set's options (fill, labeled_fit, mesh_fill, gnurbs): flag, default, unit, what it does\n"
    "  holefill render FILE --out PNG [--mode zebra|curvature|shaded] [--quantity mean|gauss|max|min|direction]\n"
    "                [--size WxH] [--view iso|top|bottom|front|back|left|right|dx,dy,dz] [--faces 1,2,..]\n"
    "                [--stripes N] [--stripe-width W] [--stripe-angle DEG] [--stripe-mode reflection|isophote]\n"
    "                [--isophote-direction x,y,z] [--direction x,y,z] [--scale-percentile LO,HI | --scale-range LO,HI]\n"
    "                [--symmetric auto|yes|no] [--normal-angle DEG] [--edges 0|1] [--legend 0|1] [--json]\n"
    "  holefill mesh-fill MESH --out OUT [--holes 0,3,..] [--json]   MESH, OUT: .obj .off .ply .stl; holes as\n"
    "                `holefill mesh-holes` numbers them [the mesh fill's options, `holefill options mesh_fill`:\n"
    "                --max-boundary, --weld, --triangulation angle|dihedral|auto, --no-refine, --shape-order, ...]\n"
    "  holefill mesh-holes MESH [--weld F] [--json]   --weld F: coincident vertices (within F of the diagonal) merged first\n"
    "  holefill gnurbs CAGE.obj --out OUT.step|OUT.brep [--sharp EDGES.json] [--anchors ANCHORS.json]\n"
    "                [--fit TARGET.obj|.off|.ply|.stl|.xyz] [--cage-out FITTED.obj] [--json] [the G-NURBS options,\n"
    "                `holefill options gnurbs`: --no-refine, --max-valence, --solve fair|stepwise, --merge-regular, --fit-rounds]\n"
    "                G² surface over a quad cage; '# sharp i j', '# knot i j d', '# anchor i x y z' lines in the OBJ\n"
    "                (1-based); EDGES.json [[i,j],..], ANCHORS.json [[i,x,y,z],..]; writes OUT and OUT's .faces.json;\n"
    "                --fit moves the cage (and anchors) to fit the target's points (mesh vertices, or x y z lines)\n"
    "  holefill fit REGION.obj|.off|.ply|.stl --labels LABELS.json --out OUT.brep|.step [--ctrl 12x12] [--untrimmed-out S.brep]\n"
    "                [--json] [labeled fitting's options, `holefill options labeled_fit`: --extension fit|G2|G1|none,\n"
    "                --max-ctrl, --tolerance, --relative-tolerance, --margin, --reach, --fairness, --isocurves, --mesh-fairness,\n"
    "                --smoothing, --frame-placement, --release-depth, --hold-labels]\n"
    "                labeled fitting of a trimmed mesh region: its extension to the domain's rectangle, control points\n"
    "                refined while the data max exceeds the tolerance (--tolerance in model units, or --relative-tolerance\n"
    "                of the region's diagonal, 1e-3 by default; --ctrl alone: exactly those); LABELS.json:\n"
    "                {\"segments\": [{\"label\": \"N\", \"vertices\": [i, j, ...]}, ...]} (0-based, along the boundary)\n"
    "  holefill param CLOUD.txt --out UV.txt [--method shape|invdist|uniform|bidgcn] [--radius R] [--corners I,J,K,L]\n"
    "                [--weights W.pt] [--json]\n"
    "                meshless parameterization of a point cloud; CLOUD.txt lines 'x y z flag u v' (flag 1: boundary point\n"
    "                with its u v; 0: interior), or bare 'x y z' lines (the boundary is found: alpha shape in the best plane);\n"
    "                boundary points without u v get chord length between four corners\n"
    "                (found, or the 0-based points given); UV.txt: 'u v' per point, same order; R in the unit-cube-scaled cloud;\n"
    "                bidgcn: the learned parameterizer (shipped weights unless --weights)\n"
    "  holefill fit-points CLOUD.txt --out OUT.brep|.step [--json] [the fit's options, `holefill options point_fit`:\n"
    "                --method shape|bidgcn|invdist|uniform, --tolerance T, --relative-tolerance R, --degree, --cells,\n"
    "                --iterations, --uniform, --faces, ...]   spline fit of a point cloud (as for param) with parameter\n"
    "                correction, refined adaptively (THB-splines; --uniform: one level) until the max error <= T (model\n"
    "                units) or R of the diagonal (1e-3 by default); OUT holds the finest-level B-spline face, or with\n"
    "                --faces one face per hierarchical cell\n"
    "  holefill samples DIR        write the bundled sample models (.brep, scan_with_holes.obj, cage_*.obj quad cages,\n"
    "                labeled_region.obj with its labeled_region.labels.json, scan_patch.xyz: a bare point cloud)\n"
    "  holefill train uvtran [--out DIR] [--stage1-steps N] [--stage2-steps N] [--batch B] [--threads T]\n"
    "                [--max-hours H] [--width D] [--layers L]   (resumes from DIR/checkpoint.pt)\n"
    "  holefill train bidgcn [--out DIR] [--steps N] [--batch B] [--noise S] [--lr L] [--threads T] [--max-hours H]\n"
    "                [--init W --first-cloud K]   (fine-tune W on clouds K, K+1, ...; resumes from DIR/checkpoint.pt)\n"
    "  holefill eval uvtran [--weights W] [--samples N] [--split test|validation]\n"
    "  holefill eval bidgcn [--weights W] [--clouds N] [--interior N] [--noise S] [--split test|validation]\n"
    "  holefill --version\n";

struct Args {
  std::string verb, input;
  std::map<std::string, std::string> opt;
  bool has(const std::string& k) const { return opt.count(k) > 0; }
  std::string get(const std::string& k, const std::string& d = "") const { return has(k) ? opt.at(k) : d; }
};

Args parse(int argc, char** argv) {
  // Valueless flags: the verbs' own, and every Bool option's (its flag sets it).
  static const std::vector<std::string> flags = [] {
    std::vector<std::string> f = {"--json", "--all", "--all-holes"};
    for (const auto& set : optionSetNames())
      for (const OptionField& o : optionSet(set).fields)
        if (o.kind == OptionKind::Bool && !o.flag.empty() && std::find(f.begin(), f.end(), o.flag) == f.end()) f.push_back(o.flag);
    return f;
  }();
  Args a;
  if (argc < 2) throw Error(std::string("no command given\n") + kUsage);
  a.verb = argv[1];
  for (int i = 2; i < argc; ++i) {
    std::string s = argv[i];
    if (s.rfind("--", 0) == 0) {
      const auto eq = s.find('=');
      if (eq != std::string::npos) { a.opt[s.substr(0, eq)] = s.substr(eq + 1); continue; }
      // --faces is fit-points' flag (pointCloudFitSchema's cellFaces) but render's list of faces.
      const bool flag = std::find(flags.begin(), flags.end(), s) != flags.end() && !(s == "--faces" && a.verb != "fit-points");
      if (flag) { a.opt[s] = "1"; continue; }
      if (i + 1 >= argc) throw Error("option " + s + " needs a value");
      a.opt[s] = argv[++i];
    } else if (a.input.empty()) {
      a.input = s;
    } else {
      throw Error("unexpected argument '" + s + "'");
    }
  }
  return a;
}

// Sets every option of `schema` whose flag is given (a Bool's bare flag sets what the schema says).
template <class O>
void applyFlags(const OptionSchema<O>& schema, const Args& a, O& o) {
  for (const auto& b : schema) {
    const OptionField& f = b.field;
    if (f.flag.empty() || !a.has(f.flag)) continue;
    try {
      b.set(o, f.kind == OptionKind::Bool ? (f.flagSets ? "true" : "false") : a.get(f.flag));
    } catch (const Error& e) {
      throw Error(f.flag + ": " + e.what());
    }
  }
}

double number(const std::string& s, const std::string& what) {
  try {
    size_t n = 0;
    const double v = std::stod(s, &n);
    if (n != s.size() || !std::isfinite(v) || v < 0) throw 0;
    return v;
  } catch (...) {
    throw Error(what + " must be a non-negative number, got '" + s + "'");
  }
}

std::vector<int> edgeNames(const std::string& list) {
  std::vector<int> r;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.rfind("Edge", 0) == 0) item = item.substr(4);
    try {
      size_t n = 0;
      const int k = std::stoi(item, &n);
      if (n != item.size() || k < 1) throw 0;
      r.push_back(k);
    } catch (...) {
      throw Error("bad edge name '" + item + "' in --edges: use Edge3,Edge7,... (1-based, as FreeCAD shows them)");
    }
  }
  if (r.empty()) throw Error("--edges names no edge");
  return r;
}

int cmdHoles(const Args& a) {
  if (a.input.empty()) throw Error("holes: no input file");
  const TopoDS_Shape shape = readShape(a.input);
  HoleDetectionOptions o;
  o.includeOuterBoundary = a.has("--all");
  const HoleDetectionResult d = detectHoles(shape, o);
  if (a.has("--json")) { std::cout << toJson(d) << "\n"; return 0; }
  std::printf("%-5s %-3s %-8s %-12s %s\n", "hole", "N", "edges", "length", "edge names");
  for (size_t i = 0; i < d.holes.size(); ++i) {
    std::string names;
    for (int e : d.holes[i].edgeIndices()) names += (names.empty() ? "Edge" : ",Edge") + std::to_string(e);
    std::printf("%-5zu %-3d %-8zu %-12.6g %s%s\n", i + 1, d.holes[i].corners, d.holes[i].edges.size(),
                d.holes[i].length, names.c_str(), d.holes[i].outerBoundary ? "  (outer boundary)" : "");
  }
  for (const auto& w : d.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (d.holes.empty()) std::printf("no holes\n");
  return 0;
}

// fill --divide: the two sides' worse outcome (outcome(AdjacentFillResult)).
int fillAdjacent(const Args& a, const TopoDS_Shape& shape, const HoleFillOptions& o) {
  if (a.has("--all-holes") || a.get("--hole") == "all") throw Error("--divide splits one hole: name it with --edges or --hole K");
  const TopoDS_Shape curve = readShape(a.get("--divide"));
  TopTools_IndexedMapOfShape curveEdges;
  TopExp::MapShapes(curve, TopAbs_EDGE, curveEdges);
  if (curveEdges.Extent() != 1)
    throw Error("--divide " + a.get("--divide") + " must hold one edge (the dividing curve); it holds " +
                std::to_string(curveEdges.Extent()));
  std::vector<int> edges;
  if (a.has("--edges")) {
    edges = edgeNames(a.get("--edges"));
  } else {
    const int k = a.has("--hole") ? static_cast<int>(number(a.get("--hole"), "--hole")) : 1;
    const HoleDetectionResult det = detectHoles(shape, o.detection);
    if (k < 1 || k > static_cast<int>(det.holes.size()))
      throw Error("hole " + std::to_string(k) + " does not exist: the shape has " + std::to_string(det.holes.size()) + " hole(s)");
    edges = det.holes[k - 1].edgeIndices();
  }
  const AdjacentFillResult r = fillAdjacentHoles(shape, edges, TopoDS::Edge(curveEdges(1)), o);
  const int code = exitCode(outcome(r));
  if (code != 2) {
    OutputSet outputs;
    outputs.write(a.get("--out"), [&](const std::string& p) { writeShape(r.shape, p); });
    if (a.has("--face-out")) {
      TopoDS_Compound faces;
      BRep_Builder B;
      B.MakeCompound(faces);
      B.Add(faces, r.first.face);
      B.Add(faces, r.second.face);
      outputs.write(a.get("--face-out"), [&](const std::string& p) { writeShape(faces, p); });
    }
    outputs.commit();
  }
  if (a.has("--json")) {
    std::cout << toJson(r) << "\n";
  } else {
    for (const HoleFillResult* f : {&r.first, &r.second})
      if (!f->face.IsNull())
        std::printf("side (%zu edges): %s, %s; G0 %.3g (%.2g of scale) G1 %.3g rad G2 %.3g; %dx%d poles; %.2f s\n",
                    f->hole.edges.size(), toString(f->status).c_str(), f->message.c_str(), f->report.g0,
                    f->report.g0Relative, f->report.g1, f->report.g2, f->polesU, f->polesV, f->timings.total);
    std::printf("%s: %s\n", toString(r.status).c_str(), r.message.c_str());
  }
  if (code == 2) std::fprintf(stderr, "holefill: fill failed: %s\n", r.message.c_str());
  return code;
}

int cmdFill(const Args& a) {
  if (a.input.empty()) throw Error("fill: no input file");
  if (!a.has("--out")) throw Error("fill: --out OUT is required");
  HoleFillOptions o;
  applyFlags(holeFillSchema(), a, o);
  TopoDS_Shape shape = readShape(a.input);
  if (a.has("--divide")) return fillAdjacent(a, shape, o);
  o.copyModel = false;  // the model was read for this fill alone
  std::vector<HoleFillResult> results;
  if (a.has("--all-holes") || a.get("--hole") == "all") {
    results = fillHoles(shape, o);
  } else if (a.has("--edges")) {
    results.push_back(fillHole(shape, edgeNames(a.get("--edges")), o));
  } else {
    const int k = a.has("--hole") ? static_cast<int>(number(a.get("--hole"), "--hole")) : 1;
    if (k < 1) throw Error("--hole is 1-based");
    results.push_back(fillHole(shape, k - 1, o));
  }
  const HoleFillResult& last = results.back();
  std::vector<Outcome> outcomes;
  for (const auto& r : results) outcomes.push_back(outcome(r));
  const int code = exitCode(outcomes);
  if (code != 2) {
    OutputSet outputs;
    outputs.write(a.get("--out"), [&](const std::string& p) { writeShape(last.shape, p); });
    if (a.has("--face-out")) outputs.write(a.get("--face-out"), [&](const std::string& p) { writeShape(last.face, p); });
    outputs.commit();
  }
  if (a.has("--json")) {
    std::cout << "[";
    for (size_t i = 0; i < results.size(); ++i) std::cout << (i ? "," : "") << toJson(results[i]);
    std::cout << "]\n";
  } else {
    for (const auto& r : results)
      std::printf("hole %d (N=%d, %zu edges): %s, %s; G0 %.3g (%.2g of scale) G1 %.3g rad G2 %.3g; %dx%d poles; %.2f s\n",
                  r.holeIndex + 1, r.hole.corners, r.hole.edges.size(), toString(r.status).c_str(), r.message.c_str(),
                  r.report.g0, r.report.g0Relative, r.report.g1, r.report.g2, r.polesU, r.polesV, r.timings.total);
  }
  if (code == 2) std::fprintf(stderr, "holefill: fill failed at stage %s: %s\n", toString(last.failedStage).c_str(), last.message.c_str());
  return code;
}

int cmdRender(const Args& a) {
  if (a.input.empty()) throw Error("render: no input file");
  if (!a.has("--out")) throw Error("render: --out PNG is required");
  std::map<std::string, std::string> given;
  for (const auto& [k, v] : a.opt)
    if (k != "--out" && k != "--json") given[k.substr(2)] = v;
  if (!given.count("mode")) given["mode"] = "zebra";
  const RenderOptions o = parseRenderOptions(given);  // before reading: a bad option costs no read
  const RenderResult r = renderInspection(readShape(a.input), o);
  writePng(r.image, a.get("--out"));
  if (a.has("--json")) {
    std::cout << toJson(r, o) << "\n";
  } else {
    std::printf("%s: %s %dx%d, %lld vertices, normal angle <= %.2f deg inside faces (%.2f on boundaries)",
                a.get("--out").c_str(), toString(o.mode).c_str(), r.image.width, r.image.height,
                static_cast<long long>(r.vertices), r.maxInteriorNormalAngle * 180 / M_PI, r.maxBoundaryNormalAngle * 180 / M_PI);
    if (o.mode == RenderMode::Curvature)
      std::printf(", %s in [%.4g, %.4g], colours span [%.4g, %.4g]", toString(o.quantity).c_str(), r.valueMin, r.valueMax,
                  r.scale.low, r.scale.high);
    std::printf("; %.2f s + %.2f s\n", r.tessellationSeconds, r.renderSeconds);
  }
  for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return 0;
}

std::vector<int> indexList(const std::string& list, const std::string& what) {
  std::vector<int> r;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) r.push_back(static_cast<int>(number(item, what)));
  return r;
}

int cmdMeshHoles(const Args& a) {
  if (a.input.empty()) throw Error("mesh-holes: no input file");
  MeshFillOptions o;
  applyFlags(meshFillSchema(), a, o);  // --weld numbers the holes as mesh-fill with it does
  TriangleMesh mesh = readMesh(a.input);
  if (o.weld > 0) mesh = weldVertices(mesh, o.weld * boundingDiagonal(mesh.vertices)).mesh;
  const MeshHoleReport d = findMeshHoles(mesh);
  if (a.has("--json")) {
    std::cout << toJson(d) << "\n";
    return 0;
  }
  std::printf("%-5s %-8s %-12s %s\n", "hole", "vertices", "length", "note");
  for (size_t i = 0; i < d.holes.size(); ++i)
    std::printf("%-5zu %-8zu %-12.6g %s\n", i, d.holes[i].loop.size(), d.holes[i].length, d.holes[i].message.c_str());
  for (const auto& w : d.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (d.holes.empty()) std::printf("no holes: the mesh is closed\n");
  return 0;
}

// Holes left open: Warned (written, the report says which and why); none filled: Failed.
int cmdMeshFill(const Args& a) {
  if (a.input.empty()) throw Error("mesh-fill: no input file");
  if (!a.has("--out")) throw Error("mesh-fill: --out OUT is required");
  MeshFillOptions o;
  applyFlags(meshFillSchema(), a, o);
  if (a.has("--holes")) o.holes = indexList(a.get("--holes"), "--holes");
  const MeshFillResult r = fillMeshHoles(readMesh(a.input), o);
  if (r.fills.empty()) throw Error("the mesh has no holes (it is closed); nothing written");
  const int code = exitCode(r.outcome());
  if (code != 2) writeMesh(r.mesh, a.get("--out"));
  if (a.has("--json")) {
    std::cout << r.toJson() << "\n";
  } else {
    std::printf("%-5s %-8s %-6s %-6s %-7s %-7s %-7s %-8s %s\n", "hole", "boundary", "+verts", "+tris", "q min", "q mean",
                "q max", "seconds", "note");
    for (const MeshHoleFill& f : r.fills)
      std::printf("%-5d %-8d %-6d %-6d %-7.4f %-7.4f %-7.4f %-8.3f %s\n", f.hole, f.boundaryVertices, f.newVertices,
                  f.newTriangles, f.minQuality, f.meanQuality, f.maxQuality, f.seconds, f.message.c_str());
    std::printf("%d of %zu holes filled, %s, %.3f s\n", r.filledHoles, r.fills.size(), r.closed ? "closed" : "still open", r.seconds);
  }
  for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (code == 2) std::fprintf(stderr, "holefill: no hole was filled; nothing written\n");
  return code;
}

// A fitting target's points: a mesh's vertices, or an .xyz file of "x y z" lines.
Eigen::MatrixX3d readPoints(const std::string& path) {
  if (fileExtension(path) != "xyz") return readMesh(path).vertices;
  std::istringstream in(readFileBytes(path, std::size_t(1) << 30));
  std::vector<Eigen::RowVector3d> pts;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream ls(line);
    std::string t[3];
    if (!(ls >> t[0]) || t[0][0] == '#') continue;
    double x[3];
    for (int k = 0; k < 3; ++k)
      if ((k > 0 && !(ls >> t[k])) || !parseDouble(t[k], x[k]) || !std::isfinite(x[k]))
        throw Error("'" + path + "' line " + std::to_string(n) + ": expected three finite numbers x y z");
    pts.emplace_back(x[0], x[1], x[2]);
  }
  if (pts.empty()) throw Error("'" + path + "' holds no points");
  Eigen::MatrixX3d out(pts.size(), 3);
  for (size_t k = 0; k < pts.size(); ++k) out.row(static_cast<Eigen::Index>(k)) = pts[k];
  return out;
}

// Written with warnings (an EP short of its conditions, an invalid shell): Warned.
int cmdGnurbs(const Args& a) {
  if (a.input.empty()) throw Error("gnurbs: no cage file");
  if (!a.has("--out")) throw Error("gnurbs: --out OUT.step (or .brep) is required");
  const std::string out = a.get("--out"), ext = fileExtension(out);
  if (ext != "step" && ext != "stp" && ext != "brep" && ext != "brp") throw Error("gnurbs: --out must end in .step or .brep, got '" + out + "'");
  QuadCage cage = readCage(a.input);
  if (a.has("--sharp")) addSharpEdgesFromJson(cage, readFileBytes(a.get("--sharp"), 1 << 26), a.get("--sharp"));
  if (a.has("--anchors")) addAnchorsFromJson(cage, readFileBytes(a.get("--anchors"), 1 << 26), a.get("--anchors"));
  GnurbsBuildOptions o;
  applyFlags(gnurbsBuildSchema(), a, o);
  if (a.has("--cage-out") && !a.has("--fit")) throw Error("gnurbs: --cage-out needs --fit (the cage is only changed by fitting)");
  std::optional<Eigen::MatrixX3d> target;
  if (a.has("--fit")) target = readPoints(a.get("--fit"));
  const GnurbsBuildResult r = buildGnurbs(cage, o, target ? &*target : nullptr);
  const std::string sidecar = out.substr(0, out.size() - ext.size() - 1) + ".faces.json";
  OutputSet outputs;
  outputs.write(out, [&](const std::string& p) { writeShape(r.brep.shape, p); });
  outputs.write(sidecar, [&](const std::string& p) { writeFileAtomically(p, r.brep.sidecarJson + "\n"); });
  if (a.has("--cage-out")) outputs.write(a.get("--cage-out"), [&](const std::string& p) { writeFileAtomically(p, formatCageObj(r.cage)); });
  outputs.commit();
  if (a.has("--json")) {
    std::cout << r.toJson() << "\n";
  } else {
    const G2GnurbsResult& s = r.surface;
    const GnurbsBrep& b = r.brep;
    const GnurbsContinuity& c = r.continuity;
    if (r.fit)
      std::printf("fit to %s: d_max %.4f%%, d_avg %.5f%% of the target's diagonal (sharp regions: %.4f%%, %.5f%% over %d points), %.2f s\n",
                  a.get("--fit").c_str(), 100 * r.fit->dMax, 100 * r.fit->dAvg, 100 * r.fit->dMaxSharp, 100 * r.fit->dAvgSharp,
                  r.fit->sharpPoints, r.fit->seconds);
    std::printf("cage: %d vertices, %d quads%s; %zu extraordinary points, %d faces in their 1-rings\n", static_cast<int>(s.cage.vertices.rows()),
                static_cast<int>(s.cage.quads.rows()), s.refinements ? " after one Catmull-Clark step" : "", s.extraordinaryPoints.size(),
                s.irregularFaces);
    if (s.refinements) std::printf("refined because %s\n", s.refinementReason.c_str());
    std::printf("patches: %d B-rep faces in %s shell (%d free edges, %s), %.3f s\n", b.faces, b.closed ? "a closed" : "an open", b.freeEdges,
                b.valid ? "valid" : "INVALID", r.seconds);
    std::printf("continuity over %d cage edges: spokes G1 %.2e rad, G2 %.2e; elsewhere G1 %.2e rad, G2 %.2e; G0 %.1e\n", c.edges, c.g1Spokes,
                c.g2Spokes, c.g1Elsewhere, c.g2Elsewhere, c.g0);
    std::printf("wrote %s and %s\n", out.c_str(), sidecar.c_str());
  }
  // An invalid shell is written (to look at) but never passes as a success.
  for (const auto& w : r.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return exitCode(r.outcome());
}

// Folded triangles, an invalid trimmed face or the data missed: Warned (LabeledFitResult::outcome).
int cmdFit(const Args& a) {
  if (a.input.empty()) throw Error("fit: no region mesh given");
  if (!a.has("--labels")) throw Error("fit: --labels LABELS.json is required");
  if (!a.has("--out")) throw Error("fit: --out OUT.brep (or .step) is required");
  LabeledFitOptions o;
  // --ctrl NUxNV: exactly those control points, unless --max-ctrl asks to refine from them.
  if (a.has("--ctrl")) {
    const std::string c = a.get("--ctrl");
    const auto x = c.find('x');
    if (x == std::string::npos) throw Error("--ctrl takes NUxNV, e.g. 12x12, got '" + c + "'");
    setOption(labeledFitSchema(), o, "controlU", c.substr(0, x));
    setOption(labeledFitSchema(), o, "controlV", c.substr(x + 1));
    o.maxControl = 0;
  }
  applyFlags(labeledFitSchema(), a, o);
  const TriangleMesh region = readMesh(a.input);
  const std::vector<LabeledSegment> labels = parseLabelsJson(readFileBytes(a.get("--labels"), 1 << 26), a.get("--labels"));
  const LabeledFitResult r = fitLabeled(region, labels, o);
  OutputSet outputs;
  outputs.write(a.get("--out"), [&](const std::string& p) { writeShape(r.fit.face, p); });
  if (a.has("--untrimmed-out"))
    outputs.write(a.get("--untrimmed-out"), [&](const std::string& p) { writeShape(BRepBuilderAPI_MakeFace(toOcct(r.fit.surface), 1e-7).Face(), p); });
  outputs.commit();
  if (a.has("--json")) {
    std::cout << r.toJson() << "\n";
  } else {
    std::printf("domain %.6g x %.6g (guiding frame degree %d), %d flipped triangles, %d extension vertices\n", r.parameterization.width,
                r.parameterization.height, r.parameterization.frame.degree, r.parameterization.flippedTriangles,
                static_cast<int>(r.extension.mesh.vertices.rows()) - r.extension.regionVertices);
    std::printf("fit %dx%d: data max %.2e, rms %.2e of the region's diagonal (scan noise %.2e); %d weak control points; log10 condition %.1f; "
                "face %s; %.2f s\n",
                r.fit.surface.numU(), r.fit.surface.numV(), r.fit.dataMax, r.fit.dataRms, r.noise, r.fit.weakControlPoints, r.fit.log10Condition,
                r.fit.valid ? "valid" : "INVALID", r.seconds);
  }
  for (const auto& w : r.allWarnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return exitCode(r.outcome());
}

// A point-cloud file as flagged; bare x y z lines are completed by the core (point_cloud_fit.h).
FlaggedCloud readCloud(const std::string& path) { return parseFlaggedCloud(readFileBytes(path, std::size_t(1) << 30), path); }

void reportFound(const CloudBoundaryCompletion& c) {
  if (c.found >= 0) std::fprintf(stderr, "no boundary flags: found %d boundary points (alpha shape, spacing %.3g)\n", c.found, c.spacing);
}

std::vector<int> cornerList(const Args& a) {
  std::vector<int> corners;
  if (a.has("--corners")) {
    std::istringstream in(a.get("--corners"));
    for (std::string t; std::getline(in, t, ',');) corners.push_back(static_cast<int>(number(t, "--corners")));
  }
  return corners;
}

// Exit 0 when written (with warnings on stderr).
int cmdParam(const Args& a) {
  if (a.input.empty()) throw Error("param: no point cloud given (lines x y z flag u v)");
  if (!a.has("--out")) throw Error("param: --out UV.txt is required");
  CloudParameterizationOptions o;
  o.weights = cloudWeightsByName(a.get("--method", "shape"));
  if (a.has("--radius")) o.radius = number(a.get("--radius"), "--radius");
  o.weightsFile = a.get("--weights", "");
  FlaggedCloud c = readCloud(a.input);
  reportFound(completeCloudBoundary(c, cornerList(a), a.has("--corners")));
  const CloudParameterization p = parameterizeCloud(c.points, c.boundary, c.uv, o);
  std::ostringstream text;
  text.precision(17);
  for (Eigen::Index k = 0; k < p.uv.rows(); ++k) text << p.uv(k, 0) << ' ' << p.uv(k, 1) << '\n';
  writeFileAtomically(a.get("--out"), text.str());
  if (a.has("--json")) {
    std::cout << p.toJson() << "\n";
  } else {
    if (o.weights == CloudWeights::Bidgcn)
      std::printf("%d points (%d on the boundary), BIDGCN, %.3f s; wrote %s\n", p.points, p.boundaryPoints, p.seconds, a.get("--out").c_str());
    else
      std::printf("%d points (%d on the boundary), %s weights, radius %.4g (unit-cube scale), %d-%d neighbours, %.3f s; wrote %s\n",
                  p.points, p.boundaryPoints, p.method.c_str(), p.radius, p.minNeighbours, p.maxNeighbours, p.seconds, a.get("--out").c_str());
  }
  for (const auto& w : p.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return 0;
}

// The tolerance not met: Warned.
int cmdFitPoints(const Args& a) {
  if (a.input.empty()) throw Error("fit-points: no point cloud given (lines x y z flag [u v])");
  if (!a.has("--out")) throw Error("fit-points: --out OUT.brep (or .step) is required");
  PointCloudFitOptions o;
  applyFlags(pointCloudFitSchema(), a, o);
  const PointCloudFitResult r = fitPointCloud(readCloud(a.input), o);
  reportFound(r.completion);
  writeShape(r.shape, a.get("--out"));
  if (a.has("--json")) {
    std::cout << r.toJson() << "\n";
  } else {
    for (const auto& h : r.fit.history)
      std::printf("%5d functions: mse %.2e, max error %.2e of the diagonal; %d cells refined, %d parameters corrected\n", h.dof, h.mse, h.maxError,
                  h.refinedCells, h.correctedParameters);
    std::printf("%s after %zu iterations, %d levels; wrote %s\n", r.fit.metTolerance ? "tolerance met" : "tolerance NOT met", r.fit.history.size(),
                r.fit.space.levels(), a.get("--out").c_str());
  }
  for (const auto& w : r.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return exitCode(r.outcome());
}

int cmdSamples(const Args& a) {
  if (a.input.empty()) throw Error("samples: no output folder");
  for (const auto& n : samples::names()) {
    const std::string path = a.input + "/" + n + ".brep";
    writeShape(samples::byName(n), path);
    std::printf("%s\n", path.c_str());
  }
  {
    TopoDS_Edge divider;
    const std::string path = a.input + "/filleted_box_adjacent_holes.brep";
    writeShape(samples::filletedBoxAdjacentHoles(&divider), path);
    writeShape(divider, a.input + "/filleted_box_adjacent_holes.divider.brep");
    std::printf("%s\n%s/filleted_box_adjacent_holes.divider.brep\n", path.c_str(), a.input.c_str());
  }
  const std::string mesh = a.input + "/scan_with_holes.obj";
  writeMesh(samples::scanWithHoles(), mesh);
  std::printf("%s\n", mesh.c_str());
  std::string labels;
  const TriangleMesh region = samples::labeledRegion(&labels);
  writeMesh(region, a.input + "/labeled_region.obj");
  writeFileAtomically(a.input + "/labeled_region.labels.json", labels + "\n");
  std::printf("%s/labeled_region.obj\n%s/labeled_region.labels.json\n", a.input.c_str(), a.input.c_str());
  std::ostringstream cloud;
  cloud.precision(10);
  const Eigen::MatrixX3d scan = samples::scanPatchCloud();
  for (Eigen::Index k = 0; k < scan.rows(); ++k) cloud << scan(k, 0) << ' ' << scan(k, 1) << ' ' << scan(k, 2) << '\n';
  writeFileAtomically(a.input + "/scan_patch.xyz", cloud.str());
  std::printf("%s/scan_patch.xyz\n", a.input.c_str());
  for (const auto& n : cages::sampleCageNames()) {
    const std::string path = a.input + "/" + n + ".obj";
    writeFileAtomically(path, formatCageObj(cages::sampleCage(n)));
    std::printf("%s\n", path.c_str());
  }
  return 0;
}


// The option sets' schemas (options/option_sets.h): every flag with its default, unit and doc.
int cmdOptions(const Args& a) {
  const std::vector<std::string> sets = a.input.empty() ? optionSetNames() : std::vector<std::string>{a.input};
  if (a.has("--json")) {
    if (!a.input.empty()) {
      std::cout << optionSetJson(a.input) << "\n";
      return 0;
    }
    std::cout << "{";
    for (size_t k = 0; k < sets.size(); ++k) std::cout << (k ? "," : "") << "\"" << sets[k] << "\":" << optionSetJson(sets[k]);
    std::cout << "}\n";
    return 0;
  }
  for (const auto& set : sets) {
    std::printf("%s:\n", set.c_str());
    const OptionList l = optionSet(set);
    for (size_t k = 0; k < l.fields.size(); ++k) {
      const OptionField& f = l.fields[k];
      const bool text = f.kind == OptionKind::Choice || f.kind == OptionKind::Text;
      std::string value = text ? "'" + l.defaults[k] + "'" : l.defaults[k];
      if (f.kind == OptionKind::Bool) value += std::string("; the flag sets ") + (f.flagSets ? "true" : "false");
      else if (!f.unit.empty()) value += " " + f.unit;
      std::printf("  %-24s %-22s default %s\n      %s\n", f.name.c_str(), f.flag.empty() ? "(no flag)" : f.flag.c_str(), value.c_str(),
                  f.doc.c_str());
    }
  }
  return 0;
}

int runVerb(int argc, char** argv) {
  try {
    const Args a = parse(argc, argv);
    if (a.verb == "holes") return cmdHoles(a);
    if (a.verb == "fill") return cmdFill(a);
    if (a.verb == "samples") return cmdSamples(a);
    if (a.verb == "render") return cmdRender(a);
    if (a.verb == "mesh-fill") return cmdMeshFill(a);
    if (a.verb == "mesh-holes") return cmdMeshHoles(a);
    if (a.verb == "gnurbs") return cmdGnurbs(a);
    if (a.verb == "fit") return cmdFit(a);
    if (a.verb == "param") return cmdParam(a);
    if (a.verb == "fit-points") return cmdFitPoints(a);
    if (a.verb == "options") return cmdOptions(a);
    throw Error("unknown command '" + a.verb + "'\n" + kUsage);
  } catch (const Error& e) {
    std::fprintf(stderr, "holefill: %s\n", e.what());
  } catch (const Standard_Failure& e) {
    std::fprintf(stderr, "holefill: %s\n", occtFailure(e).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "holefill: %s\n", e.what());
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  // OCCT's readers and writers print statistics on stdout, which would corrupt --json output.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  try {
    if (argc >= 2 && (std::string(argv[1]) == "--version" || std::string(argv[1]) == "version")) {
      std::printf("holefill 0.1.0\n");
      return 0;
    }
    if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
      std::printf("%s", kUsage);
      return 0;
    }
    if (argc >= 2 && (std::string(argv[1]) == "train" || std::string(argv[1]) == "eval"))
      return learn::learnLibrary().main(argc - 1, argv + 1);  // loads libtorch only for these verbs
  } catch (const std::exception& e) {
    std::fprintf(stderr, "holefill: %s\n", e.what());
    return 1;
  }
  // Every other verb reads untrusted files and runs geometry kernels: it runs in a watched
  // child, so a crash or a hang on a bad input is one clear line and no file left behind.
  return runSupervised([&] { return runVerb(argc, argv); });
}
