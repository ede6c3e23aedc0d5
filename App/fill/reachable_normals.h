// The normals a fill's G1 rows aim at: the support's normal, where a surface through the loop's
// curves can have it (issue 20, inexact models). A surface through an edge's curve has a normal
// perpendicular to that curve's tangent, so along an inexact edge (its curve not in the support's
// tangent plane) the support normal itself is out of reach; the nearest reachable one is the
// support normal less its tangent component. At a corner, where two curves meet at a tangent
// break, every surface through both has the normal n_c = t_a x t_b (edge_continuity.h), and a
// support normal tilted off it by delta is out of reach by delta however the fill bends. Rows that
// still aim at it there twist the fill within a few samples of the corner, and the twist shows as
// a curvature spike across the edge (shell1 face 40 at G2: 0.25 next to a 2.2e-3 rad corner tilt,
// where the original face carried the same tilt along half the edge at a curvature error of
// 0.05). So at each such corner the aim is turned onto n_c and eased back to the support normal
// over the half of each edge nearest the corner, as the original faces do.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "brep/boundary_sampling.h"
#include "brep/hole_detection.h"

namespace holefill {

// One unit normal per sample (samples as sampleBoundary gives them: each edge's run in loop order).
// A sample without a valid support normal keeps its normal unchanged.
std::vector<Eigen::Vector3d> reachableNormals(const Hole& hole, const std::vector<BoundarySample>& samples);

}  // namespace holefill
