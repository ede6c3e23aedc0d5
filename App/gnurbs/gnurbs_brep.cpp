#include "gnurbs/gnurbs_brep.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <functional>
#include <vector>

#include "geometry/error.h"
#include "geometry/json_writer.h"

namespace holefill {

namespace {

// A B-rep face's patches: one patch, or a rectangle faces[row][col] of regular control faces,
// face (r, c+1) across edge 1 of (r, c) (entered by its edge 3), (r+1, c) across edge 2 (by 0).
struct FaceGroup {
  std::vector<int> patches;                 // indices into result.patches
  std::vector<std::vector<int>> grid;       // control faces, when merged
};

std::vector<FaceGroup> groupPatches(const G2GnurbsResult& r, bool merge) {
  const CageTopology topo(r.cage);
  const int nf = topo.faceCount();
  std::vector<int> bicubic(nf, -1);  // patch index of a regular face's bicubic patch
  for (size_t i = 0; i < r.patches.size(); ++i)
    if (r.patches[i].sub < 0) bicubic[r.patches[i].face] = static_cast<int>(i);
  std::vector<bool> used(nf, false);
  auto next = [&](int f, int edge, int entry) {
    const int g = f < 0 ? -1 : topo.acrossFace(f, edge);
    return g >= 0 && topo.acrossEdge(f, edge) == entry && bicubic[g] >= 0 && !used[g] ? g : -1;
  };
  std::vector<FaceGroup> groups;
  for (size_t i = 0; i < r.patches.size(); ++i) {
    const int f = r.patches[i].face;
    if (!merge || r.patches[i].sub >= 0) {
      groups.push_back({{static_cast<int>(i)}, {}});
      continue;
    }
    if (used[f]) continue;
    std::vector<int> row = {f};
    used[f] = true;
    for (int g = next(f, 1, 3); g >= 0; g = next(g, 1, 3)) {
      row.push_back(g);
      used[g] = true;
    }
    FaceGroup group;
    group.grid.push_back(row);
    for (;;) {  // the next row must span the whole width
      std::vector<int> above;
      for (size_t c = 0; c < row.size(); ++c) {
        const int g = next(row[c], 2, 0);
        if (g < 0 || (c > 0 && topo.acrossFace(above.back(), 1) != g)) break;
        above.push_back(g);
      }
      if (above.size() != row.size()) break;
      for (int g : above) used[g] = true;
      group.grid.push_back(above);
      row = above;
    }
    for (const auto& rw : group.grid)
      for (int g : rw) group.patches.push_back(bicubic[g]);
    groups.push_back(group);
  }
  return groups;
}

// One B-spline surface over a rectangle of bicubic patches: their control nets side by side with
// triple interior knots at the cumulative knot intervals (exact), then each interior knot
// removed down to the multiplicity the geometry allows within `tol`.
Handle(Geom_BSplineSurface) mergedSurface(const G2GnurbsResult& r, const FaceGroup& g, const std::vector<int>& patchOf, double tol) {
  const int rows = static_cast<int>(g.grid.size()), cols = static_cast<int>(g.grid[0].size());
  TColgp_Array2OfPnt poles(1, 3 * cols + 1, 1, 3 * rows + 1);
  for (int rr = 0; rr < rows; ++rr)
    for (int c = 0; c < cols; ++c) {
      const BSplineSurface& s = r.patches[patchOf[g.grid[rr][c]]].surface;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const auto p = s.poles.row(s.index(a, b));
          poles.SetValue(3 * c + a + 1, 3 * rr + b + 1, gp_Pnt(p(0), p(1), p(2)));
        }
    }
  auto knots = [&](int n, const std::function<double(int)>& interval) {
    TColStd_Array1OfReal k(1, n + 1);
    TColStd_Array1OfInteger m(1, n + 1);
    double t = 0;
    for (int i = 0; i <= n; ++i) {
      k.SetValue(i + 1, t);
      m.SetValue(i + 1, i == 0 || i == n ? 4 : 3);
      if (i < n) t += interval(i);
    }
    return std::make_pair(k, m);
  };
  const QuadCage& cage = r.cage;
  const auto [ku, mu] = knots(cols, [&](int c) { const int f = g.grid[0][c]; return cage.knot(cage.quads(f, 0), cage.quads(f, 1)); });
  const auto [kv, mv] = knots(rows, [&](int rr) { const int f = g.grid[rr][0]; return cage.knot(cage.quads(f, 0), cage.quads(f, 3)); });
  Handle(Geom_BSplineSurface) s = new Geom_BSplineSurface(poles, ku, kv, mu, mv, 3, 3);
  for (int i = s->NbUKnots() - 1; i >= 2; --i) s->RemoveUKnot(i, 1, tol) || s->RemoveUKnot(i, 2, tol);
  for (int i = s->NbVKnots() - 1; i >= 2; --i) s->RemoveVKnot(i, 1, tol) || s->RemoveVKnot(i, 2, tol);
  return s;
}

}  // namespace

