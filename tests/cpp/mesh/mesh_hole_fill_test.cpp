#include "mesh/mesh_hole_fill.h"
#include "mesh/self_intersection.h"

#include <gtest/gtest.h>

#include "geometry/outcome.h"

#include <cmath>
#include <map>

#include "geometry/error.h"
#include "mesh/sample_meshes.h"

using namespace holefill;

namespace {

// The new part of a fill: vertices after the input's, triangles after the input's.
double meanNewQuality(const MeshFillResult& r, const TriangleMesh& input, double* minQ = nullptr) {
  double sum = 0, lo = 1;
  const Eigen::Index n = r.mesh.triangles.rows() - input.triangles.rows();
  for (Eigen::Index t = input.triangles.rows(); t < r.mesh.triangles.rows(); ++t) {
    const Eigen::Vector3i f = r.mesh.triangles.row(t).transpose();
    const double q = triangleQuality(r.mesh.vertices.row(f[0]).transpose(), r.mesh.vertices.row(f[1]).transpose(),
                                     r.mesh.vertices.row(f[2]).transpose());
    sum += q;
    lo = std::min(lo, q);
  }
  if (minQ) *minQ = lo;
  return n ? sum / n : 0;
}

void expectInputKept(const MeshFillResult& r, const TriangleMesh& input) {
  ASSERT_GE(r.mesh.vertices.rows(), input.vertices.rows());
  ASSERT_GE(r.mesh.triangles.rows(), input.triangles.rows());
  // Bit for bit: exact equality, not a tolerance.
  EXPECT_TRUE((r.mesh.vertices.topRows(input.vertices.rows()).array() == input.vertices.array()).all());
  EXPECT_TRUE((r.mesh.triangles.topRows(input.triangles.rows()).array() == input.triangles.array()).all());
}

// Every edge of the result has two triangles running it in opposite directions.
void expectClosedAndOriented(const TriangleMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) ++directed[{m.triangles(t, k), m.triangles(t, (k + 1) % 3)}];
  for (const auto& [e, c] : directed) {
    EXPECT_EQ(c, 1) << "edge " << e.first << "-" << e.second << " is used twice in one direction";
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << "edge " << e.first << "-" << e.second << " is a boundary";
  }
}

samples::CutResult planeWithPolygonHole(const std::vector<Eigen::Vector2d>& polygon, int n = 40) {
  const TriangleMesh plane = samples::gridPlane(n, n, 1.0 / n);
  return samples::cutHole(plane, [&](const Eigen::Vector3d& c) {
    bool in = false;  // even-odd rule
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
      if ((polygon[i].y() > c.y()) != (polygon[j].y() > c.y()) &&
          c.x() < (polygon[j].x() - polygon[i].x()) * (c.y() - polygon[i].y()) / (polygon[j].y() - polygon[i].y()) + polygon[i].x())
        in = !in;
    return in;
  });
}

// A 6×6 grid with squares (2,2) and (3,3) removed: two holes meeting only at the vertex (3,3).
std::vector<Eigen::Vector3i> gridWithoutTwoDiagonalSquares(const TriangleMesh& plane) {
  std::vector<Eigen::Vector3i> kept;
  for (Eigen::Index t = 0; t < plane.triangles.rows(); ++t) {
    const Eigen::Vector3i f = plane.triangles.row(t).transpose();
    const Eigen::Vector3d c = (plane.vertices.row(f[0]) + plane.vertices.row(f[1]) + plane.vertices.row(f[2])).transpose() / 3;
    const bool a = c.x() > 2 && c.x() < 3 && c.y() > 2 && c.y() < 3, b = c.x() > 3 && c.x() < 4 && c.y() > 3 && c.y() < 4;
    if (!a && !b) kept.push_back(f);
  }
  return kept;
}

// The 6 x 6 grid plane with those two squares cut: two holes meeting at a singular vertex.
TriangleMesh planeWithTwoDiagonalHoles() {
  TriangleMesh m = samples::gridPlane(6, 6, 1.0);
  const std::vector<Eigen::Vector3i> kept = gridWithoutTwoDiagonalSquares(m);
  m.triangles.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t i = 0; i < kept.size(); ++i) m.triangles.row(i) = kept[i].transpose();
  return m;
}

}  // namespace

