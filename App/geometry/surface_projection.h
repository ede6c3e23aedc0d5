// Orthogonal projection of an ordered point sequence onto a B-spline surface (The NURBS Book
// Sec. 6.1, point inversion by Newton's method): each point starts from its predecessor's
// parameters, so a projected loop stays continuous along its parameter and never jumps to a far
// sheet of the surface; a coarse grid search seeds the first point and any point whose Newton
// run fails to improve on its seed. Parameters stay in the surface's domain, or in the domain
// grown by `extension` on every side, where the end spans' polynomials continue the surface (a
// point beyond a slightly small surface then keeps its own parameter instead of piling up on
// the domain's edge).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "geometry/bspline_surface.h"

namespace holefill {

struct ProjectionOptions {
  int gridCells = 24;       // per direction, for seeding
  int maxIterations = 20;
  double tolerance = 1e-12;  // on the squared parameter step
  double extension = 0.0;    // fraction of the domain's size added on every side
};

struct ProjectionResult {
  std::vector<Eigen::Vector2d> uv;
  std::vector<double> distance;  // |S(uv) - p|
  int gridSearches = 0;
};

ProjectionResult projectSequence(const BSplineSurface& s, const std::vector<Eigen::Vector3d>& points,
                                 const ProjectionOptions& options = {});

// One point by Newton from the parameters `uv` (updated), within the surface's domain; returns
// the distance reached. For callers that seed from their own search (several patches).
double projectPointFrom(const BSplineSurface& s, const Eigen::Vector3d& point, Eigen::Vector2d& uv,
                        const ProjectionOptions& options = {});

}  // namespace holefill
