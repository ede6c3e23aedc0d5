// The canonical frame a learned parameterizer sees a hole boundary in (uvtran.md Sec. 4, 5.1):
// the ordered 3D loop is moved to its arc-length centroid, rotated onto its principal axes
// (z = least-variance axis, signed so the loop runs counter-clockwise around +z; x = largest
// axis, signed by the third moment), scaled to a fixed RMS radius and shifted to the centre of
// the unit cube, then resampled by arc length into a fixed number of points starting at the
// point of largest x. (A loop given the other way round gets the frame turned half a turn
// about x, so the network still sees it counter-clockwise.) Training data and inference both go through this one function, so the
// network never depends on where the loop starts, which way it runs, or how it is placed,
// rotated or scaled in the model.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace holefill::learn {

struct CanonicalFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // arc-length centroid of the loop (model units)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // rows: canonical x, y, z axes in model coordinates
  double scale = 1.0;                                 // canonical units per model unit
  Eigen::Vector3d toCanonical(const Eigen::Vector3d& p) const;
  Eigen::Vector3d toModel(const Eigen::Vector3d& q) const;
};

struct CanonicalBoundaryOptions {
  int samples = 128;         // points handed to the network
  double rmsRadius = 0.24;   // RMS distance of the loop from its centroid, canonical units
};

struct CanonicalBoundary {
  CanonicalFrame frame;
  std::vector<Eigen::Vector3d> points;  // `samples` points, canonical coordinates, counter-clockwise about +z
  std::vector<double> loopParameter;    // for each point: its position along the input polyline, in
                                        // [0, n) with n = input points (i + f means between i and i + 1)
};

// `loop` is a closed polyline (last point connects to the first), at least 6 distinct points,
// finite, enclosing area. Throws holefill::Error otherwise.
CanonicalBoundary canonicalizeBoundary(const std::vector<Eigen::Vector3d>& loop,
                                       const CanonicalBoundaryOptions& options = {});

// The loop's frame alone (origin, axes, scale), as canonicalizeBoundary computes it.
CanonicalFrame canonicalFrame(const std::vector<Eigen::Vector3d>& loop, const CanonicalBoundaryOptions& options = {});

}  // namespace holefill::learn