TEST(MeshHoleFill, PlanarHoleStaysInItsPlane) {
  const auto cut = planeWithPolygonHole({{0.2, 0.25}, {0.8, 0.2}, {0.75, 0.7}, {0.5, 0.85}, {0.25, 0.7}});
  const MeshFillResult r = fillMeshHoles(cut.mesh);
  // The plane's outer border is a loop too: the largest, and filled like any other.
  ASSERT_EQ(r.fills.size(), 2u);
  EXPECT_EQ(r.filledHoles, 2);
  expectInputKept(r, cut.mesh);
  for (Eigen::Index v = cut.mesh.vertices.rows(); v < r.mesh.vertices.rows(); ++v) EXPECT_EQ(r.mesh.vertices(v, 2), 0.0);
  const MeshHoleFill& inner = r.fills[1];
  EXPECT_GT(inner.newVertices, 10);
  EXPECT_GT(inner.meanQuality, 0.9);
  EXPECT_GT(inner.minQuality, 0.45);
  EXPECT_TRUE(r.closed);
  expectClosedAndOriented(r.mesh);
}

TEST(MeshHoleFill, ConcaveHole) {
  // A C shape: its opening is concave against the ears on the other side.
  const auto cut = planeWithPolygonHole({{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.4}, {0.4, 0.4}, {0.4, 0.6}, {0.8, 0.6}, {0.8, 0.8}, {0.2, 0.8}});
  MeshFillOptions o;
  ASSERT_NEAR(findMeshHoles(cut.mesh).holes[0].length, 4.0, 1e-12);  // the outer border: leave it open
  o.holes = {1};
  const MeshFillResult r = fillMeshHoles(cut.mesh, o);
  ASSERT_EQ(r.filledHoles, 1);
  expectInputKept(r, cut.mesh);
  double minQ;
  EXPECT_GT(meanNewQuality(r, cut.mesh, &minQ), 0.9);
  EXPECT_GT(minQ, 0.45);
  // No new triangle crosses another or the plane around (the signed area below cannot tell: a
  // fold cancels). The minimum-angle ear cutting overlaps its ears in this C (it never tests them
  // in a plane): the crossing check falls back to the other initial triangulation, and says so.
  std::vector<bool> added(r.mesh.triangles.rows(), false);
  for (Eigen::Index t = cut.mesh.triangles.rows(); t < r.mesh.triangles.rows(); ++t) added[t] = true;
  EXPECT_TRUE(selfIntersections(r.mesh, added).pairs.empty());
  EXPECT_EQ(r.fills[1].crossings, 0);
  EXPECT_NE(r.fills[1].fallback.find("minimum-dihedral"), std::string::npos) << r.fills[1].fallback;
  MeshFillOptions unchecked = o;
  unchecked.checkCrossings = false;
  const MeshFillResult paper = fillMeshHoles(cut.mesh, unchecked);
  std::vector<bool> addedPaper(paper.mesh.triangles.rows(), false);
  for (Eigen::Index t = cut.mesh.triangles.rows(); t < paper.mesh.triangles.rows(); ++t) addedPaper[t] = true;
  EXPECT_FALSE(selfIntersections(paper.mesh, addedPaper).pairs.empty());
  EXPECT_TRUE(paper.fills[1].fallback.empty());
  // The fill covers exactly the cut area: no triangle leaves the C.
  double area = 0;
  for (Eigen::Index t = cut.mesh.triangles.rows(); t < r.mesh.triangles.rows(); ++t) {
    const Eigen::Vector3i f = r.mesh.triangles.row(t).transpose();
    const Eigen::Vector3d a = r.mesh.vertices.row(f[0]), b = r.mesh.vertices.row(f[1]), c = r.mesh.vertices.row(f[2]);
    area += 0.5 * (b - a).cross(c - a).z();  // signed: a fold would subtract
  }
  double removed = 0;
  for (Eigen::Index t = 0; t < cut.removed.triangles.rows(); ++t) {
    const Eigen::Vector3i f = cut.removed.triangles.row(t).transpose();
    const Eigen::Vector3d a = cut.removed.vertices.row(f[0]), b = cut.removed.vertices.row(f[1]), c = cut.removed.vertices.row(f[2]);
    removed += 0.5 * (b - a).cross(c - a).z();
  }
  EXPECT_NEAR(area, removed, 1e-12);
  EXPECT_EQ(r.openHoles, 1);  // the outer border
}

