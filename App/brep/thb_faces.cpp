#include "brep/thb_faces.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include "geometry/error.h"

namespace holefill {

TopoDS_Shape thbCellFaces(const ThbSpace& space, const BSplineSurface& surface) {
  const Handle(Geom_BSplineSurface) s = toOcct(surface);
  BRepBuilderAPI_Sewing sewing(1e-7 * std::max(1.0, surface.poles.cwiseAbs().maxCoeff()));
  int faces = 0;
  for (const auto& [l, i, j] : space.leafCells()) {
    const double u0 = double(i) / space.cellsU(l), u1 = double(i + 1) / space.cellsU(l);
    const double v0 = double(j) / space.cellsV(l), v1 = double(j + 1) / space.cellsV(l);
    BRepBuilderAPI_MakeFace mf(s, u0, u1, v0, v1, 1e-7);
    if (!mf.IsDone()) throw Error("could not build the face of THB cell (" + std::to_string(l) + ", " + std::to_string(i) + ", " + std::to_string(j) + ")");
    sewing.Add(mf.Face());
    ++faces;
  }
  sewing.Perform();
  const TopoDS_Shape sewn = sewing.SewedShape();
  int shells = 0;
  for (TopExp_Explorer e(sewn, TopAbs_SHELL); e.More(); e.Next()) ++shells;
  if (shells != 1) throw Error("the " + std::to_string(faces) + " cell faces did not sew into one shell (" + std::to_string(shells) + " shells)");
  return sewn;
}

}  // namespace holefill
