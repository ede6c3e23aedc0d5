// Measuring a mesh fill from the outside, the same way for every filler (ours, CGAL, FreeCAD):
// given the input mesh and any filler's output, find what was added by position (fillers may
// reorder or weld vertices, so indices cannot be trusted; FreeCAD rounds them to float, so
// positions are matched at float precision), then report the metrics of
// DESIGN.md: holes left, manifoldness and orientation of the result, new triangles crossing each other
// or the surface (exactly, self_intersection.h), Field's quality of the
// new triangles, and the distance of the new surface to a ground truth (the triangles a
// benchmark cut away), normalized by the input's bounding-box diagonal. The new surface is
// sampled at its new vertices and at the centroids of its new triangles, so a filler that
// adds no vertex is measured too.
#pragma once

#include <string>

#include "mesh/triangle_mesh.h"

namespace holefill {

struct FillMetrics {
  int newVertices = 0, newTriangles = 0;
  int boundaryEdgesBefore = 0, boundaryEdgesAfter = 0;  // with coincident vertices welded
  int nonManifoldEdgesAdded = 0;         // edges of 3+ triangles in the output, beyond the input's
  int misorientedEdgesAdded = 0;         // edges run twice in one direction, beyond the input's
  int degenerateTriangles = 0;           // new triangles of zero area
  int selfIntersections = 0;             // pairs of triangles crossing, at least one new (self_intersection.h)
  double minQuality = 0, meanQuality = 0, goodShare = 0;  // over new triangles; goodShare: q ≥ 0.7
  double rmsDistance = -1, maxDistance = -1;             // to the ground truth / diagonal; −1 without one
  bool keptInput = true;                 // every input triangle is still there (by position)
};

// Distance from each point to the nearest triangle of `mesh` (brute force with box pruning).
Eigen::VectorXd distancesToMesh(const Eigen::MatrixX3d& points, const TriangleMesh& mesh);

// groundTruth may be empty (no distances then).
FillMetrics measureFill(const TriangleMesh& input, const TriangleMesh& output, const TriangleMesh& groundTruth = {});

std::string toJson(const FillMetrics& m);

}  // namespace holefill