TEST(MeshHoleFill, ElongatedHole) {
  const auto cut = planeWithPolygonHole({{0.1, 0.48}, {0.9, 0.48}, {0.9, 0.53}, {0.1, 0.53}}, 80);
  MeshFillOptions o;
  o.maxBoundary = 300;
  const MeshFillResult r = fillMeshHoles(cut.mesh, o);
  ASSERT_EQ(r.filledHoles, 1);
  double minQ;
  EXPECT_GT(meanNewQuality(r, cut.mesh, &minQ), 0.85);
  EXPECT_GT(minQ, 0.4);
  for (Eigen::Index v = cut.mesh.vertices.rows(); v < r.mesh.vertices.rows(); ++v) EXPECT_EQ(r.mesh.vertices(v, 2), 0.0);
}

TEST(MeshHoleFill, HoleInASphereFollowsTheSphere) {
  const TriangleMesh sphere = samples::icosphere(4, 1.0);
  const auto cut = samples::cutHole(sphere, [](const Eigen::Vector3d& c) { return c.normalized().z() > std::cos(0.5); });
  const MeshFillResult r = fillMeshHoles(cut.mesh);
  ASSERT_EQ(r.filledHoles, 1);
  expectInputKept(r, cut.mesh);
  EXPECT_TRUE(r.closed);
  expectClosedAndOriented(r.mesh);
  double worst = 0;
  for (Eigen::Index v = cut.mesh.vertices.rows(); v < r.mesh.vertices.rows(); ++v)
    worst = std::max(worst, std::abs(r.mesh.vertices.row(v).norm() - 1.0));
  // A cap of half-angle 0.5 rises 1 − cos 0.5 = 0.122 above its boundary's plane.
  EXPECT_LT(worst, 0.122);
  double minQ;
  EXPECT_GT(meanNewQuality(r, cut.mesh, &minQ), 0.7);
}

TEST(MeshHoleFill, ThreeVertexHole) {
  TriangleMesh sphere = samples::icosphere(2);
  TriangleMesh open = sphere;
  open.triangles = sphere.triangles.topRows(sphere.triangles.rows() - 1);
  const MeshFillResult r = fillMeshHoles(open);
  ASSERT_EQ(r.filledHoles, 1);
  EXPECT_EQ(r.fills[0].boundaryVertices, 3);
  EXPECT_EQ(r.fills[0].newVertices, 0);
  EXPECT_EQ(r.fills[0].newTriangles, 1);
  EXPECT_TRUE(r.closed);
  // The one new triangle is the removed one, in its orientation (as a cyclic rotation).
  const Eigen::Vector3i removed = sphere.triangles.bottomRows(1).transpose();
  const Eigen::Vector3i added = r.mesh.triangles.bottomRows(1).transpose();
  bool same = false;
  for (int k = 0; k < 3; ++k) same = same || (added[k] == removed[0] && added[(k + 1) % 3] == removed[1] && added[(k + 2) % 3] == removed[2]);
  EXPECT_TRUE(same);
}

TEST(MeshHoleFill, TwoThousandVertexLoopsCapATube) {
  // Elliptic, so the caps need thousands rather than hundreds of thousands of new vertices.
  const TriangleMesh t = samples::tube(2000, 3, 1.0, 0.01, 0.03);
  const MeshFillResult r = fillMeshHoles(t);
  ASSERT_EQ(r.filledHoles, 2);
  EXPECT_EQ(r.fills[0].boundaryVertices, 2000);
  EXPECT_TRUE(r.closed);
  expectClosedAndOriented(r.mesh);
  // The thin-plate fill continues the tube's wall a little past each rim (a shallow dome
  // within the tube's width), never outside the rim's ellipse.
  double lowest = 0, highest = 0.01;
  for (Eigen::Index v = t.vertices.rows(); v < r.mesh.vertices.rows(); ++v) {
    lowest = std::min(lowest, r.mesh.vertices(v, 2));
    highest = std::max(highest, r.mesh.vertices(v, 2));
    EXPECT_LT(std::hypot(r.mesh.vertices(v, 0), r.mesh.vertices(v, 1) / 0.03), 1.0);
  }
  EXPECT_LT(highest - 0.01, 0.03);
  EXPECT_GT(lowest, -0.03);
  double minQ;
  EXPECT_GT(meanNewQuality(r, t, &minQ), 0.85);
}

