// Continuity report of a filling face against the hole it fills, exactly as
// DESIGN.md defines the metrics: along the face's boundary (>= 50 samples per
// edge, 200 by default, taken on the face's own trimming curves S_F(pcurve(t))), each sample is
// matched to the nearest point B(t) of the hole's boundary edges and its support face:
//   G0 = max |F - B| (and / scale),  G1 = max angle(n_F, ±n_B),
//   G0 to the faces = max |F - S_B(pcurve_B(t))|: the same sample against the support surface
//   through the neighbour's own pcurve. In an imported model an edge lies on its face only to
//   within the edge's tolerance, so the two differ by up to that tolerance; both are reported
//   (DESIGN's tiers judge the first), with the neighbours' largest edge tolerance beside them,
//   G2 = max |κ_F - κ_B| / max(|κ_B|, 1/scale), κ along the direction across the boundary;
// scale = bounding-box diagonal of the hole boundary. The same function measures our
// fills and a peer's (FreeCAD Surface Filling), so benchmarks compare like with like.
#pragma once

#include <Eigen/Dense>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <limits>
#include <string>
#include <vector>

#include "brep/hole_detection.h"

namespace holefill {

struct EdgeContinuity {
  int edgeIndex = 0;  // hole edge (FreeCAD Edge<k> of the model)
  double g0 = 0, g1 = 0, g2 = 0;
  double g0Face = 0;     // against the neighbour face through its pcurve
  double tolerance = 0;  // the edge's own BRep tolerance now (how far it may lie off its neighbour)
  double toleranceBefore = 0;  // ... as it was when the hole was found (HoleEdge::tolerance)
  // The model's own accuracy at this edge: the largest angle between the edge's 3D curve and the
  // neighbour's tangent plane, and at its corners between the neighbour's normal and the plane of
  // the two edges meeting there (edge_continuity.h cornerMismatch). A surface through the curves
  // cannot meet the neighbour's normal closer than this (0 on an exact model; an imported model's
  // inexact edges reach 1e-3 rad).
  double g1Floor = 0;
};

// One boundary sample with its deviations, for drawing the boundary coloured by continuity, and
// the two normal curvatures across the boundary that G2 compares, for drawing them as curvature
// combs (CurvesWB's inspection: the two combs coincide where the fill is G2).
struct ContinuitySample {
  Eigen::Vector3d point;
  int edgeIndex = 0;
  double g0 = 0, g1 = 0, g2 = 0;
  // The face's unit normal, turned to agree with the support's, and the normal curvatures across
  // the boundary of the face and of the support, signed against that normal (positive: bending
  // towards it). NaN where a normal is singular.
  Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  double curvatureFace = std::numeric_limits<double>::quiet_NaN();
  double curvatureSupport = std::numeric_limits<double>::quiet_NaN();
};

struct ContinuityReport {
  int samples = 0;
  std::vector<ContinuitySample> along;  // every sample, in boundary order (not written to JSON)
  double scale = 0;
  double g0 = 0, g0Relative = 0, g1 = 0, g2 = 0;
  double g0Face = 0, g0FaceRelative = 0;  // G0 against the neighbour faces (see above)
  double edgeTolerance = 0;               // the largest BRep tolerance of the hole's edges
  bool g0Strict = false, g0Loose = false, g1Strict = false, g1Loose = false, g2Ok = false;  // STR tiers
  std::vector<EdgeContinuity> edges;
  // Highest level k with G0 <= g0Tolerance and (k>=1: G1 <= g1Tolerance) and (k>=2: G2 <= g2Tolerance); "none" if G0 fails.
  std::string achieved(double g0Tolerance, double g1Tolerance, double g2Tolerance) const;
};

struct ContinuityOptions {
  // Per edge of the filling face, uniform in its parameter. Four times the fill's minimum of 50
  // boundary constraints per edge: on lines and arcs those constraints are uniform in the same
  // parameter, and a check at the same 51 points would only see where the fill was pinned, never
  // the gaps between (measured: a 76 mm fillet edge 1.8e-6 at its samples, 0.011 between them).
  int samplesPerEdge = 200;
  bool sharedEdgesOnly = false;  // sample only the face's edges that are edges of the hole
};

class JsonWriter;
// Writes the report's fields (scale, samples, g0, g0_relative, g0_face, g0_face_relative, edge_tolerance,
// g1, g2, str, per_edge) into an open object.
void writeJsonFields(JsonWriter& j, const ContinuityReport& r);

// `hole` is a hole of `model` (by detectHoles); `face` may or may not share its edges.
ContinuityReport continuityReport(const TopoDS_Face& face, const Hole& hole, const ContinuityOptions& options = {});

// Continuity across the edges two faces of `model` share (1-based FreeCAD Face<k> indices): face
// `b` measured against face `a` along the shared edges only, scale = their bounding-box diagonal.
// Throws when an index is out of range or the faces share no edge.
ContinuityReport faceContinuity(const TopoDS_Shape& model, int a, int b, const ContinuityOptions& options = {});

}  // namespace holefill
