#include "mesh/mesh_topology.h"

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
  edges_.reserve(static_cast<size_t>(nt) * 2);
  std::vector<bool> used(mesh.vertices.rows(), false);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.triangles(t, k), v = mesh.triangles(t, (k + 1) % 3);
      used[u] = true;
      Edge& e = edges_[key(u, v)];
      e.a = std::min(u, v);
      e.b = std::max(u, v);
      e.triangles.push_back(t);
    }
  for (bool u : used) unusedVertices += u ? 0 : 1;
  for (const auto& [k, e] : edges_) {
    if (e.triangles.size() > 2) ++nonManifoldEdges;
    if (e.triangles.size() == 2 &&
        direction(mesh, e.triangles[0], e.a, e.b) == direction(mesh, e.triangles[1], e.a, e.b))
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
        const Edge& e = edges_.at(key(u, v));
        if (e.triangles.size() != 2) continue;
        const int s = e.triangles[0] == t ? e.triangles[1] : e.triangles[0];
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

const MeshTopology::Edge& MeshTopology::edge(int u, int v) const {
  auto it = edges_.find(key(u, v));
  if (it == edges_.end()) throw Error("internal: no edge " + std::to_string(u) + "-" + std::to_string(v));
  return it->second;
}

}  // namespace holefill
