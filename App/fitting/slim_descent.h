// Fold-free descent of a planar map's distortion (Rabinovich, Poranne, Panozzo & Sorkine-Hornung,
// "Scalable Locally Injective Mappings", 2017): the symmetric Dirichlet energy
// Σ_t A_t (|J_t|² + |J_t⁻¹|²) / Σ_t A_t of the map's per-triangle Jacobians J_t, minimised by
// reweighted local–global steps (each a sparse least-squares solve whose weights come from the
// singular values of J_t) with a line search that stops short of the first triangle turning over.
// The energy grows without bound as a triangle flattens, so a map that starts with no triangle
// turned over never gets one: the repair for the labeled parameterization's ARAP, whose global
// steps fold triangles where a stretch left free meets a held side (mesh-extension.md sec. 4.2
// asks for a map that does not fold; ARAP alone does not promise one).
//
// The map is linear in its unknowns, uv = map · z (rows 2v and 2v + 1: vertex v's u and v), so
// held, sliding and scaled vertices (the labeled parameterization's sides and its rectangle's
// width and height) are expressed by the caller; triangles flat or turned over in every map
// (three vertices held on one line, or turned over in the input itself) are left out.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace holefill {

struct SlimProblem {
  Eigen::SparseMatrix<double> map;     // (2 · vertices) × unknowns: uv(v, c) = row 2v + c of map · z
  Eigen::MatrixX3i triangles;          // anticlockwise in the map
  std::vector<Eigen::Matrix2d> rest;   // per triangle: columns x1 − x0 and x2 − x0 in its own isometric frame (positive area)
  std::vector<char> skip;              // per triangle: left out of the energy and of the fold test
  // Per triangle (or empty): weighed by ARAP's |J − R|² instead, without a barrier, so that a
  // triangle flat at the start (which the barrier cannot weigh) still holds its vertices and may
  // open; it is not part of the fold test either.
  std::vector<char> soft;
};

struct SlimOptions {
  int iterations = 60;    // local–global rounds at most
  double stop = 1e-6;     // relative decrease of the energy below which it stops
};

struct SlimResult {
  Eigen::VectorXd z;
  double startEnergy = 0, energy = 0;  // 4 is an isometry (|J|² + |J⁻¹|² = 4 for a rotation)
  int iterations = 0;
};

// The rest shapes of a mesh's triangles in their own isometric frames (SlimProblem::rest).
std::vector<Eigen::Matrix2d> restShapes(const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles);

// The map's signed area of triangle t at z (positive: anticlockwise).
double mappedArea(const SlimProblem& problem, const Eigen::VectorXd& z, int t);

// z0 must turn no triangle that is neither skipped nor soft over or flatten it; throws Error otherwise, or for
// sizes that disagree. Every iterate, and the result, keeps every such triangle's area positive.
SlimResult slimDescent(const SlimProblem& problem, const Eigen::VectorXd& z0, const SlimOptions& options = {});

}  // namespace holefill