TEST(MeshHoleFill, TwoHolesSharingAVertexAreFilledSeparately) {
  // Two triangles of a grid removed so that their holes meet only at one vertex.
  const TriangleMesh m = planeWithTwoDiagonalHoles();
  const MeshHoleReport holes = findMeshHoles(m);
  EXPECT_EQ(holes.singularVertices, 1);
  MeshFillOptions o;
  o.maxBoundary = 10;
  const MeshFillResult r = fillMeshHoles(m, o);
  EXPECT_EQ(r.filledHoles, 2);
  for (const auto& f : r.fills)
    if (f.boundaryVertices == 4) EXPECT_NE(f.message.find("singular"), std::string::npos) << f.message;
  EXPECT_EQ(countBoundaryEdges(r.mesh), 24);  // the outer border only
}

// The outcome every door reads (geometry/outcome.h): holes left open warn and name them, none
// filled fails with each hole's reason, all filled is ok.
TEST(MeshHoleFill, OutcomeWarnsOnOpenHolesAndFailsWhenNoneIsFilled) {
  const TriangleMesh m = planeWithTwoDiagonalHoles();
  MeshFillOptions o;
  o.maxBoundary = 10;  // the holes, not the outer border (24 edges)
  const Outcome some = fillMeshHoles(m, o).outcome();
  EXPECT_EQ(some.status, Status::Warned);  // the border stays open
  EXPECT_EQ(some.faulting.size(), 1u);
  EXPECT_EQ(exitCode(some), 3);
  o.maxBoundary = 3;  // nothing fits
  const MeshFillResult none = fillMeshHoles(m, o);
  const Outcome failed = none.outcome();
  EXPECT_EQ(failed.status, Status::Failed);
  EXPECT_EQ(failed.stage, "fill");
  EXPECT_NE(failed.message.find("no hole was filled: "), std::string::npos) << failed.message;
  EXPECT_NE(failed.message.find("max-boundary"), std::string::npos) << failed.message;
  EXPECT_EQ(exitCode(failed), 2);
  EXPECT_NE(none.toJson().find("\"status\":\"failed\""), std::string::npos);
  const Outcome closed = fillMeshHoles(samples::icosphere(1)).outcome();
  EXPECT_EQ(closed.status, Status::Ok);
}

TEST(MeshHoleFill, BadInputsGiveClearErrors) {
  TriangleMesh empty;
  EXPECT_THROW(fillMeshHoles(empty), Error);
  TriangleMesh nan = samples::icosphere(1);
  nan.vertices(3, 1) = std::nan("");
  try {
    fillMeshHoles(nan);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 3"), std::string::npos) << e.what();
  }
  TriangleMesh badIndex = samples::icosphere(1);
  badIndex.triangles(0, 2) = 999;
  EXPECT_THROW(fillMeshHoles(badIndex), Error);
  const TriangleMesh sphere = samples::icosphere(1);
  MeshFillOptions o;
  o.holes = {0};
  EXPECT_THROW(fillMeshHoles(sphere, o), Error);  // a closed mesh has no hole 0
  const MeshFillResult closed = fillMeshHoles(sphere);
  EXPECT_EQ(closed.fills.size(), 0u);
  EXPECT_TRUE(closed.closed);
}

TEST(MeshHoleFill, NonManifoldEdgeLeavesItsHoleOpenAndFillsTheRest) {
  // A plane with a hole, plus a fin: a triangle hanging on an edge of the hole's border.
  const auto cut = planeWithPolygonHole({{0.3, 0.3}, {0.7, 0.3}, {0.7, 0.7}, {0.3, 0.7}}, 10);
  TriangleMesh m = cut.mesh;
  // Pick a border edge of the hole and give it a third triangle via a new vertex above.
  const MeshHoleReport before = findMeshHoles(m);
  const MeshHole& inner = before.holes[1];
  const int a = inner.loop[0], b = inner.loop[1];
  TriangleMesh fin = m;
  fin.vertices.conservativeResize(m.vertices.rows() + 2, 3);
  fin.vertices.row(m.vertices.rows()) = Eigen::RowVector3d(0.5, 0.5, 1);
  fin.vertices.row(m.vertices.rows() + 1) = Eigen::RowVector3d(0.5, 0.5, -1);
  fin.triangles.conservativeResize(m.triangles.rows() + 2, 3);
  fin.triangles.row(m.triangles.rows()) = Eigen::RowVector3i(a, b, int(m.vertices.rows()));
  fin.triangles.row(m.triangles.rows() + 1) = Eigen::RowVector3i(b, a, int(m.vertices.rows() + 1));
  MeshFillResult r;
  ASSERT_NO_THROW(r = fillMeshHoles(fin));
  EXPECT_GT(r.detection.nonManifoldEdges, 0);
  expectInputKept(r, fin);
  bool reported = false;
  for (const auto& f : r.fills) reported = reported || f.message.find("non-manifold") != std::string::npos;
  EXPECT_TRUE(reported);
}

