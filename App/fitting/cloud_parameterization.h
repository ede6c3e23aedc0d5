// Classical meshless parameterization of a point cloud with known boundary parameters
// (bidgcn.md sec. 3.2, after Floater & Reimers, "Meshless parameterization and surface
// reconstruction", CAGD 18, 2001): every interior point's (u, v) is a convex combination of its
// neighbours' — u_i = Σ λ_ik u_k — with the boundary points' parameters fixed, one sparse linear
// system. Neighbours are the points within a radius r (default 3/√|P| after scaling the cloud
// into the unit cube, the paper's eq. (7)); weights uniform (1/|N_i|), inverse distance, or
// shape-preserving (Floater 1997: the Delaunay neighbours of the point in the projection of its
// ball onto the ball's best-fit plane, weights from the geodesic polar map, which reproduce
// planar configurations exactly). These are the baselines BIDGCN is measured against, and user
// options in their own right. The same entry also runs BIDGCN (learn/bidgcn.h) on the same
// checked, unit-cube-scaled cloud, so every door offers all four methods one way.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace holefill {

// Bidgcn is not a weighting: the learned network predicts the interior parameters directly.
enum class CloudWeights { Uniform, InverseDistance, ShapePreserving, Bidgcn };

struct CloudParameterizationOptions {
  CloudWeights weights = CloudWeights::ShapePreserving;
  double radius = 0;  // neighbourhood radius in the unit-cube-scaled cloud; 0: 3/√|P| (BIDGCN: the
                      // duplicate check's only; the network's graphs have their trained radius)
  std::string weightsFile;  // BIDGCN: empty for the shipped weights
};

struct CloudParameterization {
  Eigen::MatrixX2d uv;                 // per point; boundary points keep theirs
  double radius = 0;                   // the radius used (unit-cube scale)
  int minNeighbours = 0, maxNeighbours = 0;  // over interior points
  int grown = 0;                       // shape-preserving: points whose ball was grown (2r, 4r) to surround them
  int fallbacks = 0;                   // shape-preserving: points on their ball's hull even so, given inverse-distance weights
  double seconds = 0;
  std::vector<std::string> warnings;
  int points = 0, boundaryPoints = 0;
  std::string method;                  // the weights' name, as cloudWeightsByName takes it
  std::string toJson() const;          // the report the CLI and Python print
};

// `boundary[k]` marks points whose parameters boundaryUV.row(k) are given (other rows ignored).
// Throws Error for fewer than 10 points, fewer than 3 boundary points, non-finite input,
// coinciding points, an interior point without neighbours within the radius, or interior points
// the radius graph does not connect to the boundary.
CloudParameterization parameterizeCloud(const Eigen::MatrixX3d& points, const std::vector<bool>& boundary, const Eigen::MatrixX2d& boundaryUV,
                                        const CloudParameterizationOptions& options = {});

std::string cloudWeightsName(CloudWeights weights);            // the name cloudWeightsByName takes back
CloudWeights cloudWeightsByName(const std::string& name);  // "uniform", "invdist", "shape", "bidgcn"; throws Error otherwise

}  // namespace holefill

namespace holefill {

// Parameters for a cloud's boundary points given without them (bidgcn.md sec. 3.2): the points
// ordered around the boundary (by angle about their centroid in the cloud's best-fit plane, so the
// boundary must be star-shaped from there), four corners — the given point indices, or the four
// sharpest turns of the ordered loop, kept apart — on the unit square's corners, anticlockwise
// from the one nearest the plane's lower left, and chord length along each side in between.
// Returns uv per point (rows of non-boundary points 0). Throws Error for fewer than 4 boundary
// points or corners that are not 4 distinct boundary points.
Eigen::MatrixX2d boundaryChordParameters(const Eigen::MatrixX3d& points, const std::vector<bool>& boundary,
                                         const std::vector<int>& corners = {});

}  // namespace holefill
