#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "brep/shape_io.h"
#include "geometry/error.h"
#include "geometry/occt_bridge.h"
#include "gnurbs/cage_io.h"
#include "gnurbs/gnurbs_brep.h"
#include "gnurbs/gnurbs_report.h"
#include "gnurbs/sample_cages.h"

using namespace holefill;

TEST(CageIO, ObjRoundTripKeepsSharpEdgesKnotsAndAnchors) {
  QuadCage c = cages::polarCage(5, 2);
  c.setSharp(3, 4);
  c.setKnot(1, 2, 2.5);
  c.anchors[0] = Eigen::Vector3d(0.1, -0.2, 0.75);
  const QuadCage back = parseCageObj(formatCageObj(c));
  EXPECT_EQ(back.vertices, c.vertices);  // 17 significant digits: exact
  EXPECT_EQ(back.quads, c.quads);
  EXPECT_EQ(back.sharp, c.sharp);
  EXPECT_EQ(back.knots, c.knots);
  ASSERT_EQ(back.anchors.count(0), 1u);
  EXPECT_EQ(back.anchors.at(0), c.anchors.at(0));

  // 1-based comment lines, OBJ's a/t/n corners, other comments ignored.
  const QuadCage small = parseCageObj(
      "# a 2x1 strip\nv 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
      "f 1/1/1 2/2/2 5/5/5 4/4/4\nf 2 3 6 5\n# sharp 2 5\n# knot 1 2 0.5\n# any other comment\n");
  EXPECT_TRUE(small.isSharp(1, 4));
  EXPECT_EQ(small.knot(0, 1), 0.5);
  EXPECT_EQ(small.knot(1, 2), 1.0);
}

