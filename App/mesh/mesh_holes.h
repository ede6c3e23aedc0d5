// Hole detection on a triangle mesh (Hu et al., section II): a hole is a closed cycle of
// boundary edges (edges of exactly one triangle). Loops are traced in the direction of the
// triangles' own edges, which the paper calls anticlockwise; the filler orients its new
// triangles against that direction so they join the surrounding mesh consistently.
// The paper assumes an oriented manifold with no vertex shared by two holes. Real scans break
// that, so the tracer goes further: at a singular vertex (more than two boundary edges) it
// continues along the fan of the edge it arrived by, and a loop that still meets itself is
// split there into simple loops; triangles that are oriented against their neighbours are
// read through a consistent re-orientation of their component; loops touching a non-manifold
// edge, or in a component that cannot be oriented, are reported and left unfilled. Scans
// and exports often duplicate vertices along seams: two boundary edges between the same two
// positions running opposite ways are the two sides of a seam, closed geometrically, and are no
// hole; a hole that runs into a seam continues from the copy of the vertex where it meets it;
// and a loop that passes the same position twice through two copies of a vertex is split there,
// so the filled surface is closed geometrically (its index-level closure then needs the copies
// welded, which only the user may decide, since the input's triangles stay untouched). Nothing
// here throws for a merely broken mesh: every hole gets a status and a message.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh_topology.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

struct MeshHole {
  std::vector<int> loop;                 // vertex indices, simple (no repeats), traced as described above
  // Per loop edge k (loop[k] → loop[k+1]): the surrounding triangle on it, and the vertex the
  // input edge really ends at: loop[k+1], or a coincident copy of it where the loop was split.
  std::vector<int> edgeTriangles, edgeEnds;
  double length = 0;                     // sum of the loop's edge lengths, model units
  bool anticlockwise = true;             // the paper's orientation of the loop against the input triangles
  bool fillable = true;
  std::string message;                   // why it is not fillable, or what was done to it (split, re-oriented)
};

struct MeshHoleReport {
  std::vector<MeshHole> holes;           // longest first
  int boundaryEdges = 0;
  int nonManifoldEdges = 0;              // edges of three or more triangles
  int inconsistentEdges = 0;             // edges whose two triangles traverse it in the same direction
  int singularVertices = 0;              // vertices with more than two boundary edges
  int components = 0;                    // edge-connected components of triangles
  int unusedVertices = 0;                // vertices of no triangle
  int duplicateSplits = 0;               // loops split where they pass two coincident vertices
  int seamEdges = 0;                     // boundary edges paired along seams (not holes; see findMeshHoles)
  std::vector<std::string> warnings;
};

// The report as JSON (holes longest first with their loops, topology counts, warnings); the
// CLI prints it and the Python module hands it to json.loads.
std::string toJson(const MeshHoleReport& report);

// Validates the mesh (holefill::Error for NaN, bad indices, repeated vertices in a triangle),
// then finds every boundary loop. Vertices closer than coincidence·(bounding-box diagonal)
// count as copies of each other.
MeshHoleReport findMeshHoles(const TriangleMesh& mesh, double coincidence = 1e-9);
// The same on a validated mesh whose topology is already built.
MeshHoleReport findMeshHoles(const TriangleMesh& mesh, const MeshTopology& topology, double coincidence = 1e-9);

}  // namespace holefill
