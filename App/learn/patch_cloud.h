// Synthetic point clouds for BIDGCN (bidgcn.md sec. 4.2): a random biquadratic Bézier patch whose
// control points c_ij are drawn from [i/2 ± 1/4] × [j/2 ± 1/4] × [−1, 1] (varied, never folded),
// rotated about a random axis by a random angle, sampled at uniformly random (u, v) — the four
// corners plus random points on random sides as the sparse boundary, whose exact parameters are
// the boundary condition — then scaled into the unit cube (sec. 4.3) and, optionally, disturbed by
// Gaussian noise. The network's training data, its validation set and the benchmark's test clouds
// all come from here, from disjoint seed ranges; same seed, same cloud. Also the quality measure
// the network is trained on and judged by: the least-squares Bézier fit's residual (eq. (2), (4)).
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

namespace holefill::learn {

struct PatchCloudOptions {
  int interior = 1000;  // the paper's training clouds: 1000 interior + 34 boundary points
  int boundary = 34;    // ≥ 4: the corners come first
  int degree = 2;       // of the random Bézier patch (2: the paper's; 3..5 for generalization tests)
  double sigma = 0;     // Gaussian noise per coordinate after scaling into the unit cube
};

struct PatchCloud {
  Eigen::MatrixX3d points;     // boundary points first, then interior points
  std::vector<bool> boundary;  // true for the first `options.boundary` rows
  Eigen::MatrixX2d uv;         // exact parameters of every point (for the boundary: the condition)
};

PatchCloud randomPatchCloud(uint64_t seed, const PatchCloudOptions& options = {});

// Disjoint seed ranges, so validation and test clouds are never trained on.
enum class PatchCloudSplit { Train, Validation, Test };
uint64_t patchCloudSeed(PatchCloudSplit split, uint64_t index);

// Mean over points of |S(u_k) − p_k|² for the least-squares Bézier surface S of the given degree
// at the parameters (rank-revealing QR, so degenerate parameters give a finite answer).
double bezierFitMse(const Eigen::MatrixX3d& points, const Eigen::MatrixX2d& uv, int degree = 2);

}  // namespace holefill::learn
