// The scan noise of a triangle mesh: the standard deviation σ of independent offsets of its
// vertices along the surface normal, estimated from the mesh alone. A vertex's umbrella offset
// (the mean of its neighbours less the vertex, along its normal) holds the curvature, which is
// alike between neighbours, and the noise, which is not; the difference between a vertex's
// offset and its neighbours' mean, (I − A)² applied to the normal offsets with A the umbrella
// average, cancels the curvature to O(h⁴) and leaves noise whose spread on a valence-6
// triangulation is σ·√(Σc²) = 1.359σ (c: the coefficients of (I − A)², 7/6 at the vertex, −10/36
// at its six neighbours, 1/36 and 2/36 at the twelve of the second ring). The median of its
// magnitude, over interior vertices, is 0.6745 of that spread: robust to a few bad vertices, and
// to the boundary, which is left out. Used by labeled fitting to stop refining where what is left
// is noise (Morozov's discrepancy principle), and by its parameterization to smooth only noisy
// regions.
#pragma once

#include "mesh/triangle_mesh.h"

namespace holefill {

struct ScanNoise {
  double sigma = 0;     // model units; 0 for fewer than 8 interior vertices
  double meanEdge = 0;  // the mesh's mean edge length, model units (a scale to judge sigma by)
  int samples = 0;      // interior vertices measured
};

ScanNoise estimateScanNoise(const TriangleMesh& mesh);

}  // namespace holefill
