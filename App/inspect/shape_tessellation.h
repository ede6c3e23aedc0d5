// Adaptive tessellation of a B-rep shape for inspection: OCCT's BRepMesh gives a first
// mesh per face, then every mesh edge whose exact end normals differ by more than a bound is
// split at its parameter midpoint (conforming 1-2-3-4 splits, repeated), so zebra stripes
// and curvature colours are smooth however the surface bends. Pieces of B-rep edges are
// split at their edge-parameter midpoint in every face that holds them, so neighbouring faces
// stay crack-free. Vertices carry the exact surface fields (surface_fields.h), never mesh
// estimates. The input shape is not modified.
#pragma once

#include <Eigen/Dense>
#include <TopoDS_Shape.hxx>
#include <functional>
#include <string>
#include <vector>

#include "inspect/surface_fields.h"

namespace holefill {

struct InspectionMesh {
  SurfaceFields fields;                  // one row per vertex (at singular points: the mesh normal)
  Eigen::MatrixX2d uv;                   // parameters on the vertex's face
  Eigen::MatrixX3i triangles;            // counter-clockwise seen from the normal side
  std::vector<int> triangleFace;         // 1-based face index (FreeCAD's Face<k>) per triangle
  std::vector<int> vertexFace;
  // B-rep edges as polylines through mesh vertices, for drawing face boundaries.
  std::vector<Eigen::MatrixX3d> edgePolylines;
  std::vector<int> edgeIndex;            // 1-based Edge<k> per polyline
  double diagonal = 0;                   // bounding-box diagonal of the shape
};

struct TessellationOptions {
  double maxNormalAngle = 0.035;         // rad (2 deg) between exact normals at the ends of a mesh edge
  double relativeDeflection = 5e-4;      // BRepMesh chordal deflection, times the bounding-box diagonal
  int maxPasses = 16;                    // refinement passes after BRepMesh
  // Interactive bounds (issue 22: zebra on a fill gone wrong built 3 million vertices in 73 s with no
  // way out). Refinement stops, with a warning saying what was not reached, before a pass would
  // take the mesh past maxVertices or, at the rate measured so far, past timeLimit seconds; the
  // GUI derives the budget from its view's pixels and the CLI from the image's. What is built by
  // then is a whole, crack-free mesh: only the normal bound is not met everywhere.
  Eigen::Index maxVertices = 1000000;    // about one vertex per 2 pixels of a full-HD view
  double timeLimit = 0;                  // seconds; 0: no limit
  std::vector<int> faces;                // 1-based faces to tessellate; empty = all faces
  int threads = 0;                       // 0 = all hardware threads
  // Called after the first mesh and after each pass with the share of the budget (vertices or
  // time, whichever is nearer) used so far; returning false cancels (tessellateForInspection throws).
  std::function<bool(double)> progress;
};

struct TessellationResult {
  InspectionMesh mesh;
  double maxInteriorNormalAngle = 0;     // measured over edges inside faces (the refined ones)
  double maxBoundaryNormalAngle = 0;     // measured over edges on face boundaries
  int passes = 0, faces = 0;
  bool stoppedByBudget = false;          // maxVertices or timeLimit ended the refinement early
  std::vector<std::string> warnings;
  double seconds = 0;
};

// Throws holefill::Error for a null shape, a shape without faces, a face index out of range, or
// when progress cancels.
TessellationResult tessellateForInspection(const TopoDS_Shape& shape, const TessellationOptions& options = {});

}  // namespace holefill
