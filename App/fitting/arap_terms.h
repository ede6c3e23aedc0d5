// The pieces of the As-Rigid-As-Possible energy (Liu et al. 2008, "A Local/Global Approach to
// Mesh Parameterization") that the labeled map (labeled_parameterization.h) and the free map
// (free_flattening.h) share: per triangle edge, its cotangent weight and its vector in the
// triangle's own isometric frame; the local step's best rotation per triangle; and which triangles
// count as folds in a map. The energy is Σ_t Σ_edges w (u_i − u_j − R_t x_ij)²; mesh-extension.md
// sec. 4.2 minimises it with labeled vertices held, the free map with none.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "mesh/triangle_mesh.h"

namespace holefill {

struct ArapTerm {
  int t, i, j;        // triangle, edge from i to j
  double w;           // half the cotangent of the opposite corner, at least 1e-4 (obtuse corners keep real rows)
  Eigen::Vector2d x;  // x_i − x_j in the triangle's own isometric frame
};

// Three terms per triangle, in the triangles' order (edges opposite corners 0, 1, 2).
// `reference` is set to Σ w |x|², by which energies are made relative.
std::vector<ArapTerm> arapTerms(const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles, double& reference);

// The local step: per triangle the rotation nearest (Frobenius) to its map's Jacobian in the
// terms' frames; reflections are excluded.
std::vector<Eigen::Matrix2d> arapRotations(const std::vector<ArapTerm>& terms, const Eigen::MatrixX2d& uv, int triangles);

// Signed area of triangle t in a map (positive: anticlockwise).
double signedArea(const Eigen::MatrixX2d& uv, const Eigen::Vector3i& t);

// Triangles the input itself has turned over (normal against its corners' mean vertex normal:
// scan noise of a third of an edge does this to some). They fold in every map, so they are not
// the map's folds.
std::vector<char> trianglesTurnedInInput(const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles);

}  // namespace holefill
