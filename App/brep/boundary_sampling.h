// Boundary constraints of a hole: adaptive samples along its loop carrying
// the position, the support face's unit normal (oriented out of the material
// as the face is used in the model), the direction across the boundary into the
// hole, and the support's normal curvature in that direction; the data the
// variational fill's G0/G1/G2 energies and the continuity report are built on.
//
// Sampling is curvature dependent: an edge gets max(minSamplesPerEdge,
// turning angle / angularStep) samples, uniform in arc length, capped at
// maxSamplesPerEdge; both end points of every edge are sampled, so a corner
// appears once per adjacent edge with that edge's support normal.
#pragma once

#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <Eigen/Dense>
#include <vector>

#include "brep/hole_detection.h"
#include "geometry/differential_geometry.h"

namespace holefill {

struct BoundarySample {
  Eigen::Vector3d point;            // on the edge's 3D curve
  Eigen::Vector3d tangent;          // unit tangent along the loop's traversal
  Eigen::Vector3d normal;           // unit support normal (zero where the support is singular)
  Eigen::Vector3d across;           // unit, in the support tangent plane, perpendicular to tangent, into the hole
  double curvature = 0.0;           // support normal curvature along `across`, signed w.r.t. normal
  double weight = 0.0;              // arc length this sample stands for (model units)
  double t = 0.0;                   // parameter on the edge's curve
  int edge = 0;                     // index into Hole::edges
  bool normalValid = false;
};

struct BoundarySamplingOptions {
  int minSamplesPerEdge = 50;    // DESIGN.md: at least 50 samples per edge
  int maxSamplesPerEdge = 400;   // cap for long, wiggly edges
  double angularStep = 0.02;     // radians of tangent turning per sample
  bool operator==(const BoundarySamplingOptions& o) const {  // every field
    return minSamplesPerEdge == o.minSamplesPerEdge && maxSamplesPerEdge == o.maxSamplesPerEdge && angularStep == o.angularStep;
  }
};

std::vector<BoundarySample> sampleBoundary(const Hole& hole, const BoundarySamplingOptions& options = {});

// The support face as seen from one of its edges: the edge's pcurve and the face's surface,
// built once (OCCT adaptors are costly to construct) and evaluated at many edge parameters.
struct SupportView {
  SupportView(const TopoDS_Edge& edge, const TopoDS_Face& face);
  // Jet and oriented unit normal at edge parameter t; at singular points (a collapsed blend
  // corner, a pole) the limit along the edge: the nearest regular point within 1e-3 of the range.
  bool regularJet(double t, SurfaceJet& jet, Eigen::Vector3d& n) const;
  BRepAdaptor_Curve2d pcurve;
  BRepAdaptor_Surface surface;
  bool reversed;
};

// Oriented unit normal of the support face at edge parameter t (limit at singular points, as
// SupportView::regularJet); false when there is none. For a few queries; loops use SupportView.
bool supportNormal(const TopoDS_Edge& edge, const TopoDS_Face& face, double t, Eigen::Vector3d& n);

}  // namespace holefill