TEST(CageIO, BadCageFilesAndListsAreRefusedWithTheLineAndNothingChanged) {
  const std::string strip = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\n";
  auto message = [](const std::string& text) {
    try {
      parseCageObj(text, "t.obj");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n").find("line 4"), std::string::npos);        // a triangle
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n").find("quads"), std::string::npos);
  EXPECT_NE(message(strip + "v nan 0 0\n").find("not finite"), std::string::npos);
  EXPECT_NE(message(strip + "v 5 5 5\n").find("vertex 7 is used by no quad"), std::string::npos);       // isolated
  EXPECT_NE(message(strip + "# knot 1 2 0\n").find("positive"), std::string::npos);                     // zero interval
  EXPECT_NE(message(strip + "# sharp 1 3\n").find("not a cage edge"), std::string::npos);
  EXPECT_NE(message(strip + "f 1 2 5 4\n").find("non-manifold"), std::string::npos);                    // a repeated face
  EXPECT_NE(message(strip + "f 1 2 7 4\n").find("line 9"), std::string::npos);                          // index out of range
  EXPECT_NE(message("").find("empty"), std::string::npos);
  EXPECT_NE(message("v 0 0 0\n").find("no faces"), std::string::npos);
  EXPECT_EQ(message(strip + "\x01\xff garbage\nvt 0 0\n"), "accepted");  // unknown tags are skipped

  QuadCage c = parseCageObj(strip);
  const QuadCage before = c;
  EXPECT_THROW(addSharpEdgesFromJson(c, "[[1, 2], [1, 3]]"), Error);  // 1-3 is no edge
  EXPECT_THROW(addSharpEdgesFromJson(c, "[[1, 2, 3]]"), Error);
  EXPECT_THROW(addSharpEdgesFromJson(c, "[[0, 1]]"), Error);  // 1-based
  EXPECT_THROW(addSharpEdgesFromJson(c, "{\"1\": 2}"), Error);
  EXPECT_THROW(addAnchorsFromJson(c, "[[1, 0, 0, NaN]]"), Error);
  EXPECT_EQ(c.sharp, before.sharp);
  EXPECT_TRUE(c.anchors.empty());
  addSharpEdgesFromJson(c, " [ [1,2] , [2, 5] ] ");
  EXPECT_TRUE(c.isSharp(0, 1) && c.isSharp(1, 4));
  addAnchorsFromJson(c, "[]");
}

TEST(GnurbsBrep, SewnShellInControlFaceOrderWithTheSidecar) {
  const G2GnurbsResult r = buildG2Gnurbs(cages::polarCage(5, 2));
  const GnurbsBrep b = gnurbsToBrep(r);
  EXPECT_EQ(b.faces, static_cast<int>(r.patches.size()));
  EXPECT_EQ(b.faces, 5 * 4 + (20 - 5) * 1 + 0);  // 5 faces in the 1-ring × 4 sub-patches, 15 bicubic
  EXPECT_TRUE(b.valid);
  EXPECT_FALSE(b.closed);
  // Free edges: the cage boundary, each control edge of a 1-ring face split in two.
  int freeExpected = 0;
  const CageTopology t(r.cage);
  std::vector<bool> split(t.faceCount(), false);
  for (const auto& p : r.patches) split[p.face] = split[p.face] || p.sub >= 0;
  for (int f = 0; f < t.faceCount(); ++f)
    for (int k = 0; k < 4; ++k)
      if (t.acrossFace(f, k) < 0) freeExpected += split[f] ? 2 : 1;
  EXPECT_EQ(b.freeEdges, freeExpected);
  // Face i of the shell is patch i.
  int i = 0;
  for (TopExp_Explorer ex(b.shape, TopAbs_FACE); ex.More(); ex.Next(), ++i) {
    ASSERT_LT(i, b.faces);
    const Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(ex.Current()));
    EXPECT_LT((toEigen(s->Value(0.3, 0.6)) - r.patches[i].surface.point(0.3, 0.6)).norm(), 1e-12) << i;
  }
  EXPECT_EQ(i, b.faces);
  EXPECT_NE(b.sidecarJson.find("\"name\":\"Face1\""), std::string::npos) << b.sidecarJson.substr(0, 200);

  const G2GnurbsResult cube = buildG2Gnurbs(cages::cubeCage());
  const GnurbsBrep cb = gnurbsToBrep(cube);
  EXPECT_TRUE(cb.closed);
  EXPECT_EQ(cb.freeEdges, 0);
  EXPECT_TRUE(cb.valid);
  EXPECT_EQ(cb.faces, 24 * 4);
  // The shape survives a BREP text round trip (the Python door).
  EXPECT_NO_THROW(shapeFromBrepString(shapeToBrepString(cb.shape)));
  const GnurbsContinuity c = measureGnurbsContinuity(cube);
  EXPECT_LT(c.g1Spokes, 1e-8);
  EXPECT_LT(c.g2Spokes, 1e-6);
  EXPECT_EQ(c.edges, 48);
  EXPECT_NE(gnurbsReportJson(cube, c, &cb, 0.1).find("\"refinements\":1"), std::string::npos);
}

TEST(GnurbsBrep, RegularRectanglesMergeIntoC2BSplineFacesOfTheSameShape) {
  for (int n : {4, 5}) {
    SCOPED_TRACE("valence " + std::to_string(n));
    const G2GnurbsResult r = buildG2Gnurbs(cages::polarCage(n, 3));
    const GnurbsBrep plain = gnurbsToBrep(r);
    GnurbsBrepOptions o;
    o.mergeRegular = true;
    const GnurbsBrep merged = gnurbsToBrep(r, o);
    std::printf("valence %d: %d faces merged into %d (%d merged faces), valid %d, free edges %d -> %d\n", n, plain.faces, merged.faces,
                merged.mergedFaces, merged.valid, plain.freeEdges, merged.freeEdges);
    EXPECT_TRUE(merged.valid);
    EXPECT_LT(merged.faces, plain.faces);
    EXPECT_GE(merged.mergedFaces, n);  // at least a rectangle per sector
    GProp_GProps a, b;
    BRepGProp::SurfaceProperties(plain.shape, a);
    BRepGProp::SurfaceProperties(merged.shape, b);
    EXPECT_NEAR(a.Mass(), b.Mass(), 1e-7 * a.Mass());  // OCCT's area integration differs by 2e-8 between the face splits
    // The same surface: points of every original patch lie on the merged shell.
    double worst = 0;
    for (const auto& p : r.patches)
      for (double u : {0.3, 0.8}) {
        const Eigen::Vector3d q = p.surface.point(u, 1 - u);
        BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(gp_Pnt(q.x(), q.y(), q.z())).Vertex(), merged.shape);
        worst = std::max(worst, d.Value());
      }
    EXPECT_LT(worst, 1e-9);
    // Inside a regular rectangle the B-spline is C²: every interior knot is simple.
    int interior = 0;
    for (TopExp_Explorer ex(merged.shape, TopAbs_FACE); ex.More(); ex.Next()) {
      const auto s = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(ex.Current())));
      ASSERT_FALSE(s.IsNull());
      for (int i = 2; i < s->NbUKnots(); ++i, ++interior) EXPECT_EQ(s->UMultiplicity(i), 1);
      for (int i = 2; i < s->NbVKnots(); ++i, ++interior) EXPECT_EQ(s->VMultiplicity(i), 1);
    }
    EXPECT_GT(interior, 0);
    EXPECT_NE(merged.sidecarJson.find("\"control_faces\":["), std::string::npos);
  }
}
