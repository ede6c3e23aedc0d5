// The point-cloud pipeline as every door runs it (bidgcn.md secs. 3.2 and 5): a scanned cloud in
// — flagged with its boundary and the boundary's parameters, or bare — its boundary found where
// it is not marked (cloud_boundary.h: the alpha shape), the boundary's parameters by chord length
// between four corners where they are not given, the interior parameterized (meshless weights or
// BIDGCN, cloud_parameterization.h), and an adaptive THB-spline fitted with parameter correction
// (thb_fit.h); out, the fitted surface as B-rep — one face, exact at the finest level, or one face
// per hierarchical cell — with one report. The CLI, the Python module and the FreeCAD object only
// convert arguments and results.
#pragma once

#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

#include "fitting/cloud_parameterization.h"
#include "geometry/outcome.h"
#include "fitting/thb_fit.h"
#include "geometry/flagged_cloud.h"

namespace holefill {

struct PointCloudFitOptions {
  CloudParameterizationOptions parameterization;
  ThbFitOptions fit;
  bool adaptive = true;       // false: one uniform level (fit.maxLevels 1: least squares with parameter correction)
  // The largest point error wanted in the cloud's own units; > 0: used instead of
  // fit.relativeTolerance (of the bounding-box diagonal), 0: that relative tolerance.
  double tolerance = 0;
  std::vector<int> corners;   // boundary points (0-based) put on the unit square's corners where the boundary's
                              // parameters are not given; empty: the boundary's four sharpest turns
  bool cellFaces = false;     // the shape: one face per hierarchical cell, not the finest-level B-spline face
};

// A cloud made ready for parameterizing: its boundary marked and the boundary's parameters set.
struct CloudBoundaryCompletion {
  int found = -1;        // boundary points the alpha shape marked; -1: the cloud came flagged
  double spacing = 0;    // the alpha shape's sampling spacing (model units) where it was found
  bool chord = false;    // the boundary's parameters were computed (chord length between corners)
};

struct PointCloudFitResult {
  FlaggedCloud cloud;                      // as fitted: boundary marked, its parameters set
  CloudBoundaryCompletion completion;
  CloudParameterization parameterization;
  ThbFitResult fit;
  TopoDS_Shape shape;                      // a face, or a compound of cell faces (options.cellFaces)
  std::vector<std::string> warnings() const;  // the parameterization's, and a folding surface
  Outcome outcome() const;                    // Warned where the tolerance is not met
  std::string toJson() const;                 // {"parameterization": …, "boundary_found": n, thb_fit.h's fields, "warnings"}
};

// Marks the boundary of a bare cloud and computes the boundary's parameters where none are given
// (or always, with `rechord`). Throws Error as detectCloudBoundary and boundaryChordParameters do.
CloudBoundaryCompletion completeCloudBoundary(FlaggedCloud& cloud, const std::vector<int>& corners = {}, bool rechord = false);

// Throws Error for options out of range (degree 1 to 7, a positive relative tolerance, a tolerance
// zero or positive, at least one base
// cell and one iteration) and as the stages do (a cloud too small, non-finite, without boundary).
PointCloudFitResult fitPointCloud(const FlaggedCloud& cloud, const PointCloudFitOptions& options = {});

}  // namespace holefill
