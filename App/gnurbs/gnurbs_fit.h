// Fitting a G² G-NURBS surface to a target point set (g2-gnurbs.md sec. 5.2, the paper's
// reconstruction application): the surface is linear in the cage vertices and the anchors
// (Bézier extraction, the Catmull–Clark step and the constrained solve are all linear in the
// positions), so its basis functions are the surfaces of unit cages, computed by building the
// surface once per three control variables with the factorisations kept (G2GnurbsBuilder).
// Each round fits the control variables to the target by least squares at fixed parameters
// (tangent distance: to the tangent planes at the footpoints, plus a little point distance),
// with a small cage-Laplacian term for variables the data does not reach, then moves each
// target point's parameters to its closest point on the new surface (Newton from the nearest
// of a grid of samples over every patch). Distances are reported as fractions of the target's
// bounding-box diagonal, overall and on the patches of faces that touch a sharp edge.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "gnurbs/g2_gnurbs.h"

namespace holefill {

struct GnurbsFitOptions {
  int iterations = 6;          // least-squares + projection rounds
  int samplesPerPatch = 6;     // seed grid per patch side for the closest-point search
  double smoothness = 1e-6;    // weight of the cage Laplacian of the update, relative to the data term
  double tangentialWeight = 0.1;  // μ of the tangent distance: point-to-plane plus μ × point-to-point
  bool fitAnchors = true;      // the cage's anchors are variables too; false keeps them where they are
  G2GnurbsOptions surface;     // how each surface is built
};

struct GnurbsFitResult {
  QuadCage cage;                          // the fitted cage (input topology, fitted anchors)
  G2GnurbsResult surface;                 // its surface
  double dMax = 0, dAvg = 0;              // distances target → surface / target diagonal
  double dMaxSharp = 0, dAvgSharp = 0;    // the same over points whose closest patch touches a sharp edge
  int sharpPoints = 0;
  std::vector<double> dAvgPerRound;       // before the first fit, then after each round
  int variables = 0;                      // cage vertices + anchors
  int points = 0;                         // of the target
  double seconds = 0;
};

// Throws Error for an empty or non-finite target and for invalid cages (buildG2Gnurbs).
GnurbsFitResult fitGnurbs(const QuadCage& initial, const Eigen::MatrixX3d& target, const GnurbsFitOptions& options = {});

}  // namespace holefill
