// Initial triangulation of one hole by the modified principle of minimum angle (Hu et al.,
// section III.B). Each loop vertex gets angle θ (convex) or 2π − θ (concave), the convexity
// read from the oriented triangle (v_{i−1}, v_i, v_{i+1}) against the vertex normal; the ear at
// the vertex of least angle is cut, provided the normals of its two neighbours differ by at
// most σ (45° when all boundary normals lie within 55° of each other, else 85% of their
// largest difference). Cutting ears at similar normals first keeps a crease that crosses the
// hole as a crease of the patch. Beyond the paper, an ear is never cut when its new edge
// already exists (in the mesh or the patch) or when its triangle would fold back onto a
// neighbour; if no ear passes, σ is dropped first and the fold test second. Ears are kept
// ordered by (relaxation needed, angle) and re-keyed around each cut, so a hole of n vertices
// costs O(n log n) cuts plus one O(n²) scan of dot products for σ.
#pragma once

#include <cmath>

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace holefill {

struct MinAngleOptions {
  double lowNormalSpread = 55.0 * M_PI / 180;   // below this largest normal difference, σ = smallSigma
  double smallSigma = 45.0 * M_PI / 180;
  double sigmaShare = 0.85;                     // otherwise σ = sigmaShare · largest normal difference
  double maxFoldAngle = 150.0 * M_PI / 180;     // an ear whose normal turns more than this against a neighbour folds
};

struct MinAngleResult {
  std::vector<std::array<int, 3>> triangles;    // indices into the loop, oriented against the loop direction
  double sigma = 0;                             // the threshold used (radians)
  int earsWithoutSigma = 0;                     // ears cut after relaxing σ
  int earsWithFold = 0;                         // ears cut after relaxing the fold test too
};

// loop: the hole's vertices in the direction of the surrounding triangles' edges.
// normalSums: per loop vertex, the area-weighted sum of its surrounding triangles' normals
// (length twice the area; the triangulation adds its own triangles as it goes).
// outsideNormals: per loop edge k (loop[k] → loop[k+1]), the unit normal of the surrounding
// triangle on it. edgeExists(i, j) says whether loop vertices i and j are already joined by
// an edge of the mesh. Throws holefill::Error when no ear can be cut at all.
MinAngleResult triangulateMinAngle(const std::vector<Eigen::Vector3d>& loop,
                                   const std::vector<Eigen::Vector3d>& normalSums,
                                   const std::vector<Eigen::Vector3d>& outsideNormals,
                                   const std::function<bool(int, int)>& edgeExists,
                                   const MinAngleOptions& options = {});

}  // namespace holefill
