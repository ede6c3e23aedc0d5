// Triangulation of one hole by minimum weight, as in Liepa ("Filling holes in meshes", 2003,
// section 3, after Barequet–Sharir): a dynamic program over the loop's sub-polygons picks the
// triangulation whose largest dihedral angle (between neighbouring new triangles, and against
// the surrounding triangles along the loop) is smallest, then the smallest area. It is the
// peer's triangulation, offered beside the paper's minimum-angle one: on strongly non-planar
// loops (a hole across a saddle or a junction) it follows the surface where greedy ear cutting
// does not. O(n³) time and O(n²) memory in the loop's vertex count n.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <vector>

namespace holefill {

// loop, outsideNormals and edgeExists as for triangulateMinAngle. Returns triangles as loop
// indices, oriented against the loop. Throws holefill::Error when every triangulation would
// repeat an existing edge.
std::vector<std::array<int, 3>> triangulateMinDihedral(const std::vector<Eigen::Vector3d>& loop,
                                                       const std::vector<Eigen::Vector3d>& outsideNormals,
                                                       const std::function<bool(int, int)>& edgeExists);

}  // namespace holefill
