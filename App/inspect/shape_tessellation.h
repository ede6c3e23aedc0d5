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
  Eigen::Index maxVertices = 4000000;    // refinement stops (with a warning) before exceeding this
  std::vector<int> faces;                // 1-based faces to tessellate; empty = all faces
  int threads = 0;                       // 0 = all hardware threads
};

struct TessellationResult {
  InspectionMesh mesh;
  double maxInteriorNormalAngle = 0;     // measured over edges inside faces (the refined ones)
  double maxBoundaryNormalAngle = 0;     // measured over edges on face boundaries
  int passes = 0, faces = 0;
  std::vector<std::string> warnings;
  double seconds = 0;
};

// Throws holefill::Error for a null shape, a shape without faces or a face index out of range.
TessellationResult tessellateForInspection(const TopoDS_Shape& shape, const TessellationOptions& options = {});

}  // namespace holefill
