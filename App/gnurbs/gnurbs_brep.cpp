#include "gnurbs/gnurbs_brep.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <vector>

#include "geometry/error.h"
#include "geometry/json_writer.h"

namespace holefill {

GnurbsBrep gnurbsToBrep(const G2GnurbsResult& result, const GnurbsBrepOptions& options) {
  if (result.patches.empty()) throw Error("the G-NURBS result has no patches to export");
  const Eigen::MatrixX3d& V = result.cage.vertices;
  const double diagonal = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
  const double tol = options.sewTolerance * std::max(diagonal, 1e-12);

  std::vector<TopoDS_Face> faces;
  BRepBuilderAPI_Sewing sewing(tol);
  for (const GnurbsPatch& p : result.patches) {
    BRepBuilderAPI_MakeFace mf(toOcct(p.surface), tol);
    if (!mf.IsDone()) throw Error("could not make a face of control face " + std::to_string(p.face));
    faces.push_back(mf.Face());
    sewing.Add(faces.back());
  }
  sewing.Perform();
  // A shell in our order: each face as sewing made it (sharing edges with its neighbours).
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  for (const TopoDS_Face& f : faces) builder.Add(shell, sewing.IsModified(f) ? sewing.Modified(f) : f);

  GnurbsBrep out;
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
  for (size_t i = 0; i < result.patches.size(); ++i) {
    const GnurbsPatch& p = result.patches[i];
    j.beginObject()
        .field("name", "Face" + std::to_string(i + 1))
        .field("control_face", p.face)
        .field("sub_patch", p.sub)
        .field("input_face", result.refinements > 0 ? p.face / 4 : p.face)  // catmullClarkStep: child 4f + k
        .endObject();
  }
  j.endArray().endObject();
  out.sidecarJson = j.str();
  return out;
}

}  // namespace holefill
