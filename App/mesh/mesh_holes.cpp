#include "mesh/mesh_holes.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <queue>
#include <unordered_map>

#include "geometry/json_writer.h"
#include "mesh/mesh_topology.h"

namespace holefill {

namespace {

struct BoundaryHalfedge {
  int from, to, triangle;
  bool used = false;
};

// The outgoing boundary halfedge at v that closes the fan the tracer entered through
// `triangle` (which holds from→v): rotate around v across manifold edges, and across seams (a
// boundary halfedge paired with one running the other way between copies: `partner`, -1 for
// none) onto the copy of v on the other side, until a boundary edge that is no seam is met.
// Returns -1 when the fan crosses a non-manifold edge or does not end.
int nextOnFan(const MeshTopology& topo, int triangle, int v, const std::vector<std::vector<int>>& outgoing,
              const std::vector<BoundaryHalfedge>& halfedges, const std::vector<int>& partner) {
  int t = triangle;
  for (int guard = 0; guard < 4096; ++guard) {
    const int w = topo.nextVertex(t, v);
    const MeshTopology::Edge& e = topo.edge(v, w);
    if (e.count == 1) {
      int g = -1;
      for (int h : outgoing[v])
        if (halfedges[h].to == w && halfedges[h].triangle == t) g = h;
      if (g < 0) return -1;
      if (partner[g] < 0) return g;
      t = halfedges[partner[g]].triangle;  // across the seam: on around the copy of v there
      v = halfedges[partner[g]].to;
      continue;
    }
    if (e.count != 2) return -1;
    t = topo.triangle(e, 0) == t ? topo.triangle(e, 1) : topo.triangle(e, 0);
  }
  return -1;
}

// Cuts a traced loop (a closed sequence of halfedges) into simple loops wherever it meets
// itself: at the same vertex, or at a coincident copy of it (same `site`). Each piece stays
// a closed halfedge sequence, because the cut halfedge ends where the piece starts.
std::vector<std::vector<int>> splitAtRepeats(const std::vector<int>& loop, const std::vector<BoundaryHalfedge>& halfedges,
                                             const std::vector<int>& site, int& duplicateSplits) {
  std::vector<std::vector<int>> pieces;
  std::vector<int> stack;
  std::unordered_map<int, int> position;
  for (int h : loop) {
    const int key = site[halfedges[h].from];
    auto it = position.find(key);
    if (it == position.end()) {
      position[key] = static_cast<int>(stack.size());
      stack.push_back(h);
      continue;
    }
    const int i = it->second;
    if (halfedges[stack[i]].from != halfedges[h].from) ++duplicateSplits;
    pieces.emplace_back(stack.begin() + i, stack.end());
    for (size_t k = i; k < stack.size(); ++k) position.erase(site[halfedges[stack[k]].from]);
    stack.resize(i);
    // The remaining loop continues from this halfedge: it starts at the copy that leads on.
    position[key] = static_cast<int>(stack.size());
    stack.push_back(h);
  }
  pieces.push_back(stack);
  return pieces;
}

}  // namespace

MeshHoleReport findMeshHoles(const TriangleMesh& mesh, double coincidence) {
  validateMesh(mesh);
  return findMeshHoles(mesh, MeshTopology(mesh), coincidence);
}

MeshHoleReport findMeshHoles(const TriangleMesh& mesh, const MeshTopology& topo, double coincidence) {
  MeshHoleReport report;
  report.nonManifoldEdges = topo.nonManifoldEdges;
  report.inconsistentEdges = topo.inconsistentEdges;
  report.components = topo.components;
  report.unusedVertices = topo.unusedVertices;
  if (topo.nonOrientableComponents > 0)
    report.warnings.push_back(std::to_string(topo.nonOrientableComponents) +
                              " component(s) cannot be oriented consistently; their holes are left unfilled");
  if (report.inconsistentEdges > 0)
    report.warnings.push_back(std::to_string(report.inconsistentEdges) +
                              " edge(s) join triangles of opposite orientation; holes are read as if the minority were flipped");
  if (report.nonManifoldEdges > 0)
    report.warnings.push_back(std::to_string(report.nonManifoldEdges) +
                              " non-manifold edge(s) (three or more triangles); holes touching them are left unfilled");
  if (report.components > 1)
    report.warnings.push_back("the mesh has " + std::to_string(report.components) +
                              " components; each is filled on its own (an island inside a hole is not joined to it)");

  // Boundary halfedges in the (possibly flipped) orientation the tracer reads.
  std::vector<BoundaryHalfedge> halfedges;
  std::vector<std::vector<int>> outgoing(mesh.vertices.rows());
  for (const MeshTopology::Edge& e : topo.edges()) {
    if (e.count != 1) continue;
    const int t = topo.triangle(e, 0);
    const int a = e.a, b = e.b;
    const int from = topo.nextVertex(t, a) == b ? a : b;
    const int to = from == a ? b : a;
    outgoing[from].push_back(static_cast<int>(halfedges.size()));
    halfedges.push_back({from, to, t});
  }
  report.boundaryEdges = static_cast<int>(halfedges.size());
  std::vector<bool> nearNonManifold(mesh.vertices.rows(), false);
  for (const MeshTopology::Edge& e : topo.edges())
    if (e.count > 2) nearNonManifold[e.a] = nearNonManifold[e.b] = true;
  std::vector<int> boundaryVertices;
  for (size_t v = 0; v < outgoing.size(); ++v) {
    if (outgoing[v].size() > 1) ++report.singularVertices;
    if (!outgoing[v].empty()) boundaryVertices.push_back(static_cast<int>(v));
  }
  const std::vector<int> site = weldMap(mesh.vertices, coincidence * boundingDiagonal(mesh.vertices), boundaryVertices);

  // A seam: two boundary halfedges between the same two positions, running opposite ways (the
  // two sides of an exporter's seam of duplicated vertices, or a zero-width crack). The surface is
  // closed there geometrically, and filling either side capped the whole mesh across (the
  // corpus's seam class: fills 0.19 of the diagonal off, crossing the surface). Such pairs are
  // taken out of the boundary; a hole that runs into the seam continues from a copy of the vertex
  // it reached (below), so that it is traced as the one hole it is.
  std::vector<int> partner(halfedges.size(), -1);
  {
    std::unordered_map<std::uint64_t, std::vector<int>> bySites;
    const auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
    for (size_t h = 0; h < halfedges.size(); ++h) bySites[key(site[halfedges[h].from], site[halfedges[h].to])].push_back(static_cast<int>(h));
    for (size_t h = 0; h < halfedges.size(); ++h) {
      if (halfedges[h].used || site[halfedges[h].from] == site[halfedges[h].to]) continue;
      auto it = bySites.find(key(site[halfedges[h].to], site[halfedges[h].from]));
      if (it == bySites.end()) continue;
      for (int g : it->second)
        if (!halfedges[g].used) {
          halfedges[h].used = halfedges[g].used = true;
          partner[h] = g;
          partner[g] = static_cast<int>(h);
          report.seamEdges += 2;
          break;
        }
    }
  }
  // Where a traced hole reaches a vertex whose own boundary goes on along a seam, it goes on around
  // the fan across the seam (nextOnFan), from the copy of the vertex on the other side.
  std::vector<int> outgoingFree(outgoing.size(), 0);
  for (size_t v = 0; v < outgoing.size(); ++v)
    for (int h : outgoing[v]) outgoingFree[v] += halfedges[h].used ? 0 : 1;

  for (size_t h0 = 0; h0 < halfedges.size(); ++h0) {
    if (halfedges[h0].used) continue;
    std::vector<int> loop;
    std::string problem;
    bool singular = false, acrossSeam = false;
    int h = static_cast<int>(h0);
    for (size_t guard = 0;; ++guard) {
      if (guard > halfedges.size()) { problem = "the boundary does not close"; break; }
      halfedges[h].used = true;
      loop.push_back(h);
      const int v = halfedges[h].to;
      int next = -1;
      if (outgoing[v].size() == 1 && partner[outgoing[v][0]] < 0) {
        next = outgoing[v][0];
      } else if (outgoing[v].empty()) {
        problem = "the boundary stops at vertex " + std::to_string(v);
        break;
      } else {
        singular = singular || outgoingFree[v] > 1;
        next = nextOnFan(topo, halfedges[h].triangle, v, outgoing, halfedges, partner);
        if (next < 0) {
          problem = "the boundary passes " + std::string(outgoingFree[v] > 1 ? "singular " : "") + "vertex " + std::to_string(v) +
                    " next to a non-manifold edge";
          break;
        }
        acrossSeam = acrossSeam || halfedges[next].from != v;
      }
      if (next == static_cast<int>(h0)) break;
      if (halfedges[next].used) { problem = "the boundary runs into another loop at vertex " + std::to_string(v); break; }
      h = next;
    }
    const bool anticlockwise = !topo.flipped[halfedges[h0].triangle];
    const bool orientable = topo.orientable[topo.component[halfedges[h0].triangle]];
    const int splitsBefore = report.duplicateSplits;
    const auto pieces = problem.empty() ? splitAtRepeats(loop, halfedges, site, report.duplicateSplits)
                                        : std::vector<std::vector<int>>{loop};
    const bool atCopies = report.duplicateSplits > splitsBefore;
    for (const auto& piece : pieces) {
      MeshHole hole;
      for (int e : piece) {
        hole.loop.push_back(halfedges[e].from);
        hole.edgeTriangles.push_back(halfedges[e].triangle);
        hole.edgeEnds.push_back(halfedges[e].to);
        hole.length += (mesh.vertices.row(halfedges[e].from) - mesh.vertices.row(halfedges[e].to)).norm();
      }
      hole.anticlockwise = anticlockwise;
      const bool touchesNonManifold =
          std::any_of(hole.loop.begin(), hole.loop.end(), [&](int v) { return nearNonManifold[v]; });
      if (!problem.empty()) {
        hole.fillable = false;
        hole.message = "not filled: " + problem;
      } else if (!orientable) {
        hole.fillable = false;
        hole.message = "not filled: its component cannot be oriented consistently (Moebius-like)";
      } else if (touchesNonManifold) {
        hole.fillable = false;
        hole.message = "not filled: it touches a non-manifold edge";
      } else if (piece.size() < 3) {
        hole.fillable = false;
        hole.message = "not filled: a slit of " + std::to_string(piece.size()) + " vertices encloses no area";
      } else {
        if (pieces.size() > 1 && atCopies) hole.message = "split where the loop passes two coincident (duplicated) vertices";
        else if (pieces.size() > 1) hole.message = "split at a singular vertex shared with another loop";
        else if (singular) hole.message = "passes a singular vertex";
        if (acrossSeam) hole.message += std::string(hole.message.empty() ? "" : "; ") + "runs across a seam of duplicated vertices";
        if (!anticlockwise) hole.message += std::string(hole.message.empty() ? "" : "; ") + "its triangles are oriented against their component";
      }
      report.holes.push_back(std::move(hole));
    }
  }
  if (report.seamEdges > 0)
    report.warnings.push_back(std::to_string(report.seamEdges) + " boundary edges lie along seams (pairs running opposite ways between "
                              "duplicated vertices): closed geometrically, they are no holes and are left as they are; weld the "
                              "copies (--weld) for an index-closed mesh");
  if (report.duplicateSplits > 0)
    report.warnings.push_back(std::to_string(report.duplicateSplits) +
                              " loop(s) pass duplicated vertices (coincident copies, as along export seams); they are filled "
                              "as split loops, closed geometrically; weld the copies for an index-closed mesh");
  std::stable_sort(report.holes.begin(), report.holes.end(),
                   [](const MeshHole& a, const MeshHole& b) { return a.length > b.length; });
  return report;
}

std::string toJson(const MeshHoleReport& d) {
  JsonWriter w;
  w.beginObject().key("holes").beginArray();
  for (size_t i = 0; i < d.holes.size(); ++i) {
    const MeshHole& h = d.holes[i];
    w.beginObject().field("hole", static_cast<int>(i)).field("boundary_vertices", static_cast<int>(h.loop.size()));
    w.field("length", h.length).field("fillable", h.fillable).field("anticlockwise", h.anticlockwise);
    w.field("message", h.message).field("loop", h.loop);
    w.endObject();
  }
  w.endArray();
  w.field("boundary_edges", d.boundaryEdges).field("non_manifold_edges", d.nonManifoldEdges);
  w.field("inconsistent_edges", d.inconsistentEdges).field("singular_vertices", d.singularVertices);
  w.field("components", d.components).field("duplicate_vertex_splits", d.duplicateSplits).field("seam_edges", d.seamEdges);
  w.field("warnings", d.warnings);
  w.endObject();
  return w.str();
}

}  // namespace holefill
