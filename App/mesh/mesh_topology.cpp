#include "mesh/mesh_topology.h"

#include <algorithm>
#include <queue>

#include "geometry/error.h"

namespace holefill {

namespace {
// +1 when triangle t runs u→v, −1 when it runs v→u.
int direction(const TriangleMesh& mesh, int t, int u, int v) {
  for (int k = 0; k < 3; ++k)
    if (mesh.triangles(t, k) == u) return mesh.triangles(t, (k + 1) % 3) == v ? 1 : -1;
  return 0;
}
}  // namespace

MeshTopology::MeshTopology(const TriangleMesh& mesh) : mesh_(mesh) {
  const int nt = static_cast<int>(mesh.triangles.rows());
  // (edge key, 3·triangle + corner): the corner says which of the triangle's edges it is.
  // Bucketed by the lower vertex (a counting sort), then sorted within each small bucket:
  // linear time where one global sort was the largest cost on scans of 100k triangles.
  const Eigen::Index nv = mesh.vertices.rows();
  std::vector<int> start(nv + 1, 0);
  std::vector<bool> used(nv, false);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      used[mesh.triangles(t, k)] = true;
      ++start[std::min(mesh.triangles(t, k), mesh.triangles(t, (k + 1) % 3)) + 1];
    }
  for (Eigen::Index v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<std::uint64_t, int>> halfedges(static_cast<size_t>(nt) * 3);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.triangles(t, k), v = mesh.triangles(t, (k + 1) % 3);
      halfedges[fill[std::min(u, v)]++] = {key(u, v), 3 * t + k};
    }
  for (Eigen::Index v = 0; v < nv; ++v) std::sort(halfedges.begin() + start[v], halfedges.begin() + start[v + 1]);
  edgeTriangles_.reserve(halfedges.size());
  // Per triangle edge: the triangle across it when the edge is manifold, else −1.
  std::vector<int> across(static_cast<size_t>(nt) * 3, -1);
  for (size_t i = 0; i < halfedges.size();) {
    size_t j = i;
    while (j < halfedges.size() && halfedges[j].first == halfedges[i].first) edgeTriangles_.push_back(halfedges[j++].second / 3);
    if (j - i == 2) {
      across[halfedges[i].second] = halfedges[i + 1].second / 3;
      across[halfedges[i + 1].second] = halfedges[i].second / 3;
    }
    const std::uint64_t k = halfedges[i].first;
    keys_.push_back(k);
    edges_.push_back({static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffffu), static_cast<int>(i), static_cast<int>(j - i)});
    i = j;
  }
  for (bool u : used) unusedVertices += u ? 0 : 1;
  for (const Edge& e : edges_) {
    if (e.count > 2) ++nonManifoldEdges;
    if (e.count == 2 && direction(mesh, triangle(e, 0), e.a, e.b) == direction(mesh, triangle(e, 1), e.a, e.b))
      ++inconsistentEdges;
  }

  // Breadth-first orientation across manifold edges; a component that contradicts itself is
  // not orientable and keeps its input orientation.
  flipped.assign(nt, false);
  component.assign(nt, -1);
  std::vector<int> members;
  for (int seed = 0; seed < nt; ++seed) {
    if (component[seed] >= 0) continue;
    const int c = components++;
    bool ok = true;
    members.clear();
    std::queue<int> queue;
    component[seed] = c;
    queue.push(seed);
    while (!queue.empty()) {
      const int t = queue.front();
      queue.pop();
      members.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const int u = mesh.triangles(t, k), v = mesh.triangles(t, (k + 1) % 3);
        const int s = across[3 * t + k];
        if (s < 0 || s == t) continue;
        // Consistent neighbours traverse the shared edge in opposite directions.
        const bool wantFlip = (direction(mesh, s, u, v) == 1) != flipped[t];
        if (component[s] < 0) {
          component[s] = c;
          flipped[s] = wantFlip;
          queue.push(s);
        } else if (flipped[s] != wantFlip) {
          ok = false;
        }
      }
    }
    orientable.push_back(ok);
    if (!ok) {
      ++nonOrientableComponents;
      for (int t : members) flipped[t] = false;
      continue;
    }
    size_t nFlipped = 0;
    for (int t : members) nFlipped += flipped[t] ? 1 : 0;
    if (2 * nFlipped > members.size())
      for (int t : members) flipped[t] = !flipped[t];
  }
}

int MeshTopology::nextVertex(int t, int v) const {
  for (int k = 0; k < 3; ++k)
    if (mesh_.triangles(t, k) == v) return mesh_.triangles(t, flipped[t] ? (k + 2) % 3 : (k + 1) % 3);
  throw Error("internal: vertex " + std::to_string(v) + " is not in triangle " + std::to_string(t));
}

bool MeshTopology::hasEdge(int u, int v) const { return std::binary_search(keys_.begin(), keys_.end(), key(u, v)); }

const MeshTopology::Edge& MeshTopology::edge(int u, int v) const {
  auto it = std::lower_bound(keys_.begin(), keys_.end(), key(u, v));
  if (it == keys_.end() || *it != key(u, v)) throw Error("internal: no edge " + std::to_string(u) + "-" + std::to_string(v));
  return edges_[it - keys_.begin()];
}

}  // namespace holefill
