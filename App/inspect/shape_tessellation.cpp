#include "inspect/shape_tessellation.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <Geom2d_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <iomanip>
#include <map>
#include <sstream>
#include <set>
#include <tuple>
#include <unordered_map>

#include "geometry/error.h"

namespace holefill {

namespace {

using Tri = std::array<int, 3>;
constexpr double kBRepMeshAngle = 0.2;  // rad: BRepMesh's angular deflection when the bound is smaller

std::uint64_t edgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

double normalAngle(const SurfaceFields& f, int a, int b) {
  if (!f.regular[static_cast<size_t>(a)] || !f.regular[static_cast<size_t>(b)]) return 0.0;
  const double c = f.normals.row(a).dot(f.normals.row(b));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

// A piece of a B-rep edge between two mesh nodes of a face, with its edge parameters: faces
// sharing the edge split the same pieces at the same parameter, so they stay crack-free.
struct BoundarySegment {
  int a, b;       // local nodes
  int edge;       // 1-based edge index in the shape
  int faceEdge;   // index into FaceMesh::edges (the edge as oriented in this face)
  double ta, tb;  // edge parameters at a and b
};

// One face's mesh in its own numbering while it is refined.
struct FaceMesh {
  TopoDS_Face face;
  int index = 0;  // 1-based face index
  std::vector<Eigen::Vector2d> uv;
  std::vector<Tri> tris;
  SurfaceFields fields;
  std::vector<TopoDS_Edge> edges;
  std::vector<BoundarySegment> segments;
};

using SegmentKey = std::tuple<int, double, double>;  // (edge, ta, tb) with ta < tb
SegmentKey segmentKey(const BoundarySegment& s) { return {s.edge, std::min(s.ta, s.tb), std::max(s.ta, s.tb)}; }

void appendFields(FaceMesh& m, const TopoDS_Face& face, size_t from, int threads) {
  Eigen::MatrixX2d uv(static_cast<Eigen::Index>(m.uv.size() - from), 2);
  for (size_t i = from; i < m.uv.size(); ++i) uv.row(static_cast<Eigen::Index>(i - from)) = m.uv[i];
  const SurfaceFields add = evaluateFaceFields(face, uv, threads);
  SurfaceFields all;
  all.resize(static_cast<Eigen::Index>(m.uv.size()));
  if (from > 0) {
    all.points.topRows(from) = m.fields.points;
    all.normals.topRows(from) = m.fields.normals;
    all.d1.topRows(from) = m.fields.d1;
    all.k1.head(from) = m.fields.k1;
    all.k2.head(from) = m.fields.k2;
    std::copy(m.fields.regular.begin(), m.fields.regular.end(), all.regular.begin());
  }
  all.place(static_cast<Eigen::Index>(from), add);
  m.fields = std::move(all);
}

// Triangle (v0, v1, v2) with midpoints mid[i] on edge (v[i], v[i+1]) (-1: edge not split),
// replaced by the conforming 2-, 3- or 4-triangle pattern, keeping the orientation.
void splitTriangle(const Tri& v, const std::array<int, 3>& mid, const SurfaceFields& f, std::vector<Tri>& out) {
  const int count = (mid[0] >= 0) + (mid[1] >= 0) + (mid[2] >= 0);
  if (count == 0) { out.push_back(v); return; }
  if (count == 3) {
    out.push_back({v[0], mid[0], mid[2]});
    out.push_back({mid[0], v[1], mid[1]});
    out.push_back({mid[2], mid[1], v[2]});
    out.push_back({mid[0], mid[1], mid[2]});
    return;
  }
  // Rotate so that edge 0 is split (count 1) or edge 2 is the unsplit one (count 2).
  int r = 0;
  for (; r < 3; ++r) {
    if (count == 1 && mid[r] >= 0) break;
    if (count == 2 && mid[(r + 2) % 3] < 0) break;
  }
  const int a = v[r], b = v[(r + 1) % 3], c = v[(r + 2) % 3];
  const int m0 = mid[r], m1 = mid[(r + 1) % 3];
  if (count == 1) {
    out.push_back({a, m0, c});
    out.push_back({m0, b, c});
    return;
  }
  out.push_back({m0, b, m1});
  const auto P = [&](int i) { return Eigen::Vector3d(f.points.row(i)); };
  if ((P(a) - P(m1)).norm() < (P(m0) - P(c)).norm()) {
    out.push_back({a, m0, m1});
    out.push_back({a, m1, c});
  } else {
    out.push_back({a, m0, c});
    out.push_back({m0, m1, c});
  }
}

// Edge -> number of triangles using it (1: face boundary, 2: interior).
std::unordered_map<std::uint64_t, int> edgeUse(const std::vector<Tri>& tris) {
  std::unordered_map<std::uint64_t, int> use;
  use.reserve(tris.size() * 2);
  for (const Tri& t : tris)
    for (int i = 0; i < 3; ++i) ++use[edgeKey(t[i], t[(i + 1) % 3])];
  return use;
}

// The face's mesh from BRepMesh, with the exact fields at its nodes and its boundary pieces.
bool loadFace(FaceMesh& m, const TopTools_IndexedMapOfShape& edges, int threads) {
  TopLoc_Location loc;
  const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(m.face, loc);
  if (tri.IsNull() || !tri->HasUVNodes() || tri->NbTriangles() == 0) return false;
  for (int i = 1; i <= tri->NbNodes(); ++i) m.uv.emplace_back(tri->UVNode(i).X(), tri->UVNode(i).Y());
  const bool reversed = m.face.Orientation() == TopAbs_REVERSED;
  for (int i = 1; i <= tri->NbTriangles(); ++i) {
    int a, b, c;
    tri->Triangle(i).Get(a, b, c);
    if (reversed) std::swap(b, c);
    m.tris.push_back({a - 1, b - 1, c - 1});
  }
  appendFields(m, m.face, 0, threads);
  for (TopExp_Explorer ex(m.face, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge e = TopoDS::Edge(ex.Current());
    // A seam is met twice, once per orientation, each with its own polygon and pcurve: both sides
    // split at the same parameters. Degenerate edges (poles) have no length to split.
    if (BRep_Tool::Degenerated(e)) continue;
    const Handle(Poly_PolygonOnTriangulation) poly = BRep_Tool::PolygonOnTriangulation(e, tri, loc);
    if (poly.IsNull() || !poly->HasParameters()) continue;
    const int fe = static_cast<int>(m.edges.size());
    m.edges.push_back(e);
    for (int i = 1; i < poly->NbNodes(); ++i)
      m.segments.push_back({poly->Node(i) - 1, poly->Node(i + 1) - 1, edges.FindIndex(e), fe, poly->Parameter(i),
                            poly->Parameter(i + 1)});
  }
  return true;
}

// Splits, pass after pass, every mesh edge whose exact end normals differ by more than the
// bound: interior edges per face, boundary pieces jointly in all faces that hold them.
std::string shortNumber(double x) {
  std::ostringstream s;
  s << std::setprecision(3) << x;
  return s.str();
}

int refine(std::vector<FaceMesh>& parts, const TessellationOptions& o, std::chrono::steady_clock::time_point start,
           TessellationResult& r) {
  Eigen::Index vertices = 0;
  for (const auto& m : parts) vertices += static_cast<Eigen::Index>(m.uv.size());
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const auto report = [&] {
    if (!o.progress) return;
    double used = static_cast<double>(vertices) / static_cast<double>(std::max<Eigen::Index>(o.maxVertices, 1));
    if (o.timeLimit > 0) used = std::max(used, elapsed() / o.timeLimit);
    if (!o.progress(std::min(used, 1.0))) throw Error("the tessellation was cancelled");
  };
  report();
  int pass = 0;
  for (; pass < o.maxPasses; ++pass) {
    std::set<SegmentKey> splitSegments;
    for (const auto& m : parts)
      for (const auto& sg : m.segments)
        if (normalAngle(m.fields, sg.a, sg.b) > o.maxNormalAngle) splitSegments.insert(segmentKey(sg));
    std::vector<std::unordered_map<std::uint64_t, int>> mids(parts.size());
    Eigen::Index added = 0;
    for (size_t p = 0; p < parts.size(); ++p) {
      const FaceMesh& m = parts[p];
      const auto use = edgeUse(m.tris);
      for (const Tri& t : m.tris)
        for (int i = 0; i < 3; ++i) {
          const int a = t[i], b = t[(i + 1) % 3];
          const auto key = edgeKey(a, b);
          if (use.at(key) == 2 && normalAngle(m.fields, a, b) > o.maxNormalAngle) mids[p].emplace(key, -1);
        }
      for (const auto& sg : m.segments)
        if (splitSegments.count(segmentKey(sg))) mids[p].emplace(edgeKey(sg.a, sg.b), -1);
      added += static_cast<Eigen::Index>(mids[p].size());
    }
    if (added == 0) return pass;
    const auto stop = [&](const std::string& why) {
      r.stoppedByBudget = true;
      r.warnings.push_back(why + ": refinement stopped at " + std::to_string(vertices) + " vertices, so neighbouring normals differ by more than " +
                           shortNumber(o.maxNormalAngle * 180 / M_PI) + " deg in places (stripes and colours are coarse there)");
      return pass;
    };
    if (vertices + added > o.maxVertices)
      return stop("the next pass would pass the vertex budget of " + std::to_string(o.maxVertices));
    // A pass costs about its new vertices at the rate seen so far (the first mesh included).
    if (o.timeLimit > 0 && elapsed() * (1.0 + static_cast<double>(added) / static_cast<double>(vertices)) > o.timeLimit)
      return stop("the next pass would pass the time limit of " + shortNumber(o.timeLimit) + " s");
    vertices += added;
    for (size_t p = 0; p < parts.size(); ++p) {
      FaceMesh& m = parts[p];
      auto& mid = mids[p];
      if (mid.empty()) continue;
      const size_t from = m.uv.size();
      // Boundary pieces: the midpoint in edge parameter, placed by the edge's pcurve on this face.
      std::vector<BoundarySegment> segments;
      for (const auto& sg : m.segments) {
        const auto it = mid.find(edgeKey(sg.a, sg.b));
        if (it == mid.end()) { segments.push_back(sg); continue; }
        const double tm = 0.5 * (sg.ta + sg.tb);
        // On a seam the two sides have their own pcurves, and OCCT's polygon and pcurve lookups
        // do not pick sides the same way: take the side that passes through this piece's start.
        const Eigen::Vector2d qa = m.uv[static_cast<size_t>(sg.a)], qb = m.uv[static_cast<size_t>(sg.b)];
        Handle(Geom2d_Curve) pc;
        double best = std::numeric_limits<double>::infinity();
        for (int side = 0; side < 2; ++side) {
          TopoDS_Edge e = m.edges[static_cast<size_t>(sg.faceEdge)];
          if (side) e.Reverse();
          double f, l;
          const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(e, m.face, f, l);
          if (c.IsNull()) continue;
          const gp_Pnt2d p0 = c->Value(sg.ta);
          const double d = (Eigen::Vector2d(p0.X(), p0.Y()) - qa).norm();
          if (d < best) { best = d; pc = c; }
        }
        const gp_Pnt2d q = pc.IsNull() ? gp_Pnt2d() : pc->Value(tm);
        if (pc.IsNull() || (Eigen::Vector2d(q.X(), q.Y()) - 0.5 * (qa + qb)).norm() > 0.5 * (qb - qa).norm()) {
          mid.erase(it);  // no usable pcurve here: keep the piece (the other face may still split it)
          segments.push_back(sg);
          continue;
        }
        it->second = static_cast<int>(m.uv.size());
        m.uv.emplace_back(q.X(), q.Y());
        segments.push_back({sg.a, it->second, sg.edge, sg.faceEdge, sg.ta, tm});
        segments.push_back({it->second, sg.b, sg.edge, sg.faceEdge, tm, sg.tb});
      }
      m.segments.swap(segments);
      for (auto& [key, idx] : mid) {
        if (idx >= 0) continue;
        const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
        idx = static_cast<int>(m.uv.size());
        m.uv.push_back(0.5 * (m.uv[a] + m.uv[b]));
      }
      appendFields(m, m.face, from, o.threads);
      std::vector<Tri> next;
      next.reserve(m.tris.size() * 2);
      for (const Tri& t : m.tris) {
        std::array<int, 3> md;
        for (int i = 0; i < 3; ++i) {
          const auto it = mid.find(edgeKey(t[i], t[(i + 1) % 3]));
          md[i] = it == mid.end() ? -1 : it->second;
        }
        splitTriangle(t, md, m.fields, next);
      }
      m.tris.swap(next);
    }
    report();
  }
  return pass;
}

}  // namespace

TessellationResult tessellateForInspection(const TopoDS_Shape& shape, const TessellationOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (shape.IsNull()) throw Error("the shape is empty: nothing to inspect");
  if (!(o.maxNormalAngle > 0) || !(o.relativeDeflection > 0))
    throw Error("tessellation needs a positive normal-angle bound and deflection");
  // BRepMesh stores its triangulation in the shape it meshes: mesh a copy, the caller's shape stays as it was.
  const TopoDS_Shape work = BRepBuilderAPI_Copy(shape, true, false).Shape();
  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(work, TopAbs_FACE, faces);
  TopExp::MapShapes(work, TopAbs_EDGE, edges);
  if (faces.IsEmpty()) throw Error("the shape has no faces: curvature and zebra need surfaces");
  std::vector<int> wanted = o.faces;
  if (wanted.empty())
    for (int k = 1; k <= faces.Extent(); ++k) wanted.push_back(k);
  for (int k : wanted)
    if (k < 1 || k > faces.Extent())
      throw Error("face " + std::to_string(k) + " does not exist: the shape has " + std::to_string(faces.Extent()) + " faces");

  Bnd_Box box;
  BRepBndLib::Add(work, box);
  TessellationResult r;
  InspectionMesh& mesh = r.mesh;
  mesh.diagonal = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
  if (!(mesh.diagonal > 0) || !std::isfinite(mesh.diagonal)) throw Error("the shape has no finite extent");
  // BRepMesh only starts: it is slow at small angles (37 s for 0.5 deg on a filleted box), our splits are not.
  BRepMesh_IncrementalMesh(work, o.relativeDeflection * mesh.diagonal, false, std::max(o.maxNormalAngle, kBRepMeshAngle), true);
  std::vector<FaceMesh> parts;
  for (int k : wanted) {
    FaceMesh m;
    m.face = TopoDS::Face(faces(k));
    m.index = k;
    if (!loadFace(m, edges, o.threads)) {
      r.warnings.push_back("face " + std::to_string(k) + " could not be meshed and is left out");
      continue;
    }
    parts.push_back(std::move(m));
  }
  r.passes = refine(parts, o, t0, r);
  if (parts.empty()) throw Error("no face of the shape could be meshed");

  // Gather the faces into one mesh and measure what the refinement reached.
  Eigen::Index nv = 0, nt = 0;
  for (const auto& p : parts) { nv += static_cast<Eigen::Index>(p.uv.size()); nt += static_cast<Eigen::Index>(p.tris.size()); }
  mesh.fields.resize(nv);
  mesh.uv.resize(nv, 2);
  mesh.triangles.resize(nt, 3);
  std::vector<Eigen::Index> offset;
  Eigen::Index v0 = 0, t0i = 0;
  for (size_t p = 0; p < parts.size(); ++p) {
    const FaceMesh& m = parts[p];
    offset.push_back(v0);
    mesh.fields.place(v0, m.fields);
    for (size_t i = 0; i < m.uv.size(); ++i) mesh.uv.row(v0 + static_cast<Eigen::Index>(i)) = m.uv[i];
    mesh.vertexFace.insert(mesh.vertexFace.end(), m.uv.size(), parts[p].index);
    const auto use = edgeUse(m.tris);
    for (const Tri& t : m.tris) {
      mesh.triangles.row(t0i++) << t[0] + v0, t[1] + v0, t[2] + v0;
      mesh.triangleFace.push_back(parts[p].index);
      for (int i = 0; i < 3; ++i) {
        const double a = normalAngle(m.fields, t[i], t[(i + 1) % 3]);
        double& worst = use.at(edgeKey(t[i], t[(i + 1) % 3])) == 2 ? r.maxInteriorNormalAngle : r.maxBoundaryNormalAngle;
        worst = std::max(worst, a);
      }
    }
    v0 += static_cast<Eigen::Index>(m.uv.size());
  }
  r.faces = static_cast<int>(parts.size());
  // Singular points (poles, apexes) have no surface normal: shade them with the mesh normal around them.
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3d a = mesh.fields.points.row(mesh.triangles(t, 0)), b = mesh.fields.points.row(mesh.triangles(t, 1)),
                          c = mesh.fields.points.row(mesh.triangles(t, 2));
    for (int i = 0; i < 3; ++i)
      if (!mesh.fields.regular[static_cast<size_t>(mesh.triangles(t, i))])
        mesh.fields.normals.row(mesh.triangles(t, i)) += (b - a).cross(c - a);
  }
  for (Eigen::Index i = 0; i < nv; ++i)
    if (!mesh.fields.regular[static_cast<size_t>(i)] && mesh.fields.normals.row(i).norm() > 0) mesh.fields.normals.row(i).normalize();

  // Face boundaries: each edge once, through the nodes of the first meshed face that holds it.
  std::map<int, std::vector<std::pair<double, Eigen::Index>>> edgeNodes;
  std::map<int, size_t> edgePart;
  for (size_t p = 0; p < parts.size(); ++p)
    for (const auto& sg : parts[p].segments) {
      if (edgePart.emplace(sg.edge, p).first->second != p) continue;
      auto& nodes = edgeNodes[sg.edge];
      nodes.emplace_back(sg.ta, offset[p] + sg.a);
      nodes.emplace_back(sg.tb, offset[p] + sg.b);
    }
  for (auto& [e, nodes] : edgeNodes) {
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end(), [](const auto& x, const auto& y) { return x.first == y.first; }), nodes.end());
    Eigen::MatrixX3d line(static_cast<Eigen::Index>(nodes.size()), 3);
    for (size_t i = 0; i < nodes.size(); ++i) line.row(static_cast<Eigen::Index>(i)) = mesh.fields.points.row(nodes[i].second);
    mesh.edgePolylines.push_back(std::move(line));
    mesh.edgeIndex.push_back(e);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace holefill
