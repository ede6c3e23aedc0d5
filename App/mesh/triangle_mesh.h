// The triangle mesh of the mesh-hole-filling pipeline (Hu et al., "Filling Holes in
// Triangular Meshes in Engineering", section II): vertices and oriented triangles as index
// triples, nothing more, so it crosses the Python door as two NumPy arrays. Here live the
// checks every mesh passes before the pipeline touches it (finite coordinates, indices in
// range, no repeated index in a triangle) and the per-triangle facts the report uses:
// Field's quality q = 2·r_in/R_circ (1 for an equilateral triangle, 0 for a degenerate one).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace holefill {

struct TriangleMesh {
  Eigen::MatrixX3d vertices;
  Eigen::MatrixX3i triangles;            // counter-clockwise seen from the outside
};

// Throws holefill::Error naming the first offending vertex or triangle: a non-finite
// coordinate, an index out of range, or a triangle repeating a vertex. `what` names the
// input in the message ("mesh", a file name).
void validateMesh(const TriangleMesh& mesh, const std::string& what = "mesh");

// Field's quality 2·r_in/R_circ = 4·(s−a)(s−b)(s−c)/(abc) with s the half perimeter.
double triangleQuality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Angle in [0, π] between two vectors; atan2 keeps full accuracy near 0 and π where acos of
// the dot product does not. 0 when either vector is zero.
double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// Largest inner angle (radians) of a triangle; π for a degenerate one.
double maxInnerAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Area-weighted vertex normals (unit; zero for a vertex without non-degenerate triangles).
Eigen::MatrixX3d vertexNormals(const TriangleMesh& mesh);

// Per vertex, the smallest index of its cluster of vertices joined by pairs within `tol` (itself
// when it has no copy): the map that welds coincident copies. Only `candidates` are compared (all when empty).
std::vector<int> weldMap(const Eigen::MatrixX3d& vertices, double tol, const std::vector<int>& candidates = {});

// Number of edges with exactly one triangle once coincident vertices are welded by `weld`
// (an empty weld map: as indexed).
int countBoundaryEdges(const TriangleMesh& mesh, const std::vector<int>& weld = {});

// Length of the bounding-box diagonal of the vertices (0 for an empty mesh).
double boundingDiagonal(const Eigen::MatrixX3d& vertices);

}  // namespace holefill
