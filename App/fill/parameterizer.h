// Parameterizers give every boundary sample of a hole a (u, v) on the filling
// surface's domain: the samples of the trimming pcurve (uvtran.md Sec. 2-3).
// All sit behind parameterize().
//  - NearestPlane (NP, Liu 2012): least-squares plane of the loop, orthogonal projection.
//  - MeanValue (MVC, Floater 2003): the N corners go to a regular N-gon whose first side lies
//    along u (a 4-sided loop fills the axis-aligned square), samples along each side by chord
//    length; mean value coordinates of interior points of the N-gon interpolate the boundary
//    and give interior reference points (uv, xyz).
//  - Auto: NP when every support normal is within acos(autoPlaneCos) of the least-squares
//    plane's normal (the fill is a height field over the plane) and the projection does not
//    fold, else MVC; a planar loop that folds is self-intersecting and stays an error.
//  - UVTran (uvtran.md): a learned projection surface predicted from the boundary; the
//    boundary's projection onto it is the pcurve, and the surface inside it gives interior
//    reference points. Any failure (no weights, a fold, a surface far from the boundary) falls
//    back to MVC with a warning that says why.
//  - Support: the hole's own pcurves on its single support face (a hole cut out of one
//    face); reproduces that face's surface when it is a B-spline, and is the reference for tests.
// Every result is oriented counter-clockwise (u is mirrored when needed) so the filling
// face is FORWARD with the loop as its outer wire; a folded (self-intersecting) pcurve throws.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "brep/boundary_sampling.h"
#include "brep/hole_detection.h"
#include "geometry/bspline_surface.h"

namespace holefill {

enum class ParamMethod { NearestPlane, MeanValue, Auto, Support, Uvtran };

ParamMethod paramMethodFromString(const std::string& name);  // "np" | "mvc" | "auto" | "uvtran" | "support"
std::string toString(ParamMethod m);

struct ParameterizationOptions {
  double margin = 0.03;           // domain = pcurve bounding box grown by this fraction of its size per side
  int minCorners = 3;            // MVC maps loops with fewer corners onto a circle by arc length
  int interiorReferenceGrid = 12; // MVC interior reference points on a grid of this many cells per side
  double autoPlaneCos = 0.8;      // Auto takes NP while all |n . plane normal| >= this (36.9 deg: NP compresses <= 20%)
  std::string uvtranWeights;      // empty: the shipped Resources/models/uvtran.pt
  double uvtranMaxDistance = 0.2; // UVTran surface farther than this from the boundary (fraction of the
                                  // boundary's box diagonal) is rejected as a wrong prediction
  bool operator==(const ParameterizationOptions& o) const {  // every field
    return margin == o.margin && minCorners == o.minCorners && interiorReferenceGrid == o.interiorReferenceGrid &&
           autoPlaneCos == o.autoPlaneCos && uvtranWeights == o.uvtranWeights && uvtranMaxDistance == o.uvtranMaxDistance;
  }
};

struct Parameterization {
  std::vector<Eigen::Vector2d> uv;           // one per boundary sample
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;     // domain of the filling surface
  std::vector<double> knotsU, knotsV;        // initial knots when the method implies them (Support), else empty
  std::vector<Eigen::Vector2d> interiorUV;   // interior reference points (MVC)
  std::vector<Eigen::Vector3d> interiorXYZ;
  std::vector<int> cornerSamples;            // sample indices of the corners used
  bool mirroredU = false;
  ParamMethod chosen = ParamMethod::NearestPlane;  // the method used (differs from the request for Auto)
  std::vector<std::string> warnings;
  BSplineSurface projectionSurface;          // UVTran's predicted surface (same coordinates as the samples)
};

// `samples` must be in the coordinates the fill is solved in (normalized); `hole` gives corners and supports.
Parameterization parameterize(const Hole& hole, const std::vector<BoundarySample>& samples, ParamMethod method,
                              const ParameterizationOptions& options = {});

}  // namespace holefill