TEST(MeshHoleFill, InconsistentOrientationIsReadThroughTheMajority) {
  const TriangleMesh sphere = samples::icosphere(3);
  auto cut = samples::cutHole(sphere, [](const Eigen::Vector3d& c) { return c.normalized().z() > 0.9; });
  TriangleMesh m = cut.mesh;
  // Flip a few triangles far from the hole.
  int flipped = 0;
  for (Eigen::Index t = 0; t < m.triangles.rows() && flipped < 5; ++t) {
    const Eigen::Vector3i f = m.triangles.row(t).transpose();
    if (m.vertices(f[0], 2) < -0.5) { m.triangles.row(t) = Eigen::RowVector3i(f[0], f[2], f[1]); ++flipped; t += 40; }
  }
  const MeshFillResult r = fillMeshHoles(m);
  EXPECT_GT(r.detection.inconsistentEdges, 0);
  ASSERT_EQ(r.filledHoles, 1);
  // The patch faces outward like the majority.
  for (Eigen::Index t = m.triangles.rows(); t < r.mesh.triangles.rows(); ++t) {
    const Eigen::Vector3i f = r.mesh.triangles.row(t).transpose();
    const Eigen::Vector3d a = r.mesh.vertices.row(f[0]), b = r.mesh.vertices.row(f[1]), c = r.mesh.vertices.row(f[2]);
    EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0);
  }
}

TEST(MeshHoleFill, DuplicatedSeamVerticesSplitTheLoop) {
  // A plane with a hole whose border passes a vertex twice through two coincident copies:
  // the triangles on one side of the pinch use a copy of the vertex.
  TriangleMesh plane = samples::gridPlane(6, 6, 1.0);
  const std::vector<Eigen::Vector3i> kept = gridWithoutTwoDiagonalSquares(plane);
  TriangleMesh m = plane;
  m.vertices.conservativeResize(plane.vertices.rows() + 1, 3);
  const int pinch = 3 * 7 + 3, copy = static_cast<int>(plane.vertices.rows());
  m.vertices.row(copy) = m.vertices.row(pinch);
  m.triangles.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t i = 0; i < kept.size(); ++i) {
    Eigen::Vector3i f = kept[i];
    const Eigen::Vector3d c = (plane.vertices.row(f[0]) + plane.vertices.row(f[1]) + plane.vertices.row(f[2])).transpose() / 3;
    if (c.x() > 3 && c.y() < 3)  // the lower-right quadrant around the pinch uses the copy
      for (int k = 0; k < 3; ++k)
        if (f[k] == pinch) f[k] = copy;
    m.triangles.row(i) = f.transpose();
  }
  MeshFillOptions o;
  o.maxBoundary = 10;
  const MeshFillResult r = fillMeshHoles(m, o);
  EXPECT_GE(r.detection.duplicateSplits, 1);
  EXPECT_EQ(r.filledHoles, 2);
  EXPECT_FALSE(r.closed);
  // Once the copies are welded, only the outer border is open.
  EXPECT_EQ(countBoundaryEdges(r.mesh, weldMap(r.mesh.vertices, 1e-12)), 24);
}

