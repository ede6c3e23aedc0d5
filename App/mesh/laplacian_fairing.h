// Shape of the patch: new vertices placed by discrete fairing, Δ^k x = 0 with the cotangent
// (or uniform umbrella) Laplacian over the patch and the surrounding mesh's ring around the hole, loop
// vertices and that ring held fixed (Liepa, "Filling holes in meshes", section 4, and the
// umbrella operator of Kobbelt et al. that Hu et al. cite for it). Not in Hu et al.: their
// refinement places new vertices on the flat triangles of the initial triangulation and the
// bilateral filter only smooths, so a fill of a curved region stays as flat as the hole's
// boundary polygon (measured 2× the distance of Liepa's fill to the cut-away surface of the
// Stanford bunny). k = 2 (thin plate) continues the surrounding surface's slope across the
// boundary; the bilateral filter then runs on the faired patch as the paper has it. New
// vertices move along their normals only (one offset each, making the normal part of Δ^k x
// vanish; repeated with fresh normals and relaxed edges, `passes` times), so the
// triangle layout and quality made by refinement and smoothing survive, and planar holes stay
// planar.
#pragma once

#include <array>
#include <vector>

#include "mesh/hole_patch.h"

namespace holefill {

// The surrounding mesh's triangles around the hole's loop: their corners are loop vertices
// (index < boundaryCount, the patch's own numbering) or ring points (index boundaryCount + k
// for points[k]). They carry the surrounding slope and curvature into the solve.
struct SurroundingRing {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
};

enum class LaplacianWeights { Uniform, Cotangent };

struct LaplacianFairingOptions {
  LaplacianWeights weights = LaplacianWeights::Cotangent;  // cotangent: the normal part of L follows curvature, not mesh irregularity
  int order = 2;                       // 0: off (the paper's flat placement), 1: membrane, 2: thin plate, 3: minimum variation
  bool alongNormals = true;            // false: vertices move freely (tangential drift is left to the quality pass)
  int passes = 3;                      // solve, relax edges in the new shape, solve again ... (connectivity follows the shape)
  // From this many new vertices on, an order above 2 is solved at 2: L^3's wider stencil fills its
  // sparse LU in badly (a 20,000-vertex hole's cap of 0.1 million triangles took 23 s at order 3,
  // 4 s at 2; docs/benchmarks.md, issue 26). 0: never.
  int highOrderUpTo = 20000;
};

// Throws holefill::Error if the sparse solve fails.
void fairLaplacian(HolePatch& patch, const SurroundingRing& ring, const LaplacianFairingOptions& options = {});

}  // namespace holefill