GnurbsBrep gnurbsToBrep(const G2GnurbsResult& result, const GnurbsBrepOptions& options) {
  if (result.patches.empty()) throw Error("the G-NURBS result has no patches to export");
  const Eigen::MatrixX3d& V = result.cage.vertices;
  const double diagonal = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
  const double tol = options.sewTolerance * std::max(diagonal, 1e-12);

  const std::vector<FaceGroup> groups = groupPatches(result, options.mergeRegular);
  std::vector<int> patchOf(result.cage.quads.rows(), -1);
  for (size_t i = 0; i < result.patches.size(); ++i)
    if (result.patches[i].sub < 0) patchOf[result.patches[i].face] = static_cast<int>(i);
  std::vector<TopoDS_Face> faces;
  BRepBuilderAPI_Sewing sewing(tol);  // cutting on: a merged face's edges meet several of its neighbours'
  GnurbsBrep out;
  for (const FaceGroup& g : groups) {
    const GnurbsPatch& p = result.patches[g.patches[0]];
    Handle(Geom_BSplineSurface) surface;
    if (g.patches.size() > 1) {
      surface = mergedSurface(result, g, patchOf, tol);
      ++out.mergedFaces;
    } else {
      surface = toOcct(p.surface);
    }
    BRepBuilderAPI_MakeFace mf(surface, tol);
    if (!mf.IsDone()) throw Error("could not make a face of control face " + std::to_string(p.face));
    faces.push_back(mf.Face());
    sewing.Add(faces.back());
  }
  sewing.Perform();
  // A shell in our order: each face as sewing made it (sharing edges with its neighbours).
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  for (size_t k = 0; k < faces.size(); ++k) {
    const TopoDS_Shape f = sewing.IsModified(faces[k]) ? sewing.Modified(faces[k]) : TopoDS_Shape(faces[k]);
    // Sewing drops a face it finds degenerate (a patch collapsed to a curve by coincident cage
    // vertices, found by fuzzing), and adding the null shape it leaves crashed in OCCT.
    if (f.IsNull())
      throw Error("the patch of control face " + std::to_string(result.patches[groups[k].patches[0]].face) +
                  " is degenerate (coincident cage vertices?): sewing removed it");
    builder.Add(shell, f);
  }

  out.faces = static_cast<int>(faces.size());
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(shell, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int i = 1; i <= edgeFaces.Extent(); ++i)
    if (edgeFaces(i).Extent() < 2) ++out.freeEdges;
  out.closed = out.freeEdges == 0;
  shell.Closed(out.closed);
  out.shape = shell;
  out.valid = BRepCheck_Analyzer(shell).IsValid();

  JsonWriter j;
  j.beginObject().field("refinements", result.refinements).key("faces").beginArray();
  for (size_t i = 0; i < groups.size(); ++i) {
    const GnurbsPatch& p = result.patches[groups[i].patches[0]];
    j.beginObject()
        .field("name", "Face" + std::to_string(i + 1))
        .field("control_face", p.face)
        .field("sub_patch", p.sub)
        .field("input_face", result.refinements > 0 ? p.face / 4 : p.face);  // catmullClarkStep: child 4f + k
    if (groups[i].patches.size() > 1) {
      std::vector<int> all;
      for (int k : groups[i].patches) all.push_back(result.patches[k].face);
      j.field("control_faces", all);
    }
    j.endObject();
  }
  j.endArray().endObject();
  out.sidecarJson = j.str();
  return out;
}

}  // namespace holefill