TEST(MeshHoleFill, PlanarSliverHoleGetsBackItsTriangle) {
  // A needle-shaped hole (q = 0.087) in a coarse plane, refined hard (α = 6): the splits cannot
  // improve a planar three-vertex hole, only spoil it (q 0.003 with 74 new vertices when the
  // bare fallback is off), so the fill is the missing triangle itself.
  TriangleMesh m;
  m.vertices.resize(7, 3);
  m.vertices << -2, -2, 0, 8, -2, 0, 8, 12, 0, -2, 12, 0, 0, 0, 0, 0.6, 0, 0, 5, 10, 0;
  m.triangles.resize(7, 3);
  m.triangles << 0, 1, 5, 0, 5, 4, 1, 2, 5, 5, 2, 6, 2, 3, 6, 6, 3, 4, 3, 0, 4;
  const MeshHoleReport holes = findMeshHoles(m);
  int needle = -1;
  for (size_t h = 0; h < holes.holes.size(); ++h)
    if (holes.holes[h].loop.size() == 3) needle = static_cast<int>(h);
  ASSERT_GE(needle, 0);
  MeshFillOptions o;
  o.holes = {needle};
  o.refinement.densityFactor = 6;
  const MeshHoleFill f = fillMeshHoles(m, o).fills[needle];
  ASSERT_TRUE(f.filled) << f.message;
  EXPECT_EQ(f.newVertices, 0);
  EXPECT_EQ(f.newTriangles, 1);
  const double q = triangleQuality(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.6, 0, 0), Eigen::Vector3d(5, 10, 0));
  EXPECT_NEAR(f.minQuality, q, 1e-12);
  o.keepBetterBare = false;
  const MeshHoleFill spoiled = fillMeshHoles(m, o).fills[needle];
  EXPECT_GT(spoiled.newVertices, 0);
  EXPECT_LT(spoiled.minQuality, q);
}

TEST(MeshHoleFill, MinimumDihedralTriangulationCoversThePlanarHole) {
  // Liepa's program on a planar concave loop: n − 2 triangles, all facing one way, covering the
  // cut area exactly (the signed areas add up to the removed area).
  const auto cut = planeWithPolygonHole({{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.4}, {0.4, 0.4}, {0.4, 0.6}, {0.8, 0.6}, {0.8, 0.8}, {0.2, 0.8}});
  const MeshHoleReport holes = findMeshHoles(cut.mesh);
  const MeshHole& hole = holes.holes[1];
  std::vector<Eigen::Vector3d> loop, across;
  for (size_t k = 0; k < hole.loop.size(); ++k) {
    loop.push_back(cut.mesh.vertices.row(hole.loop[k]).transpose());
    across.push_back(Eigen::Vector3d(0, 0, 1));
  }
  const auto tris = triangulateMinDihedral(loop, across, [](int, int) { return false; });
  ASSERT_EQ(tris.size(), loop.size() - 2);
  double area = 0;
  for (const auto& t : tris) {
    const double a = 0.5 * (loop[t[1]] - loop[t[0]]).cross(loop[t[2]] - loop[t[0]]).z();
    EXPECT_GT(a, 0);  // no fold: every triangle faces +z like the plane
    area += a;
  }
  double removed = 0;
  for (Eigen::Index t = 0; t < cut.removed.triangles.rows(); ++t) {
    const Eigen::Vector3i f = cut.removed.triangles.row(t).transpose();
    removed += 0.5 * (cut.removed.vertices.row(f[1]) - cut.removed.vertices.row(f[0]))
                         .cross(cut.removed.vertices.row(f[2]) - cut.removed.vertices.row(f[0])).z();
  }
  EXPECT_NEAR(area, removed, 1e-12);
  // The whole pipeline with it fills validly and closed.
  MeshFillOptions o;
  o.holes = {1};
  o.initial = MeshFillOptions::Triangulation::MinDihedral;
  const MeshFillResult r = fillMeshHoles(cut.mesh, o);
  EXPECT_EQ(r.filledHoles, 1);
  for (Eigen::Index v = cut.mesh.vertices.rows(); v < r.mesh.vertices.rows(); ++v) EXPECT_EQ(r.mesh.vertices(v, 2), 0.0);
}

TEST(MeshHoleFill, AutoTriangulationKeepsMinimumAngleAtCreases) {
  // A plane folded by 90° along y = 0.5, with a hole across the fold: a crease reaches the
  // loop, so auto uses the paper's minimum-angle triangulation; a hole in a sphere has no
  // crease and gets Liepa's minimum-dihedral one.
  TriangleMesh folded = samples::gridPlane(20, 20, 1.0 / 20);
  for (Eigen::Index v = 0; v < folded.vertices.rows(); ++v)
    if (folded.vertices(v, 1) > 0.5) {
      folded.vertices(v, 2) = folded.vertices(v, 1) - 0.5;
      folded.vertices(v, 1) = 0.5;
    }
  const auto crease = samples::cutHole(folded, [](const Eigen::Vector3d& c) { return (c - Eigen::Vector3d(0.5, 0.5, 0)).norm() < 0.2; });
  MeshFillOptions o;
  o.initial = MeshFillOptions::Triangulation::Auto;
  o.maxBoundary = 60;
  const MeshFillResult r = fillMeshHoles(crease.mesh, o);
  ASSERT_EQ(r.filledHoles, 1);
  for (const auto& f : r.fills)
    if (f.filled) EXPECT_EQ(f.triangulation, "angle");
  const auto cap = samples::cutHole(samples::icosphere(4), [](const Eigen::Vector3d& c) { return c.normalized().z() > 0.9; });
  const MeshFillResult s = fillMeshHoles(cap.mesh, o);
  ASSERT_EQ(s.filledHoles, 1);
  EXPECT_EQ(s.fills[0].triangulation, "dihedral");
}

