#include "inspect/shape_tessellation.h"

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <cmath>

#include "brep/sample_models.h"
#include "geometry/error.h"

using namespace holefill;

namespace {

double maxTriangleNormalSpread(const InspectionMesh& m) {
  double worst = 0;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Eigen::Index a = m.triangles(t, i), b = m.triangles(t, (i + 1) % 3);
      if (!m.fields.regular[a] || !m.fields.regular[b]) continue;
      worst = std::max(worst, std::acos(std::clamp(m.fields.normals.row(a).dot(m.fields.normals.row(b)), -1.0, 1.0)));
    }
  return worst;
}

}  // namespace

TEST(ShapeTessellation, SphereMeetsTheNormalBoundWithExactPoints) {
  const double r = 5.0;
  TessellationOptions o;
  o.maxNormalAngle = 3.0 * M_PI / 180;
  const TessellationResult t = tessellateForInspection(BRepPrimAPI_MakeSphere(r).Shape(), o);
  const InspectionMesh& m = t.mesh;
  ASSERT_GT(m.triangles.rows(), 100);
  EXPECT_LE(t.maxInteriorNormalAngle, o.maxNormalAngle);
  EXPECT_LE(t.maxBoundaryNormalAngle, o.maxNormalAngle);
  EXPECT_LE(maxTriangleNormalSpread(m), o.maxNormalAngle + 1e-12);
  for (Eigen::Index i = 0; i < m.fields.size(); ++i) {
    EXPECT_NEAR(m.fields.points.row(i).norm(), r, 1e-9);
    if (m.fields.regular[i]) EXPECT_NEAR(m.fields.k1(i), 1 / r, 1e-9);
  }
  // Triangles are counter-clockwise seen from outside.
  int outward = 0, proper = 0;
  for (Eigen::Index k = 0; k < m.triangles.rows(); ++k) {
    const Eigen::Vector3d a = m.fields.points.row(m.triangles(k, 0)), b = m.fields.points.row(m.triangles(k, 1)),
                          c = m.fields.points.row(m.triangles(k, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() < 1e-9 * r * r) continue;  // BRepMesh's slivers with two corners on a pole
    ++proper;
    outward += n.dot(a + b + c) > 0;
  }
  EXPECT_EQ(outward, proper);
  EXPECT_GT(proper, m.triangles.rows() * 0.99);
}

TEST(ShapeTessellation, RefinementSplitsInteriorEdgesUntilTheBoundHolds) {
  // A tight bound forces refinement passes on top of BRepMesh on a B-spline fill-like surface.
  TessellationOptions o;
  o.maxNormalAngle = 0.5 * M_PI / 180;
  const TessellationResult t = tessellateForInspection(samples::byName("cc_valence5"), o);
  EXPECT_LE(t.maxInteriorNormalAngle, o.maxNormalAngle * 1.0001);
  EXPECT_TRUE(t.warnings.empty());
  // Every triangle is a real one: no zero areas from the split patterns.
  for (Eigen::Index k = 0; k < t.mesh.triangles.rows(); ++k) {
    const Eigen::Vector3d a = t.mesh.fields.points.row(t.mesh.triangles(k, 0)),
                          b = t.mesh.fields.points.row(t.mesh.triangles(k, 1)),
                          c = t.mesh.fields.points.row(t.mesh.triangles(k, 2));
    ASSERT_GT((b - a).cross(c - a).norm(), 0.0);
  }
}

TEST(ShapeTessellation, TrimmedFacesStayInsideTheirTrim) {
  const TopoDS_Shape shape = samples::byName("panel_6_sided");
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  const TessellationResult t = tessellateForInspection(shape);
  int outside = 0;
  for (Eigen::Index i = 0; i < t.mesh.fields.size(); ++i) {
    const TopoDS_Face f = TopoDS::Face(faces(t.mesh.vertexFace[i]));
    BRepClass_FaceClassifier c(f, gp_Pnt2d(t.mesh.uv(i, 0), t.mesh.uv(i, 1)), 1e-7);
    outside += c.State() == TopAbs_OUT;
  }
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(t.faces, faces.Extent());
  EXPECT_FALSE(t.mesh.edgePolylines.empty());
}

TEST(ShapeTessellation, OnlyTheAskedFacesAndTheInputIsNotModified) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1, 2, 3).Shape();
  TessellationOptions o;
  o.faces = {2, 5};
  const TessellationResult t = tessellateForInspection(box, o);
  EXPECT_EQ(t.faces, 2);
  for (int f : t.mesh.triangleFace) EXPECT_TRUE(f == 2 || f == 5);
  TopLoc_Location loc;
  for (TopExp_Explorer ex(box, TopAbs_FACE); ex.More(); ex.Next())
    EXPECT_TRUE(BRep_Tool::Triangulation(TopoDS::Face(ex.Current()), loc).IsNull());
}

