// Synthetic training data for UVTran (uvtran.md Sec. 5.1, adapted): a hole boundary sampled from
// a known surface, with the answer the network must give. Each sample draws
//  - a target surface: a clamped bicubic B-spline with 8x8 control points and 4 random interior
//    knots per direction, interpolating a smooth generator at its Greville abscissae. Generators
//    are near-isometric bendings of a plane (flat, bumpy, cylinder-like, dome-like, saddle) with
//    low-frequency height waves, plus the paper's structured perturbations (a boundary row or
//    column of control points shifted) and small noise;
//  - a closed pcurve in the unit square: 3-8 sides, straight or curved, uneven lengths,
//    concave corners, local bumps, some stretched up to 2.5:1 (strips such as removed fillets);
// and records B(t) = S(pcurve(t)) in the canonical frame (canonical_boundary.h), with the
// ground-truth (u, v) of every boundary point and the surface's poles and knots there.
// The task is made well posed by construction: the pcurve's centre and RMS radius are fixed in
// the domain, and the domain is rotated/mirrored so S_u follows the canonical x axis and the
// normal the canonical z axis at the centre; what remains is the intrinsic shape of the
// boundary, which is what a good parameterization has to follow. Same seed, same sample.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/bspline_surface.h"
#include "learn/canonical_boundary.h"

namespace holefill::learn {

constexpr int kUvtranGrid = 8;           // control points per direction
constexpr int kUvtranInteriorKnots = 4;  // per direction

struct UvtranDataOptions {
  CanonicalBoundaryOptions canonical;  // boundary samples (128) and canonical RMS radius (0.24)
  int densePcurveSamples = 2048;       // pcurve points before arc-length resampling
  double pcurveRmsRadius = 0.27;       // RMS distance of the pcurve from (0.5, 0.5) in the domain
  double poleMargin = 0.004;           // canonical poles must lie in [margin, 1 - margin]^3
  int maxAttempts = 200;               // redraws before giving up on a seed
};

struct UvtranSample {
  std::vector<Eigen::Vector3d> boundary;  // canonical, counter-clockwise about +z
  std::vector<Eigen::Vector2d> params;    // ground-truth (u, v) of each boundary point on `surface`
  std::vector<int> cornerSamples;         // boundary indices nearest to the pcurve's corners
  BSplineSurface surface;                 // canonical coordinates, poles in [0, 1]^3
  int sides = 0;
  std::string family;                     // flat | bumpy | cylinder | dome | saddle
  uint64_t seed = 0;
  int attempts = 0;
};

UvtranSample makeUvtranSample(uint64_t seed, const UvtranDataOptions& options = {});

// Disjoint seed ranges, so validation and test samples are never trained on.
enum class UvtranSplit { Train, Validation, Test };
uint64_t uvtranSeed(UvtranSplit split, uint64_t index);

// The 4 interior knots of a clamped cubic knot vector with 8 poles, and back.
std::vector<double> interiorKnots(const std::vector<double>& knots);
std::vector<double> clampedCubicKnots(const std::vector<double>& interior);

}  // namespace holefill::learn
