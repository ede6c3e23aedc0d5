#include "brep/continuity_report.h"

#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <cmath>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <filesystem>

#include "brep/edge_continuity.h"
#include "brep/sample_models.h"
#include "brep/shape_io.h"

using namespace holefill;

namespace {

// The first solid of an OCCT sample model (Debian's occt-misc) without its k-th face (1-based, in
// TopExp order, as FreeCAD numbers them): a real part with a hole, the face kept as its truth.
bool partWithoutFace(const std::string& file, int k, TopoDS_Shape& holed, TopoDS_Face& removed) {
  const std::string path = "/usr/share/opencascade/data/occ/" + file;
  if (!std::filesystem::exists(path)) return false;
  TopoDS_Shape part = readShape(path);
  TopExp_Explorer solids(part, TopAbs_SOLID);
  if (solids.More()) part = solids.Current();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(part, TopAbs_FACE, faces);
  BRep_Builder B;
  TopoDS_Shell shell;
  B.MakeShell(shell);
  for (int i = 1; i <= faces.Extent(); ++i)
    if (i == k) removed = TopoDS::Face(faces(i));
    else B.Add(shell, faces(i));
  holed = shell;
  return !removed.IsNull();
}

// The one hole of partWithoutFace's part, and its truth; false when the model is not installed.
bool realHole(const std::string& file, int k, Hole& hole, TopoDS_Face& truth) {
  TopoDS_Shape holed;
  if (!partWithoutFace(file, k, holed, truth)) return false;
  const HoleDetectionResult det = detectHoles(holed);
  if (det.holes.size() != 1) ADD_FAILURE() << file << " without face " << k << ": " << det.holes.size() << " holes";
  if (det.holes.empty()) return false;
  hole = det.holes[0];
  return true;
}

}  // namespace

TEST(ContinuityReport, ExactNeighboursHaveNoFloor) {
  // An OCCT-made cylinder is exact: its side meets its cap along the circle with the edge lying
  // in both faces (g1Floor ~ 0) at OCCT's default tolerance, at a right angle (G1 = pi/2).
  const TopoDS_Shape cyl = BRepPrimAPI_MakeCylinder(10, 30).Shape();
  const ContinuityReport r = faceContinuity(cyl, 1, 2);
  ASSERT_FALSE(r.edges.empty());
  for (const auto& e : r.edges) {
    EXPECT_LT(e.g1Floor, 1e-9);
    EXPECT_LE(e.toleranceBefore, 1e-6);
    EXPECT_NEAR(e.g1, M_PI / 2, 1e-6);
    EXPECT_LT(e.g0, 1e-9);
  }
}

TEST(ContinuityReport, InexactNeighboursShowTheirOwnAccuracy) {
  // Top.brep face 138 (a B-spline patch from an imported model): its edges' 3D curves lie off their
  // neighbours by up to their tolerances, and the neighbours meet them at an angle. The report gives
  // the original face's own errors against the hole, beside what the model allows at each edge.
  Hole hole;
  TopoDS_Face truth;
  if (!realHole("Top.brep", 138, hole, truth)) GTEST_SKIP() << "occt-misc's Top.brep is not installed";
  const ContinuityReport r = continuityReport(truth, hole);
  ASSERT_EQ(r.edges.size(), hole.edges.size());
  double worstFloor = 0, worstTolerance = 0;
  for (size_t i = 0; i < r.edges.size(); ++i) {
    EXPECT_EQ(r.edges[i].toleranceBefore, hole.edges[i].tolerance);
    worstFloor = std::max(worstFloor, r.edges[i].g1Floor);
    worstTolerance = std::max(worstTolerance, r.edges[i].toleranceBefore);
    // The original face is no better than the model allows: its G1 error is at least near the floor.
    EXPECT_GE(r.edges[i].g1 + 1e-6, 0.5 * r.edges[i].g1Floor);
  }
  EXPECT_GT(worstFloor, 1e-5);                 // the model's own angle between edge and neighbour
  EXPECT_GT(worstTolerance, 1e-6 * r.scale);   // an edge placed less exactly than the strict tier
  EXPECT_GT(r.g0Relative, 1e-6);               // so even the original face misses the strict G0 tier
}

TEST(ContinuityReport, TiltedNeighboursAtCornersRaiseTheFloor) {
  // hammer.brep face 2: a 15:1 B-spline strip whose neighbours, at the strip's corners, are tilted
  // 2.8e-3 rad off the plane of the two edges meeting there. Any surface through both edge curves
  // has that plane as its tangent plane at the corner, so G1 <= 1e-3 cannot hold there against
  // those neighbours: the floor of each edge at such a corner is at least the tilt.
  Hole hole;
  TopoDS_Face truth;
  if (!realHole("hammer.brep", 2, hole, truth)) GTEST_SKIP() << "occt-misc's hammer.brep is not installed";
  const std::vector<double> tilt = cornerMismatch(hole);
  const ContinuityReport r = continuityReport(truth, hole);
  int tilted = 0;
  for (size_t i = 0; i < r.edges.size(); ++i) {
    if (tilt[i] > 1e-3 && tilt[i] < 1e-2) ++tilted;  // tilted, yet far from a crease
    EXPECT_GE(r.edges[i].g1Floor, tilt[i]);
  }
  EXPECT_GE(tilted, 2);
}

TEST(ContinuityReport, FilletedBoxCornerIsTangentButNotCurvatureContinuous) {
  // The vertex blend of a box filleted with radius r is a sphere of radius r meeting three
  // cylinders along quarter circles: tangent (G1 ~ 0), but across each edge the sphere bends by
  // 1/r and the cylinder (along its axis) not at all, so G2 = (1/r) / (1/scale) = scale / r with
  // scale the quarter circle's box diagonal r*sqrt(2): sqrt(2), whatever r. No fill of that corner
  // can be G2 against the cylinders (hole_fill_test's UnreachableG2IsReportedNotDowngraded).
  TopTools_IndexedMapOfShape boxEdges;
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(100, 80, 60).Shape();
  BRepFilletAPI_MakeFillet fillet(box);
  TopExp::MapShapes(box, TopAbs_EDGE, boxEdges);
  for (int i = 1; i <= boxEdges.Extent(); ++i) fillet.Add(12.0, TopoDS::Edge(boxEdges(i)));
  const TopoDS_Shape rounded = fillet.Shape();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(rounded, TopAbs_FACE, faces);
  int sphere = 0;
  for (int i = 1; i <= faces.Extent() && !sphere; ++i)
    if (BRepAdaptor_Surface(TopoDS::Face(faces(i))).GetType() == GeomAbs_Sphere) sphere = i;
  ASSERT_GT(sphere, 0);
  int neighbours = 0;
  for (int i = 1; i <= faces.Extent(); ++i) {
    if (i == sphere) continue;
    ContinuityReport r;
    try {
      r = faceContinuity(rounded, i, sphere);
    } catch (const std::exception&) {
      continue;  // not adjacent
    }
    ++neighbours;
    EXPECT_LT(r.g1, 1e-6);
    EXPECT_NEAR(r.g2, std::sqrt(2.0), 1e-3);
    // The samples carry what G2 compared, for the combs: the sphere bends by 1/r across (away
    // from its outward normal: -1/r), the cylinder along its axis not at all.
    for (const ContinuitySample& s : r.along) {
      EXPECT_NEAR(s.curvatureFace, -1.0 / 12.0, 1e-6);
      EXPECT_NEAR(s.curvatureSupport, 0.0, 1e-9);
      EXPECT_NEAR(s.normal.norm(), 1.0, 1e-12);
    }
  }
  EXPECT_EQ(neighbours, 3);
}
