// Known meshes for tests, the demo and the benchmark's ground-truth holes: a triangulated
// plane, an icosphere, an open tube, and cutting a hole out of any of them. The removed
// triangles are kept, so a fill can be measured against the surface that was there.
#pragma once

#include <functional>
#include <string>

#include "mesh/triangle_mesh.h"

namespace holefill::samples {

// nx × ny squares of size h in the z = 0 plane, each split along a diagonal that alternates,
// so no vertex has a preferred direction.
TriangleMesh gridPlane(int nx, int ny, double h = 1.0);
// Loop-subdivided icosahedron projected onto the sphere of the given radius (20·4^level triangles).
TriangleMesh icosphere(int level, double radius = 1.0);
// Open cylinder of radius r around z from 0 to height: `segments` around, `rings` rows;
// squash < 1 scales y, for an elliptic cross-section.
TriangleMesh tube(int segments, int rings, double radius, double height, double squash = 1.0);

// The bundled demo mesh (Resources/samples/scan_with_holes.obj): a sphere of radius 25 (a
// level-4 icosphere, 2562 vertices) with three holes of different sizes, one of them elongated.
TriangleMesh scanWithHoles();

// The bundled labeled-fitting demo region: a patch of a torus (radii 60 and 25, 60° × 70°)
// with a rectangular corner cut away (an L), 42 × 15 cells of about 2 × 2, jittered inside so
// the triangles are irregular; `labelsJson` receives its four labeled sides ({"segments": [...]}, 0-based).
TriangleMesh labeledRegion(std::string* labelsJson = nullptr);

// The bundled point-cloud demo: a scan-like cloud of a 40 × 40 bumpy sheet (a low wave and a
// sharp bump), 3000 random points with 0.005 of Gaussian noise, no boundary marked (rows x y z).
Eigen::MatrixX3d scanPatchCloud();

struct CutResult {
  TriangleMesh mesh;                     // what is left, unused vertices removed
  TriangleMesh removed;                  // the cut-out triangles (ground truth)
};
// Removes every triangle whose centroid satisfies `inside`.
CutResult cutHole(const TriangleMesh& mesh, const std::function<bool(const Eigen::Vector3d&)>& inside);

}  // namespace holefill::samples
