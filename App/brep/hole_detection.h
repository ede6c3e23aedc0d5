// Hole detection in B-rep models: the free-boundary loops of a shell, an open
// solid, a compound of faces or a whole model, each ordered and oriented the
// way the filling face will use it, with the adjacent support face of every
// edge and N = the number of corners (tangent breaks above cornerAngleDeg).
//
// Orientation: a free edge E used by support face F with orientation o enters
// the hole loop as E with orientation reverse(o), so the filling face and F use
// E oppositely, as a consistently oriented shell needs. With the support
// normals n, the hole's interior then lies to the left of the loop about n.
//
// Limits and fallbacks: seam edges (used twice by one face) and degenerated
// edges are never free; edges used by more than two faces are non-manifold and
// are reported in nonManifoldEdges, never guessed into a loop. Where several
// free edges leave one vertex (loops touching at a vertex) the loop takes the
// leftmost turn about the support normal, which keeps each hole's interior on
// its own side. A loop is classified as the outer boundary of an open sheet
// when the material of its support faces lies on the side of the loop's
// centroid (score > outerScoreThreshold); such loops are returned only when
// includeOuterBoundary is set. Free chains that do not close are reported as warnings.
#pragma once

#include <Eigen/Dense>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

namespace holefill {

struct HoleEdge {
  TopoDS_Edge edge;       // oriented as the filling face's wire uses it
  int edgeIndex = 0;      // 1-based TopExp::MapShapes(model, EDGE) index: FreeCAD's "Edge<k>"
  TopoDS_Face support;    // adjacent face, oriented as in the model
  int supportIndex = 0;   // 1-based TopExp::MapShapes(model, FACE) index: FreeCAD's "Face<k>"
  bool cornerAtStart = false;  // tangent break with the previous edge of the loop at this edge's start
  double turnAtStart = 0.0;    // angle between incoming and outgoing tangents there (radians)
  double length = 0.0;
  double tolerance = 0.0;      // the edge's BRep tolerance when the hole was found: how closely the model
                               // itself places it (an imported model's edges may lie that far off their faces)
};

struct Hole {
  std::vector<HoleEdge> edges;  // in loop order
  int corners = 0;              // N
  double length = 0.0;          // total boundary length (model units)
  double scale = 0.0;           // bounding-box diagonal of the boundary (model units)
  double outerScore = 0.0;      // > 0: support material lies towards the loop's centroid
  bool outerBoundary = false;   // classified as the outer boundary of an open sheet
  std::vector<int> edgeIndices() const;
};

struct HoleDetectionOptions {
  double cornerAngleDeg = 5.0;       // tangent break that makes a corner (degrees)
  bool includeOuterBoundary = false; // also return loops classified as outer sheet boundaries
  double outerScoreThreshold = 0.3;  // classification threshold of Hole::outerScore
};

struct HoleDetectionResult {
  std::vector<Hole> holes;
  std::vector<Hole> outerBoundaries;  // loops classified as outer boundaries (always listed here)
  std::vector<int> nonManifoldEdges;  // 1-based edge indices used by more than two faces
  std::vector<std::string> warnings;
};

HoleDetectionResult detectHoles(const TopoDS_Shape& model, const HoleDetectionOptions& options = {});

// Completes a hole whose edges (ordered, oriented, with supports) are set: corners and turns,
// lengths, scale and the outer-boundary score, as detectHoles does for the loops it finds.
void finishHole(Hole& hole, const HoleDetectionOptions& options = {});

// The hole of `detection` whose loop contains all the given 1-based edge indices; throws if none does.
const Hole& holeContainingEdges(const HoleDetectionResult& detection, const std::vector<int>& edgeIndices);

// Unit tangent of an oriented edge at its start (atEnd = false) or end, along the edge's orientation.
Eigen::Vector3d edgeTangent(const TopoDS_Edge& edge, bool atEnd);

}  // namespace holefill
