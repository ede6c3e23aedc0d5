// Adaptive THB-spline fitting of a parameterized point cloud (bidgcn.md sec. 5): penalized least
// squares (data term plus λ times the thin-plate energy) in a THB space (thb_spline.h); points
// whose error exceeds the tolerance mark the active cell they lie in, which is refined with its
// neighbours; each iteration corrects the parameters once (Newton footpoint projection, a new
// parameter kept only where it brings the point closer); it stops at the tolerance or the
// iteration cap. The result is exactly a B-spline at the finest level. The thin-plate term is
// fairness_energy.h's (the mixed derivative counted twice, where the paper's J counts it once),
// and the correction runs on the fit before the refinement rather than after it.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "fitting/thb_spline.h"
#include "geometry/bspline_surface.h"

namespace holefill {

class JsonWriter;

struct ThbFitOptions {
  int degree = 3;
  int baseCells = 4;              // cells per direction at level 0
  double relativeTolerance = 1e-3;  // max point error, relative to the cloud's bounding-box diagonal
  double smoothing = 1e-4;        // λ, relative to the data term's scale (1e-7 left corner folds in scans; 1e-4 none, same error)
  int maxIterations = 8;
  int maxLevels = 6;              // cells are not refined beyond this many levels
  bool correctParameters = true;
};

struct ThbFitIteration {
  int dof = 0;                    // active THB functions
  double mse = 0, maxError = 0;   // over the points, relative to the diagonal (mse of the relative errors)
  int refinedCells = 0;
  int correctedParameters = 0;
};

struct ThbFitResult {
  ThbSpace space{3, 4, 4};
  Eigen::MatrixX3d coefficients;  // per active function
  BSplineSurface surface;         // the same surface as one B-spline at the finest level
  Eigen::MatrixX2d uv;            // the corrected parameters
  std::vector<ThbFitIteration> history;
  bool metTolerance = false;
  Eigen::VectorXd errors;         // per point, at the corrected parameters, relative to the diagonal
  double diagonal = 0;            // of the cloud's bounding box (model units)
  double relativeTolerance = 0;   // the goal the fit had, of the diagonal
  int folds = 0;                  // of 65 × 65 domain samples, those whose normal opposes the cloud's best-fit
                                  // plane normal (or vanishes): the surface folds there although the points
                                  // may all be within the tolerance (crowded or crossing parameters)
  std::string toJson() const;     // iterations (dof, mse, max error, refined cells, corrected parameters), levels, met_tolerance, folds,
                                  // diagonal, relative_tolerance, tolerance (model units)
  void writeFields(JsonWriter& j) const;  // the same fields into an object the caller has open (a larger report)
};

// `uv` in [0, 1]² per point. Throws Error for fewer points than the base space has functions,
// non-finite input or parameters outside [0, 1]².
ThbFitResult fitThb(const Eigen::MatrixX3d& points, const Eigen::MatrixX2d& uv, const ThbFitOptions& options = {});

}  // namespace holefill
