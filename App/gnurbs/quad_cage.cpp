#include "gnurbs/quad_cage.h"

#include <cmath>
#include <string>
#include <unordered_map>

#include "geometry/error.h"
#include "geometry/tolerances.h"

namespace holefill {

double QuadCage::knot(int a, int b) const {
  const auto it = knots.find(edgeKey(a, b));
  return it == knots.end() ? 1.0 : it->second;
}

CageTopology::CageTopology(const QuadCage& cage) {
  const int nv = static_cast<int>(cage.vertices.rows()), nf = static_cast<int>(cage.quads.rows());
  if (nf == 0) throw Error("the cage has no quads");
  if (!cage.vertices.allFinite()) throw Error("the cage has a vertex with a non-finite coordinate");
  // The patches' poles are sums of products of the cage's coordinates: past tol::kMaxCoordinate
  // they overflow and OCCT crashes on them. Checked here, where every door's cage passes (the
  // Python door's arrays crashed FreeCAD at 1e300; only the OBJ reader checked before).
  const auto beyond = [](const Eigen::Vector3d& p) { return p.cwiseAbs().maxCoeff() > tol::kMaxCoordinate; };
  const std::string units = " has a coordinate beyond " + std::to_string(static_cast<long long>(tol::kMaxCoordinate)) +
                            " (corrupt, or in the wrong units)";
  for (int v = 0; v < nv; ++v)
    if (beyond(cage.vertices.row(v).transpose())) throw Error(cage.vertexName(v) + units);
  auto name = [&](int f) { return cage.quadName(f); };
  std::unordered_map<std::uint64_t, int> directed;  // (from << 32 | to) → 4*face+edge
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 4; ++k) {
      const int v = cage.quads(f, k);
      if (v < 0 || v >= nv) throw Error(name(f) + " refers to " + cage.vertexName(v) + ", which does not exist");
      for (int m = 0; m < k; ++m)
        if (cage.quads(f, m) == v) throw Error(name(f) + " repeats " + cage.vertexName(v));
    }
    for (int k = 0; k < 4; ++k) {
      const auto from = static_cast<std::uint64_t>(cage.quads(f, k)), to = static_cast<std::uint64_t>(cage.quads(f, (k + 1) % 4));
      if (!directed.emplace((from << 32) | to, 4 * f + k).second)
        throw Error(cage.edgeName(static_cast<int>(from), static_cast<int>(to)) + " is used twice in the same direction (" +
                    name(f) + "): the cage is non-manifold or not consistently oriented");
    }
  }
  across_.assign(4 * nf, -1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k) {
      const auto from = static_cast<std::uint64_t>(cage.quads(f, k)), to = static_cast<std::uint64_t>(cage.quads(f, (k + 1) % 4));
      const auto it = directed.find((to << 32) | from);
      if (it != directed.end()) across_[4 * f + k] = it->second;
    }
  auto isEdge = [&](std::uint64_t key) {
    const auto a = key & 0xffffffffu, b = key >> 32;
    return directed.count((a << 32) | b) > 0 || directed.count((b << 32) | a) > 0;
  };
  for (const auto& [key, d] : cage.knots) {
    if (!isEdge(key)) throw Error("a knot interval is given for " + cage.edgeName(key) + ", which is not a cage edge");
    if (!(d > 0) || !std::isfinite(d)) throw Error("knot intervals must be positive and finite; " + cage.edgeName(key) + " has " + std::to_string(d));
  }
  for (std::uint64_t key : cage.sharp)
    if (!isEdge(key)) throw Error("sharp " + cage.edgeName(key) + " is not a cage edge");

  // Rotation about a vertex: the face across a corner's incoming edge holds the next corner.
  std::vector<Corner> cornerOf(nv, Corner{-1, -1});
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k) cornerOf[cage.quads(f, k)] = {f, k};
  around_.assign(nv, {});
  spokes_.assign(nv, {});
  boundary_.assign(nv, false);
  for (int v = 0; v < nv; ++v) {
    // An unused vertex is most often an index off by one in the file the cage came from.
    if (cornerOf[v].face < 0) throw Error(cage.vertexName(v) + " is used by no quad; remove isolated vertices from the cage");
    // Turn backwards (across the outgoing edge) until the boundary or back at the start.
    Corner start = cornerOf[v];
    for (int steps = 0; steps <= nf; ++steps) {
      const int a = across_[4 * start.face + start.corner];  // across the outgoing edge (v → next)
      if (a < 0) { boundary_[v] = true; break; }
      const Corner prev{a / 4, (a % 4 + 1) % 4};           // that face's corner at v
      if (prev.face == cornerOf[v].face) break;
      start = prev;
    }
    Corner c = start;
    for (int steps = 0; steps <= nf; ++steps) {
      around_[v].push_back(c);
      spokes_[v].push_back(cage.quads(c.face, (c.corner + 1) % 4));
      const int in = (c.corner + 3) % 4;                      // incoming edge (prev → v)
      const int a = across_[4 * c.face + in];
      if (a < 0) { spokes_[v].push_back(cage.quads(c.face, in)); break; }
      c = Corner{a / 4, a % 4};                               // across face's outgoing edge at v
      if (c.face == start.face && c.corner == start.corner) break;
    }
  }
  // Every corner of a vertex must be in its one fan: otherwise two fans meet at the vertex.
  std::vector<size_t> uses(nv, 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k) ++uses[cage.quads(f, k)];
  for (int v = 0; v < nv; ++v)
    if (uses[v] != around_[v].size()) throw Error(cage.vertexName(v) + " is non-manifold (two fans of quads meet there)");
  for (const auto& [v, a] : cage.anchors) {
    if (v < 0 || v >= nv) throw Error("an anchor is given for " + cage.vertexName(v) + ", which does not exist");
    if (!a.allFinite()) throw Error("the anchor of " + cage.vertexName(v) + " is not finite");
    if (beyond(a)) throw Error("the anchor of " + cage.vertexName(v) + units);
  }
}

std::vector<int> CageTopology::extraordinaryPoints() const {
  std::vector<int> eps;
  for (int v = 0; v < vertexCount(); ++v)
    if (isExtraordinary(v)) eps.push_back(v);
  return eps;
}

}  // namespace holefill
