// Shape of the patch: new vertices placed by discrete fairing, Δ^k x = 0 with the uniform
// (umbrella) Laplacian over the patch and the surrounding mesh's ring around the hole, loop
// vertices and that ring held fixed (Liepa, "Filling holes in meshes", section 4, and the
// umbrella operator of Kobbelt et al. that Hu et al. cite for it). Not in Hu et al.: their
// refinement places new vertices on the flat triangles of the initial triangulation and the
// bilateral filter only smooths, so a fill of a curved region stays as flat as the hole's
// boundary polygon (measured 2× the distance of Liepa's fill to the cut-away surface of the
// Stanford bunny). k = 2 (thin plate) continues the surrounding surface's slope across the
// boundary; the bilateral filter then runs on the faired patch as the paper has it. New
// vertices move along their normals only (a least-squares solve for one offset each), so the
// triangle layout and quality made by refinement and smoothing survive, and planar holes stay
// planar.
#pragma once

#include <vector>

#include "mesh/hole_patch.h"

namespace holefill {

struct LaplacianFairingOptions {
  int order = 2;                       // 0: off (the paper's flat placement), 1: membrane, 2: thin plate, 3: minimum variation
};

// outerRing[k]: positions of loop vertex k's neighbours in the surrounding mesh that are not
// loop vertices (the fixed ring that carries the surrounding slope into the solve).
// Throws holefill::Error if the sparse solve fails.
void fairLaplacian(HolePatch& patch, const std::vector<std::vector<Eigen::Vector3d>>& outerRing,
                   const LaplacianFairingOptions& options = {});

}  // namespace holefill
