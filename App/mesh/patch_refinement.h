// Density refinement of a hole's patching mesh after Pfeifle and Seidel, as Hu et al. use it
// (section III.C): every loop vertex carries a scale σ, the mean length of its edges in the
// surrounding mesh; a triangle is split at its centroid c (σ(c) the mean of its corners')
// when α·|c − v_m| exceeds both σ(c) and σ(v_m) for all three corners and its largest angle is
// below 5π/6, after which its three old edges are relaxed; when a pass splits nothing the
// patch is done, otherwise all interior edges are relaxed until none swaps and splitting
// resumes. Relaxing an edge swaps it when an opposite vertex lies inside the circumsphere of
// the other triangle, tested in the equivalent symmetric form (the two angles facing the edge
// sum to more than π). Swaps never create an existing edge, a degenerate or folded triangle.
// Beyond the paper, the bare triangulation is relaxed once before the first split, so small
// holes that never split still get Delaunay-like triangles.
#pragma once

#include <cmath>

#include <string>

#include "mesh/hole_patch.h"

namespace holefill {

struct RefinementOptions {
  double densityFactor = 1.4142135623730951;   // α; √2 matches the surrounding density (paper)
  double maxSplitAngle = 5 * M_PI / 6;         // triangles with a larger angle are not split
  double maxFoldAngle = 150.0 * M_PI / 180;    // a swap may not turn neighbouring normals further apart
  int maxRounds = 200;                         // split/relax rounds (safety cap, never reached on sane input)
  int maxRelaxPasses = 100;                    // relaxation passes per round (3D swaps may cycle)
  int maxVertices = 2000000;                   // new vertices per hole before giving up with an error
};

struct RefinementResult {
  int splits = 0, swaps = 0, rounds = 0;
  bool capped = false;                         // a safety cap ended a loop early
};

// Refines `patch` in place; patch.scale must hold σ for the loop vertices.
RefinementResult refinePatch(HolePatch& patch, const RefinementOptions& options = {});

// Relaxes the listed edges, and every edge a swap disturbs, until no swap happens (or the
// work cap of maxRelaxPasses × triangles); returns the swap count.
int relaxEdges(HolePatch& patch, PatchEdges& edges, std::vector<std::pair<int, int>> work, const RefinementOptions& options,
               bool* capped = nullptr);
// relaxEdges on every edge of the patch.
int relaxAllEdges(HolePatch& patch, PatchEdges& edges, const RefinementOptions& options, bool* capped = nullptr);

}  // namespace holefill
