// The patching mesh of one hole (Hu et al., section II: "the mesh that fills the hole"),
// in its own small index space: the hole's loop vertices come first and never move, new
// vertices follow. Refinement (patch_refinement.h) and fairing (bilateral_fairing.h) work on
// it; the filler maps it back into the surrounding mesh. The edge map answers which patch
// triangles hold an edge: one for a loop edge, two for an interior edge.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "geometry/edge_key.h"

namespace holefill {

struct HolePatch {
  std::vector<Eigen::Vector3d> points;          // [0, boundaryCount) the loop, then new vertices
  int boundaryCount = 0;
  std::vector<std::array<int, 3>> triangles;    // oriented like the surrounding mesh
  std::vector<double> scale;                    // per vertex: the local edge length it should get (σ of the paper)
  // Whether two loop vertices are joined by an edge of the surrounding mesh: the patch must
  // never add such an edge again.
  std::function<bool(int, int)> outsideEdge = [](int, int) { return false; };

  bool isNew(int v) const { return v >= boundaryCount; }
};

// The patch triangles on one edge: one on a loop edge, two on an interior edge, never more
// (the patch is a disk). A fixed pair, not a vector: edits touch these maps millions of times.
struct EdgeTriangles {
  int t[2] = {-1, -1};
  int n = 0;
  size_t size() const { return static_cast<size_t>(n); }
  int operator[](int k) const { return t[k]; }
  const int* begin() const { return t; }
  const int* end() const { return t + n; }
};

// Undirected edge → patch triangles on it, kept up to date by the refinement's edits.
class PatchEdges {
public:
  explicit PatchEdges(const HolePatch& patch);
  static std::uint64_t key(int u, int v) { return undirectedEdgeKey(u, v); }
  void add(const std::array<int, 3>& tri, int t);
  void remove(const std::array<int, 3>& tri, int t);
  const EdgeTriangles* find(int u, int v) const;
  bool has(int u, int v) const { return find(u, v) != nullptr; }

private:
  std::unordered_map<std::uint64_t, EdgeTriangles> map_;
};

// Field's quality of the patch's worst triangle and the mean over its triangles.
double worstQuality(const HolePatch& patch);
double meanQuality(const HolePatch& patch);

// Unit normal of a patch triangle (zero when degenerate), unnormalized cross product in `area2`.
Eigen::Vector3d patchTriangleNormal(const HolePatch& patch, const std::array<int, 3>& tri, double* area2 = nullptr);

}  // namespace holefill
