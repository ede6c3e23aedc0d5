// The boundary points of a scanned point cloud given without them (bidgcn.md sec. 3.2 assumes a
// known boundary; scans come without): the cloud is projected onto its best-fit plane and the
// outer boundary of its regularized alpha shape (CGAL) is taken, with α tied to the sampling —
// a multiple of the median Delaunay edge — so that concave notches wider than a few point
// spacings are followed while gaps of the sampling are not taken for edges (concave corners are
// rounded at that radius: points deep in them are not marked). Holes inside the
// cloud are not boundary: only the component with the most boundary edges is kept. The cloud
// must be a height field over that plane (as every method here assumes).
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace holefill {

struct CloudBoundaryOptions {
  double alphaSpacings = 3.0;  // alpha-disc radius, in median Delaunay edge lengths
};

struct CloudBoundary {
  std::vector<bool> boundary;  // per point
  int count = 0;               // boundary points
  double spacing = 0;          // the median Delaunay edge length (model units)
};

// Throws Error for fewer than 10 points, non-finite or coinciding-in-the-plane points, a cloud
// spanning no area, or an alpha shape without a boundary loop.
CloudBoundary detectCloudBoundary(const Eigen::MatrixX3d& points, const CloudBoundaryOptions& options = {});

}  // namespace holefill
