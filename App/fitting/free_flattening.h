// Free flattening of a mesh region: the As-Rigid-As-Possible map (Liu et al. 2008) with every
// boundary vertex free, started from the as-similar-as-possible (least-squares conformal) map,
// which a single sparse solve gives. A developable region comes out isometric, a curved one with
// its distortion spread evenly; nothing is pressed onto a line. This is the map of the paper's
// comparison without labels (mesh-extension.md sec. 6, Figs. 8b/9b, there a projection), and
// the one labeled fitting falls back to where the labels cannot hold (labeled_fit.h): labels by a
// bounding-box rule that put a crescent's inner arc, a slot or an L's inner corner on the sides
// of a rectangle make that map singular at single boundary points, which no tensor-product
// surface of reasonable size follows. Global steps that would turn triangles over are stepped back
// towards the last map without folds (flip repair), as in labeled_parameterization.h. ARAP does
// not keep distant parts of a free boundary from overlapping (an arm of a saddle's U-slot laid
// over the other); started instead from a map given without folds or overlaps (the labeled one),
// a step is also stepped back where the boundary would run over itself, so the map stays one to
// one (a simpler relative of the scaffold of Jiang et al. 2017, whose triangles between the
// boundary and a box forbid the same).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.h"

namespace holefill {

struct FreeFlatteningOptions {
  // Local–global rounds: at least `iterations`, then on while ten rounds still lower the energy
  // by 1% or more, up to `maxIterations` (as LabeledParameterizationOptions).
  int iterations = 40;
  int maxIterations = 400;
  // A map per vertex to start from instead of the as-similar-as-possible one; without folds and
  // with its boundary loops simple, every step then keeps them so. Empty: the conformal start.
  Eigen::MatrixX2d start;
};

struct FreeFlattening {
  Eigen::MatrixX2d uv;           // per vertex; the triangles keep their orientation (anticlockwise stays anticlockwise)
  int flippedTriangles = 0;      // turned over in the returned map (triangles turned over in the input itself not counted)
  bool boundaryCrosses = false;  // the returned map's boundary loops cross themselves or each other
  double arapEnergy = 0;         // Σ cot-weighted |edge − rotated edge|², relative to Σ cot-weighted |edge|²
};

// The region's triangles must be oriented consistently (labeled_parameterization checks it).
// Throws Error for fewer than two triangles, vertices used by no triangle, or a system that cannot
// be solved.
FreeFlattening flattenFree(const TriangleMesh& region, const FreeFlatteningOptions& options = {});

}  // namespace holefill
