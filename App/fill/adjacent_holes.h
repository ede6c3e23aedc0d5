// Adjacent holes (uvtran.md Sec. 5.2, Fig. 8): one free-boundary loop split by a dividing curve
// into two holes that share it, filled as two trimmed B-spline faces sharing that curve as one
// edge, each at the asked continuity towards its neighbours and towards each other.
//
// The two fills cannot be solved independently: across the dividing curve neither side has a
// neighbour to take normals and curvature from. So the first side is filled with the curve asked
// G0 only (its shape there left to fairness; the curve's support is a ruled strip whose normals
// blend the model's at the curve's two ends, no face of the result) and sewn; the second side
// then has the first face as its neighbour across the curve and is filled at the asked
// continuity there as on its other edges, so the two faces meet at the second fill's tolerances.
// `across` measures what the two new faces share. (A provisional one-face fill of the whole loop
// as that neighbour was tried first and dropped: the divider does not lie on it, and its normals
// at the points nearest the divider made the first side fail G1 on the demo's filleted box.)
//
// The dividing curve must run inside the hole from one vertex of the loop to another (within
// 1e-4 of the hole's scale; its ends are moved onto those vertices) and split the loop into two
// chains of at least one edge each. The user's shape is never touched.
#pragma once

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

#include "brep/continuity_report.h"
#include "fill/hole_fill.h"

namespace holefill {

struct AdjacentFillResult {
  FillStatus status = FillStatus::Failed;  // the worse of the two fills'
  std::string message;
  HoleFillResult first, second;  // the two sides; second.shape holds both faces
  TopoDS_Shape shape;            // the model with both faces sewn in (null when a fill failed)
  TopoDS_Edge shared;            // the dividing curve as the edge the two faces share
  int sharedEdgeIndex = 0;       // its 1-based index in `shape` (FreeCAD Edge<k>); the first fill names it Edge0
  ContinuityReport across;       // the second face against the first along the shared edge
  bool shapeValid = false;
};

// `holeEdges` name the loop (1-based edge indices of `model`, any subset); `divider` is an edge
// (any edge whose 3D curve runs across the hole, e.g. from a sketch). Throws holefill::Error when
// the loop cannot be named or the divider does not end at two distinct vertices of it.
AdjacentFillResult fillAdjacentHoles(const TopoDS_Shape& model, const std::vector<int>& holeEdges,
                                     const TopoDS_Edge& divider, const HoleFillOptions& options = {});

// {"status", "message", "shared_edge", "shape_valid", "across": {continuity fields}, "fills": [first, second]}.
std::string toJson(const AdjacentFillResult& r);
Outcome outcome(const AdjacentFillResult& r);  // the worse side's, with its stage

}  // namespace holefill
