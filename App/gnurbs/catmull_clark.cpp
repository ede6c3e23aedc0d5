#include "gnurbs/catmull_clark.h"

#include <unordered_map>

namespace holefill {

QuadCage catmullClarkStep(const QuadCage& cage, const CageTopology& topo) {
  const int nv = topo.vertexCount(), nf = topo.faceCount();
  std::unordered_map<std::uint64_t, int> edgeIndex;  // edge key → index into edges
  struct Edge {
    int a, b;
    int faces[2] = {-1, -1};
  };
  std::vector<Edge> edges;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k) {
      const int a = cage.quads(f, k), b = cage.quads(f, (k + 1) % 4);
      const auto [it, fresh] = edgeIndex.emplace(QuadCage::edgeKey(a, b), static_cast<int>(edges.size()));
      if (fresh) edges.push_back({a, b});
      edges[it->second].faces[fresh ? 0 : 1] = f;
    }
  const int ne = static_cast<int>(edges.size());
  auto edgeOf = [&](int a, int b) { return edgeIndex.at(QuadCage::edgeKey(a, b)); };
  auto isCrease = [&](const Edge& e) { return e.faces[1] < 0 || cage.isSharp(e.a, e.b); };

  QuadCage out;
  out.vertices.resize(nv + ne + nf, 3);
  for (int f = 0; f < nf; ++f) {
    Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) c += cage.vertices.row(cage.quads(f, k));
    out.vertices.row(nv + ne + f) = c / 4;
  }
  for (int e = 0; e < ne; ++e) {
    const Edge& E = edges[e];
    Eigen::RowVector3d p = cage.vertices.row(E.a) + cage.vertices.row(E.b);
    out.vertices.row(nv + e) = isCrease(E) ? Eigen::RowVector3d(p / 2)
                                           : Eigen::RowVector3d((p + out.vertices.row(nv + ne + E.faces[0]) + out.vertices.row(nv + ne + E.faces[1])) / 4);
  }
  for (int v = 0; v < nv; ++v) {
    const Eigen::RowVector3d V = cage.vertices.row(v);
    std::vector<int> creaseEnds;
    Eigen::RowVector3d midSum = Eigen::RowVector3d::Zero(), faceSum = Eigen::RowVector3d::Zero();
    for (int w : topo.spokes(v)) {
      if (isCrease(edges[edgeOf(v, w)])) creaseEnds.push_back(w);
      midSum += (V + cage.vertices.row(w)) / 2;
    }
    for (const auto& c : topo.facesAround(v)) faceSum += out.vertices.row(nv + ne + c.face);
    const double n = static_cast<double>(topo.valence(v));
    if (creaseEnds.size() == 2)
      out.vertices.row(v) = (6 * V + cage.vertices.row(creaseEnds[0]) + cage.vertices.row(creaseEnds[1])) / 8;
    else if (creaseEnds.size() > 2)
      out.vertices.row(v) = V;
    else  // smooth vertex, or a dart (one crease ends here): the smooth rule
      out.vertices.row(v) = (faceSum / n + 2 * midSum / n + (n - 3) * V) / n;
  }

  out.quads.resize(4 * nf, 4);
  const bool nonUniform = !cage.knots.empty();
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k) {
      const int prev = cage.quads(f, (k + 3) % 4), v = cage.quads(f, k), next = cage.quads(f, (k + 1) % 4);
      const int eNext = nv + edgeOf(v, next), ePrev = nv + edgeOf(prev, v), center = nv + ne + f;
      out.quads.row(4 * f + k) << v, eNext, center, ePrev;
      if (nonUniform) {
        out.setKnot(v, eNext, cage.knot(v, next) / 2);
        out.setKnot(next, eNext, cage.knot(v, next) / 2);
        // eNext → centre runs parallel to the face's edges (next, next+1) and (prev, v).
        out.setKnot(eNext, center, (cage.knot(next, cage.quads(f, (k + 2) % 4)) + cage.knot(prev, v)) / 4);
      }
    }
  for (const Edge& E : edges)
    if (cage.isSharp(E.a, E.b)) {
      out.setSharp(E.a, nv + edgeOf(E.a, E.b));
      out.setSharp(E.b, nv + edgeOf(E.a, E.b));
    }
  out.anchors = cage.anchors;
  out.numberBase = cage.numberBase;
  return out;
}

}  // namespace holefill
