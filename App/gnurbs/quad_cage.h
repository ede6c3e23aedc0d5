// The quad control mesh ("cage") a G-NURBS surface is built over (g2-gnurbs.md sec. 2): vertices,
// quads, a knot interval per edge (non-uniform; 1 where none is given), sharp edges (C0
// creases) and anchors at sharp extraordinary points (sec. 5.1, V_EP = A_EP). CageTopology
// holds what the construction asks of the cage: the face across each quad edge, the faces and
// spokes around each vertex in rotational order, valences and extraordinary points. A cage
// that is not a consistently oriented 2-manifold of quads is refused with the offending
// element named.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "geometry/edge_key.h"

namespace holefill {

struct QuadCage {
  Eigen::MatrixX3d vertices;
  Eigen::MatrixX4i quads;                        // corners in order around the face, all quads alike
  std::map<std::uint64_t, double> knots;         // edgeKey → knot interval (> 0); absent = 1
  std::set<std::uint64_t> sharp;                 // edgeKey of C0 crease edges
  std::map<int, Eigen::Vector3d> anchors;        // sharp EP vertex → its anchor A_EP
  // Messages name vertices and quads from this base: 0 for arrays (Python), 1 for cages read
  // from OBJ files, so a user finds the element where the error says it is.
  int numberBase = 0;

  static std::uint64_t edgeKey(int a, int b) { return undirectedEdgeKey(a, b); }
  double knot(int a, int b) const;
  bool isSharp(int a, int b) const { return sharp.count(edgeKey(a, b)) > 0; }
  void setKnot(int a, int b, double d) { knots[edgeKey(a, b)] = d; }
  void setSharp(int a, int b) { sharp.insert(edgeKey(a, b)); }
  std::string vertexName(int v) const { return "vertex " + std::to_string(v + numberBase); }
  std::string quadName(int f) const { return "quad " + std::to_string(f + numberBase); }
  std::string edgeName(std::uint64_t key) const {
    return "edge " + std::to_string((key & 0xffffffffu) + numberBase) + "-" + std::to_string((key >> 32) + numberBase);
  }
  std::string edgeName(int a, int b) const { return "edge " + std::to_string(a + numberBase) + "-" + std::to_string(b + numberBase); }
};

class CageTopology {
public:
  // Validates the cage (finite coordinates, indices in range, every vertex used, no repeated corner, every
  // directed edge in one quad only, knot intervals positive and on cage edges, sharp edges and
  // anchors on the cage) and builds the adjacency.
  explicit CageTopology(const QuadCage& cage);

  int faceCount() const { return static_cast<int>(across_.size() / 4); }
  int vertexCount() const { return static_cast<int>(around_.size()); }
  // The face across edge (k, k+1) of face f and that edge's local index there; -1 on the boundary.
  int acrossFace(int f, int k) const { return across_[4 * f + k] >= 0 ? across_[4 * f + k] / 4 : -1; }
  int acrossEdge(int f, int k) const { return across_[4 * f + k] >= 0 ? across_[4 * f + k] % 4 : -1; }

  // Faces around v as (face, corner) pairs in rotational order: face i lies between spokes i
  // and i+1, spoke i being the edge from v to spokes(v)[i]. On a boundary vertex the fan runs
  // from one boundary edge to the other and there is one spoke more than faces.
  struct Corner { int face, corner; };
  const std::vector<Corner>& facesAround(int v) const { return around_[v]; }
  const std::vector<int>& spokes(int v) const { return spokes_[v]; }
  bool onBoundary(int v) const { return boundary_[v]; }
  int valence(int v) const { return static_cast<int>(spokes_[v].size()); }
  // An interior vertex whose valence is not 4 (the G² construction's EP).
  bool isExtraordinary(int v) const { return !boundary_[v] && !spokes_[v].empty() && valence(v) != 4; }
  std::vector<int> extraordinaryPoints() const;

private:
  std::vector<int> across_;                 // 4 per face: 4*face+edge across, or -1
  std::vector<std::vector<Corner>> around_;
  std::vector<std::vector<int>> spokes_;
  std::vector<bool> boundary_;
};

}  // namespace holefill