TEST(MeshHoleFill, ALoopWhoseChordsTheMeshHasIsFilledFromAFan) {
  // The open base a b c d of a square pyramid, with both of its diagonals already edges of the
  // mesh (two fins hanging off them): every ear of either triangulation would repeat one. The
  // hole is filled from a fan around a new centre vertex instead, and the report says so.
  TriangleMesh m;
  m.vertices.resize(7, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1, 0.5, 0.5, -3, 0.5, -3, -3;
  m.triangles.resize(6, 3);
  m.triangles << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4,  // the pyramid's sides
      0, 2, 5, 1, 3, 6;                               // the fins on the diagonals
  const MeshHoleReport d = findMeshHoles(m);
  int base = -1;
  for (size_t h = 0; h < d.holes.size(); ++h)
    if (d.holes[h].loop.size() == 4 && std::count(d.holes[h].loop.begin(), d.holes[h].loop.end(), 4) == 0) base = static_cast<int>(h);
  ASSERT_GE(base, 0);
  MeshFillOptions o;
  o.holes = {base};
  const MeshFillResult r = fillMeshHoles(m, o);
  const MeshHoleFill& f = r.fills[base];
  ASSERT_TRUE(f.filled) << f.message;
  EXPECT_EQ(f.triangulation, "fan");
  EXPECT_NE(f.message.find("filled from the fan initial triangulation"), std::string::npos) << f.message;
  EXPECT_GE(f.newVertices, 1);
}

TEST(MeshHoleFill, AHoleAcrossAThinWallStaysOnItsSide) {
  // A thin double wall: an icosphere of radius 1 around one of radius 0.97 (inside out). A cap cut
  // from the outer one, 0.17 deep at its middle, is filled flat by the paper's placement, which
  // pierces the inner wall; ours (thin plate, tested for crossings exactly) stays outside it.
  TriangleMesh outer = samples::icosphere(4, 1.0), inner = samples::icosphere(4, 0.97);
  for (Eigen::Index t = 0; t < inner.triangles.rows(); ++t) std::swap(inner.triangles(t, 1), inner.triangles(t, 2));
  TriangleMesh wall;
  wall.vertices.resize(outer.vertices.rows() + inner.vertices.rows(), 3);
  wall.vertices << outer.vertices, inner.vertices;
  wall.triangles.resize(outer.triangles.rows() + inner.triangles.rows(), 3);
  wall.triangles << outer.triangles, (inner.triangles.array() + static_cast<int>(outer.vertices.rows())).matrix();
  const auto cut = samples::cutHole(wall, [](const Eigen::Vector3d& c) { return c.norm() > 0.985 && c.z() > std::cos(0.6); });
  const auto crossings = [&](const MeshFillResult& r) {
    std::vector<bool> added(r.mesh.triangles.rows(), false);
    for (Eigen::Index t = cut.mesh.triangles.rows(); t < r.mesh.triangles.rows(); ++t) added[t] = true;
    return selfIntersections(r.mesh, added).pairs.size();
  };
  const MeshFillResult paper = fillMeshHoles(cut.mesh, paperPipeline());
  ASSERT_EQ(paper.filledHoles, 1);
  EXPECT_GT(crossings(paper), 0u);
  const MeshFillResult ours = fillMeshHoles(cut.mesh);
  ASSERT_EQ(ours.filledHoles, 1);
  EXPECT_EQ(crossings(ours), 0u);
  EXPECT_EQ(ours.fills[0].crossings, 0);
  EXPECT_TRUE(ours.closed);
}

TEST(MeshHoleFill, AHoleOnASeamIsOneHoleAndTheSeamNone) {
  // A 10 x 10 grid whose right half lies on copies of the seam's vertices, and a hole cut across
  // the seam: one hole (not the two seam sides as well), filled without crossing, closed once the
  // copies are welded.
  TriangleMesh m = samples::gridPlane(10, 10, 0.1);
  std::map<int, int> copyOf;
  const Eigen::Index nv = m.vertices.rows();
  std::vector<Eigen::RowVector3d> extra;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) {
    const Eigen::Vector3d c = (m.vertices.row(m.triangles(t, 0)) + m.vertices.row(m.triangles(t, 1)) + m.vertices.row(m.triangles(t, 2))).transpose() / 3;
    if (c.x() < 0.5) continue;
    for (int k = 0; k < 3; ++k) {
      const int v = m.triangles(t, k);
      if (std::abs(m.vertices(v, 0) - 0.5) > 1e-12) continue;
      if (!copyOf.count(v)) {
        copyOf[v] = static_cast<int>(nv + extra.size());
        extra.push_back(m.vertices.row(v));
      }
      m.triangles(t, k) = copyOf[v];
    }
  }
  m.vertices.conservativeResize(nv + static_cast<Eigen::Index>(extra.size()), 3);
  for (size_t i = 0; i < extra.size(); ++i) m.vertices.row(nv + static_cast<Eigen::Index>(i)) = extra[i];
  const auto cut = samples::cutHole(m, [](const Eigen::Vector3d& c) { return (c - Eigen::Vector3d(0.5, 0.5, 0)).norm() < 0.22; });
  const MeshHoleReport d = findMeshHoles(cut.mesh);
  EXPECT_GT(d.seamEdges, 0);
  int inner = 0;
  for (const MeshHole& h : d.holes) inner += h.length < 3.5 ? 1 : 0;  // not the grid's outer border (4 long)
  EXPECT_EQ(inner, 1);
  MeshFillOptions o;
  for (size_t h = 0; h < d.holes.size(); ++h)
    if (d.holes[h].length < 3.5) o.holes.push_back(static_cast<int>(h));
  const MeshFillResult r = fillMeshHoles(cut.mesh, o);
  EXPECT_EQ(r.filledHoles, 1);
  std::vector<bool> added(r.mesh.triangles.rows(), false);
  for (Eigen::Index t = cut.mesh.triangles.rows(); t < r.mesh.triangles.rows(); ++t) added[t] = true;
  EXPECT_TRUE(selfIntersections(r.mesh, added).pairs.empty());
  // Only the grid's outer border is left, once the seam's copies are welded.
  EXPECT_EQ(countBoundaryEdges(r.mesh, weldMap(r.mesh.vertices, 1e-12)), 40);
}

