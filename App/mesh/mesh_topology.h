// Edge adjacency of a triangle mesh as the hole pipeline reads it: every undirected edge
// with the triangles on it, edge-connected components, and a consistent orientation per
// component (Hu et al., section II: "a mesh is oriented if all its triangles are consistently
// oriented"). Input meshes often are not; rather than refuse them, the topology records which
// triangles must be read reversed so each orientable component agrees with its majority, and
// every query below (nextVertex) answers in that corrected orientation. The input is untouched.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/triangle_mesh.h"

namespace holefill {

class MeshTopology {
public:
  struct Edge {
    int a, b;                            // a < b
    int first, count;                    // its triangles: triangle(e, 0 .. count−1)
  };

  explicit MeshTopology(const TriangleMesh& mesh);

  // The vertex after v in triangle t, in the corrected orientation.
  int nextVertex(int t, int v) const;
  // Throws holefill::Error when the edge does not exist; hasEdge asks first.
  const Edge& edge(int u, int v) const;
  bool hasEdge(int u, int v) const;
  const std::vector<Edge>& edges() const { return edges_; }
  int triangle(const Edge& e, int k) const { return edgeTriangles_[e.first + k]; }
  static std::uint64_t key(int u, int v) {
    const auto lo = static_cast<std::uint64_t>(std::min(u, v)), hi = static_cast<std::uint64_t>(std::max(u, v));
    return (lo << 32) | hi;  // ordered by the lower vertex first: the order of the bucketed build
  }

  std::vector<bool> flipped;             // per triangle
  std::vector<int> component;            // per triangle
  std::vector<bool> orientable;          // per component
  int components = 0, nonOrientableComponents = 0;
  int nonManifoldEdges = 0, inconsistentEdges = 0, unusedVertices = 0;

private:
  const TriangleMesh& mesh_;
  // Sorted by key; edges_[i] belongs to keys_[i]. Sorting flat arrays instead of hashing
  // per-edge vectors builds a 75k-triangle mesh's topology several times faster.
  std::vector<std::uint64_t> keys_;
  std::vector<Edge> edges_;
  std::vector<int> edgeTriangles_;
};

}  // namespace holefill
