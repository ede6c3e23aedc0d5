#include "fitting/boundary_embedding.h"

#include <algorithm>

#include "geometry/polygon2d.h"

namespace holefill {

std::vector<int> boundaryCrossingVertices(const MeshHoleReport& boundary, const Eigen::MatrixX2d& uv, size_t limit) {
  std::vector<Polygon2> loops;
  for (const MeshHole& h : boundary.holes) {
    loops.emplace_back();
    for (int v : h.loop) loops.back().push_back(uv.row(v).transpose());
  }
  std::vector<int> out;
  for (const auto& [e, f] : crossingEdges(loops, limit))
    for (const LoopEdge& x : {e, f}) {
      const std::vector<int>& loop = boundary.holes[x.loop].loop;
      out.push_back(loop[x.edge]);
      out.push_back(loop[(x.edge + 1) % loop.size()]);
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace holefill