TEST(MeshHoleFill, ThePapersModeIsItsPipeline) {
  // The paper places new vertices on the flat initial triangulation and only smooths them with
  // its bilateral filter: with the filter off, a tube's planar rim is capped exactly in its plane.
  // Ours continues the wall (thin plate) off that plane. The paper's mode adds nothing of ours:
  // no crossing test, no fallback, the minimum-angle triangulation.
  const TriangleMesh t = samples::tube(60, 6, 1.0, 0.5);
  MeshFillOptions paper = paperPipeline();
  paper.fairing.iterations = 0;
  const MeshFillResult flat = fillMeshHoles(t, paper);
  ASSERT_EQ(flat.filledHoles, 2);
  double offPlane = 0;
  for (Eigen::Index v = t.vertices.rows(); v < flat.mesh.vertices.rows(); ++v)
    offPlane = std::max(offPlane, std::min(std::abs(flat.mesh.vertices(v, 2)), std::abs(flat.mesh.vertices(v, 2) - 0.5)));
  EXPECT_LT(offPlane, 1e-12);
  for (const MeshHoleFill& f : flat.fills) {
    EXPECT_EQ(f.triangulation, "angle");
    EXPECT_TRUE(f.fallback.empty());
  }
  EXPECT_TRUE(isPaperPipeline(paperPipeline()));
  EXPECT_FALSE(isPaperPipeline(MeshFillOptions{}));
  const MeshFillResult ours = fillMeshHoles(t);
  double oursOff = 0;
  for (Eigen::Index v = t.vertices.rows(); v < ours.mesh.vertices.rows(); ++v)
    oursOff = std::max(oursOff, std::min(std::abs(ours.mesh.vertices(v, 2)), std::abs(ours.mesh.vertices(v, 2) - 0.5)));
  EXPECT_GT(oursOff, 1e-3);
}
