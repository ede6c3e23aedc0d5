// Labeled parameterization of a trimmed mesh region (mesh-extension.md sec. 4.2, after Vaitkus &
// Várady): the user labels boundary segments North/East/South/West; a guiding frame
// (guiding_frame.h) fitted to the labeled points gives where along its rectangle side each
// labeled vertex belongs and the rectangle's starting proportions; local–global
// As-Rigid-As-Possible mapping (Liu et al. 2008) then flattens the region with every labeled
// vertex held on its side, the rectangle's width and height left to the optimisation.
// Unlabeled boundary vertices and inner holes are free. Labels that run S, E, N, W clockwise
// along the triangles mean the region was labeled from its other side: it is read from there
// (the same map). The start is Tutte's embedding with the perimeter on the rectangle (unlabeled
// stretches spread along its sides by arc length), which cannot fold; a global step of ARAP that
// turns triangles over is stepped back towards the last map without folds until none is left
// (flip repair), and the result is the last map without folds. Ears of a labeled side (a
// triangle of three of its vertices) are flat in every map, not folded.
//
// Beyond the paper, for labels that run round what cannot be a side (the corpus's rule labels
// every boundary vertex): a labeled stretch that lies deep inside its side's line past a sharp
// turn — a notch, slot, bitten corner or a crescent's horn — is left free (releaseDepth), so that
// the map stays the surface's own there and the extension continues the surface into it; ARAP
// then starts from the as-similar-as-possible map, and the held map is kept instead wherever
// leaving them free did not lower the distortion. ARAP reads the triangles of a copy smoothed
// along the normal (denoise), so that scan noise is not taken for the surface's shape.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "fitting/guiding_frame.h"
#include "mesh/scan_noise.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

struct LabeledSegment {
  Side side;
  std::vector<int> vertices;  // consecutive perimeter vertices, in the perimeter's order
};

struct LabeledParameterizationOptions {
  // Local–global rounds: at least `iterations`, then on while ten rounds still lower the energy
  // by 1% or more, up to `maxIterations`. ARAP converges slowly where a stretch left free has to
  // swing far from its start (an L's other arm, beyond a held inner leg: energy 3.3e-3 after 40
  // rounds, 5.5e-7 after 200, on a plane where 0 is reachable).
  int iterations = 40;
  int maxIterations = 400;
  // Weight of the guiding frame's placement of labeled vertices along their sides, relative to
  // the mean ARAP edge weight; every labeled vertex stays on its side whatever the weight. Large:
  // the placement is held (the paper's choice); 0: ARAP alone decides it.
  double framePlacement = 1.0;
  // Labeled vertices deeper than this fraction of their side's chord inside the line supporting
  // the side (across it, within the surface) are left free: a notch, slot, concave arc or rounded
  // corner labeled as part of a side cannot lie on the rectangle's side without the map turning
  // singular there. Negative: every labeled vertex is held on its side, as given.
  double releaseDepth = 0.05;
  // Rounds of Taubin smoothing of a copy of the region whose triangles ARAP and the guiding frame
  // then read (the map is of the surface, not of its scan noise); 0: the region as given.
  int denoise = 10;
  GuidingFrameOptions frame;
};

struct LabeledParameterization {
  Eigen::MatrixX2d uv;             // per mesh vertex; labeled vertices on the sides of [0, width] × [0, height]
  double width = 0, height = 0;    // the rectangle, after the optimised scale
  std::vector<int> perimeter;      // the outer boundary loop, anticlockwise in uv
  Eigen::MatrixX3d mapped;         // the positions mapped: the region's, smoothed along the normal where it is noisy (denoise)
  ScanNoise noise;                 // the region's scan noise (mesh/scan_noise.h), which decides that
  GuidingFrame frame;
  int flippedTriangles = 0;        // in the returned map (0 unless even the start had some)
  double arapEnergy = 0;           // Σ cot-weighted |edge − rotated edge|², relative to Σ cot-weighted |edge|²
  std::vector<std::string> warnings;
};

// Throws Error for regions the method cannot take: fewer than two triangles, non-manifold or
// non-orientable meshes, several components, a segment with no vertex or with vertices not
// consecutive on the perimeter, a vertex labeled with two sides other than at a shared corner
// (e.g. North and South on one segment), fewer than two labeled sides.
LabeledParameterization parameterizeLabeled(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                            const LabeledParameterizationOptions& options = {});

// Where the labels cannot hold (labeled_fit.h tries it when the labeled map's fit misses the
// data): the region's free flattening (free_flattening.h) of the same smoothed copy, mirrored if
// need be and turned so that each labeled side lies where the rectangle has it (South below the
// labeled vertices' centre, East to its right, ...), moved into its bounding rectangle
// [0, width] × [0, height]. The labels then orient the surface's parameters without pinning any
// vertex to a line. `labeled` is the labeled map of the same region and segments (its smoothed
// copy, noise, frame and perimeter are kept). A noisy region (options.denoise) is flattened from a
// copy smoothed within its surface as well as across it: with no side held, triangles that scan
// noise turned over at the rim fold the boundary over itself. Throws Error where the flattening does.
LabeledParameterization relaxLabels(const TriangleMesh& region, const std::vector<LabeledSegment>& segments,
                                    const LabeledParameterization& labeled, const LabeledParameterizationOptions& options = {});

}  // namespace holefill