TEST(ShapeTessellation, BadInputsGiveClearErrors) {
  EXPECT_THROW(tessellateForInspection(TopoDS_Shape()), Error);
  EXPECT_THROW(tessellateForInspection(BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 0)).Shape()), Error);
  TessellationOptions o;
  o.faces = {7};
  try {
    tessellateForInspection(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("face 7 does not exist"), std::string::npos);
  }
  o.faces.clear();
  o.maxNormalAngle = std::nan("");
  EXPECT_THROW(tessellateForInspection(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), o), Error);
}

// Issue 22: an overlay on a surface that bends a lot (here a tight bound on the valence-5 fill)
// must stop at its budget with a whole mesh and say so, not refine for a minute.
TEST(ShapeTessellation, VertexBudgetStopsRefinementWithAWholeMesh) {
  TessellationOptions o;
  o.maxNormalAngle = 0.5 * M_PI / 180;
  const TopoDS_Shape shape = samples::byName("cc_valence5");
  const TessellationResult free = tessellateForInspection(shape, o);
  ASSERT_FALSE(free.stoppedByBudget);
  o.maxVertices = free.mesh.fields.size() / 3;
  const TessellationResult t = tessellateForInspection(shape, o);
  EXPECT_TRUE(t.stoppedByBudget);
  EXPECT_LE(t.mesh.fields.size(), o.maxVertices);
  EXPECT_LT(t.passes, free.passes);
  ASSERT_FALSE(t.warnings.empty());
  EXPECT_NE(t.warnings.back().find("vertex budget"), std::string::npos) << t.warnings.back();
  EXPECT_GT(t.maxInteriorNormalAngle, o.maxNormalAngle);  // what the warning says was not reached
  for (Eigen::Index k = 0; k < t.mesh.triangles.rows(); ++k)
    for (int i = 0; i < 3; ++i) ASSERT_LT(t.mesh.triangles(k, i), t.mesh.fields.size());
}

TEST(ShapeTessellation, TimeLimitStopsBeforeAPassThatWouldPassIt) {
  TessellationOptions o;
  o.maxNormalAngle = 0.5 * M_PI / 180;
  o.timeLimit = 1e-6;  // spent by the first mesh already: no refinement pass starts
  const TessellationResult t = tessellateForInspection(samples::byName("cc_valence5"), o);
  EXPECT_TRUE(t.stoppedByBudget);
  EXPECT_EQ(t.passes, 0);
  ASSERT_FALSE(t.warnings.empty());
  EXPECT_NE(t.warnings.back().find("time limit"), std::string::npos) << t.warnings.back();
}

TEST(ShapeTessellation, ProgressReportsAndCancels) {
  TessellationOptions o;
  o.maxNormalAngle = 0.5 * M_PI / 180;
  std::vector<double> seen;
  o.progress = [&](double f) { seen.push_back(f); return true; };
  const TessellationResult t = tessellateForInspection(samples::byName("cc_valence5"), o);
  ASSERT_EQ(static_cast<int>(seen.size()), t.passes + 1);  // the first mesh, then each pass
  for (size_t k = 0; k < seen.size(); ++k) {
    EXPECT_GE(seen[k], 0.0);
    EXPECT_LE(seen[k], 1.0);
    if (k > 0) EXPECT_GE(seen[k], seen[k - 1]);
  }
  o.progress = [](double) { return false; };
  EXPECT_THROW(tessellateForInspection(samples::byName("cc_valence5"), o), Error);
}
