// The systematic part of a fit's residual on a noisy region. A fit's residual is the scan noise,
// which is independent from vertex to vertex, plus the model error (too few control points, a
// distorted map), which is alike between neighbours. Averaged over a vertex's neighbourhood of
// `window` vertices the noise falls by √window and the model error stays: the largest such mean
// is the model error a stopping rule must read. The data RMS cannot: a bump or horn the fit
// cuts off holds a few percent of the vertices and hardly moves it (Morozov's discrepancy
// principle, the data RMS within 1.5 σ, stopped 12 × 12 on a noisy B-spline ring whose fit then
// missed the true surface by 5 σ). Used by labeled fitting's refinement (labeled_fit.h).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "mesh/mesh_holes.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

struct ResidualBias {
  double max = 0;  // the largest |mean signed residual| over a neighbourhood, the residual's units
  int at = -1;     // the vertex whose neighbourhood it is
};

// Per vertex, the mean of `residual` over its neighbourhood and how many vertices that holds
// (the neighbourhood as residualBias's). Throws Error as residualBias.
struct NeighbourhoodMeans {
  Eigen::VectorXd mean;
  Eigen::VectorXi count;
};
NeighbourhoodMeans neighbourhoodMeans(const TriangleMesh& mesh, const Eigen::VectorXd& residual, int window);

// `residual`: per vertex of `mesh`, the signed residual along the normal. A vertex's
// neighbourhood: its rings taken whole until they hold `window` vertices (itself included), or
// its whole component. Throws Error when the sizes disagree or window < 1.
ResidualBias residualBias(const TriangleMesh& mesh, const Eigen::VectorXd& residual, int window = 25);

// The vertices where a fit misses by more than scan noise of σ (model units) explains, at any
// scale: a neighbourhood of w vertices (w = 1, 7 and 25 by rings, and runs of 3, 5 and 9 along
// `boundary`, the mesh's boundary loops) whose mean squared residual exceeds what w noise residuals reach
// (χ²_w at 4.4 standard deviates, Wilson–Hilferty; about the largest of 20,000 draws). Squares,
// not the signed mean residualBias reads: where a fit cannot bend enough (a reflex corner) the
// boundary vertices lie below it and their inner neighbours above, and the signed mean cancels
// (bspline_notch_n0p05 of the labeled corpus at 32 × 32: boundary vertices 3.1, 4.5 and 4.8 σ
// off, their 25-vertex means 0.1 σ). Runs along the boundary, since a ring neighbourhood of a
// boundary vertex is mostly inner vertices. Per vertex, 1 where it misses. Used by labeled
// fitting's local refinement (labeled_fit.h), which finds the loops once (findMeshHoles) for the
// fits it tests. Throws Error as residualBias, or for σ ≤ 0.
std::vector<char> verticesMissedPastNoise(const TriangleMesh& mesh, const std::vector<MeshHole>& boundary, const Eigen::VectorXd& residual,
                                          double sigma);

}  // namespace holefill
