#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <cmath>

#include "brep/thb_faces.h"
#include "geometry/bspline_basis.h"
#include "geometry/occt_bridge.h"

using namespace holefill;

namespace {

// A cubic surface over [0, 1]² with the knots of `cells` × `cells` cells: a wavy sheet.
BSplineSurface wavy(int cells) {
  BSplineSurface s;
  s.knotsU = clampedUniformKnots(3, cells, 0, 1);
  s.knotsV = clampedUniformKnots(3, cells, 0, 1);
  const int n = cells + 3;
  s.poles.resize(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.poles.row(i * n + j) << double(i) / (n - 1), double(j) / (n - 1), 0.1 * std::sin(2.0 * i) * std::cos(1.3 * j);
  return s;
}

double area(const TopoDS_Shape& s) {
  GProp_GProps g;
  BRepGProp::SurfaceProperties(s, g, 1e-10);  // adaptive, to this relative precision (the default rule is not)
  return g.Mass();
}

}  // namespace

// One face per leaf cell of the hierarchical mesh, sewn into one valid shell whose faces together
// are the whole surface (the same area as the single finest-level face) and meet along the
// cells' edges (one free boundary: the square's).
TEST(ThbFaces, OneFacePerLeafCellCoveringTheSurface) {
  ThbSpace space(3, 4, 4);
  space.refine(0, {{0, 0}});                 // the lower-left cell into four
  const BSplineSurface s = wavy(8);          // the finest level's knots: 4 << 1 cells a direction
  const TopoDS_Shape shell = thbCellFaces(space, s);
  int faces = 0;
  for (TopExp_Explorer e(shell, TopAbs_FACE); e.More(); e.Next()) ++faces;
  EXPECT_EQ(faces, static_cast<int>(space.leafCells().size()));
  EXPECT_EQ(faces, 15 + 4);
  EXPECT_TRUE(BRepCheck_Analyzer(shell).IsValid());
  const TopoDS_Face whole = BRepBuilderAPI_MakeFace(toOcct(s), 1e-7).Face();
  EXPECT_NEAR(area(shell), area(whole), 1e-9 * area(whole));
}
