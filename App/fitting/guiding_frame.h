// The guiding frame of labeled fitting (mesh-extension.md sec. 4.1, after Vaitkus & Várady): up
// to four Bézier curves, one per labeled side of the presumed four-sided patch, joined at shared
// corners, fitted to the labeled boundary points by least squares with the bending energy
// ∫|c''|² as regulariser (eq. (1)-(2)). Parameters come from projecting the points on the
// current frame; the fit starts linear (a quadrilateral) and raises the degree while the points
// are not met within the tolerance. A corner the labels stop well short of is taken where the
// two sides' own cubic fits, continued, meet, and held there. With three labeled sides the frame is three curves; with
// two, two (sharing a corner when they are adjacent). The frame sets the corners and
// proportions the labeled parameterization maps to the domain rectangle.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace holefill {

// Sides in counterclockwise order around the domain rectangle (u to the right, v up): South runs
// along v = 0 from u = 0 to 1, East along u = 1 upwards, North along v = 1 from u = 1 to 0, West
// along u = 0 downwards. A side's points are given in that running direction.
enum class Side { South = 0, East = 1, North = 2, West = 3 };

struct LabeledSides {
  std::array<std::vector<Eigen::Vector3d>, 4> points;  // empty: the side is not labeled
};

struct GuidingFrameOptions {
  double tolerance = 1e-3;   // max point-to-frame distance, relative to the points' bounding-box diagonal
  double bending = 1e-6;     // λ of eq. (1), per point and relative to the bending matrix's largest entry
  int maxDegree = 7;         // the highest Bézier degree tried
  int roundsPerDegree = 200; // at most, least-squares + projection rounds before raising the degree
};

struct GuidingFrame {
  int degree = 1;
  std::array<bool, 4> labeled{};                 // sides with a curve
  std::array<Eigen::MatrixX3d, 4> control;       // Bézier control points per labeled side (degree + 1 rows)
  std::array<std::vector<double>, 4> parameters; // each labeled point's parameter on its side's curve
  double maxDeviation = 0, rmsDeviation = 0;     // point-to-frame distances / diagonal
  int rounds = 0;                                // least-squares rounds in all

  Eigen::Vector3d point(Side side, double t) const;
};

// Throws Error when fewer than two sides are labeled, a labeled side has fewer than two points,
// or a point is not finite.
GuidingFrame fitGuidingFrame(const LabeledSides& sides, const GuidingFrameOptions& options = {});

}  // namespace holefill
