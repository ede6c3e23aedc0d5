// The last step of labeled fitting (mesh-extension.md sec. 3): a cubic tensor-product B-spline
// with a chosen number of control points fitted by least squares to parameterized points (the
// extended four-sided mesh, or the bare region for comparison) with a small thin-plate term,
// then trimmed by the region's boundary loops, whose parameters become the face's pcurves. The
// result carries the diagnostics the benchmark compares: the region's data error, the control
// points whose support holds fewer than three points ("weak"), and the normal matrix's condition.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <TopoDS_Face.hxx>
#include <vector>

#include "geometry/bspline_surface.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

struct TensorFitOptions {
  int controlU = 12, controlV = 12;  // control points per direction (cubic: at least 4)
  double smoothing = 1e-6;           // thin-plate weight relative to the data term's scale
  // Rounds of parameter correction (Hoschek's intrinsic parameterization; the footpoint by The
  // NURBS Book's point inversion): after a fit, each region vertex takes the parameters of its
  // closest point on the surface and the fit is solved again. A map distorted where the region
  // turns (a reflex corner) otherwise pins points to parameters the surface can only honour by
  // stretching along itself, which with few control points also bends it off the data. Needs the
  // region's vertices as the first rows of `points` (an extension keeps them there); the rest of
  // the points keep their parameters. A vertex whose footpoint would turn a region triangle over
  // in the parameters keeps its last ones; a round that does not lower the data RMS is not taken
  // and ends the correction. 0: as given.
  int parameterCorrections = 0;
  // The knots' rectangle [u0, u1] × [v0, v1]; empty (u1 <= u0): the points' parameter bounds.
  // A fit of the region alone over its whole domain rectangle (the thin plate carries it past
  // the data) needs it.
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  // Weight of each point past the region's own (rows of `points` after the first
  // region.vertices.rows(), e.g. an extension's samples) in the data term, against 1 for the
  // region's. Samples on a grid finer than the region's edges weigh less, so that the extension
  // pulls per unit of area as the region does (labeled_fit.h).
  double extraWeight = 1;
  // Interior knots as fractions of the domain, ascending and strictly inside (0, 1), where the
  // knots are not uniform (labeled fitting inserts them where its fit misses, labeled_fit.h).
  // Empty: the uniform knots of controlU (controlV); given, they decide that direction's count.
  std::vector<double> knotsU, knotsV;
  // Cells refined locally, as truncated hierarchical B-splines (fitting/thb_spline.h): the uniform
  // knots of controlU × controlV make level 0 (controlU − 3 × controlV − 3 cells), and each entry
  // (level, i, j) refines cell (i, j) of that level, which must lie in the level's domain when its
  // turn comes (entries are applied level by level, in order). The unknowns are then the active THB
  // functions, each a sum of finest-level B-splines, so that a few cells gain control where the fit
  // misses without a knot line across the whole domain (which under scan noise lets every span
  // it crosses follow the noise); the surface is the same spline written at the finest level.
  // Weak control points and the condition are the THB functions'. Needs uniform knots (knotsU
  // and knotsV empty).
  std::vector<std::array<int, 3>> refinedCells;
};

struct TensorFitResult {
  BSplineSurface surface;             // untrimmed, over the points' domain
  TopoDS_Face face;                   // trimmed by the region's boundary loops
  bool valid = false;                 // BRepCheck_Analyzer on the face
  Eigen::MatrixX2d regionUV;          // the region vertices' parameters the face is trimmed at (corrected)
  int correctionRounds = 0;           // parameter corrections taken
  double dataMax = 0, dataRms = 0;    // region vertices to the surface / region diagonal: the boundary's at their parameters, inner ones at their closest points
  Eigen::Index dataMaxAt = 0;         // the region vertex that is dataMax off
  int unknowns = 0;                   // the control points solved for (the THB functions where refinedCells are given)
  int weakControlPoints = 0;          // unknowns whose support holds fewer than three fitted points
  double log10Condition = 0;          // of the points' own normal matrix BᵀB, unweighted and without the thin plate (infinite when singular)
};

// `points`/`pointsUV`: what is fitted (rows alike); `region`/`regionUV`: the trimmed region whose
// vertices measure the data error and whose boundary loops trim the face. Throws Error for sizes
// that disagree, fewer than 4 control points a direction, or non-finite input.
TensorFitResult fitTensorProduct(const Eigen::MatrixX3d& points, const Eigen::MatrixX2d& pointsUV, const TriangleMesh& region,
                                 const Eigen::MatrixX2d& regionUV, const TensorFitOptions& options = {});

}  // namespace holefill
