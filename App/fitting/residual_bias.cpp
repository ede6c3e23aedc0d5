#include "fitting/residual_bias.h"

#include <cmath>
#include <vector>

#include "geometry/error.h"

namespace holefill {

NeighbourhoodMeans neighbourhoodMeans(const TriangleMesh& mesh, const Eigen::VectorXd& residual, int window) {
  const int n = static_cast<int>(mesh.vertices.rows());
  if (residual.size() != n) throw Error("the residual has " + std::to_string(residual.size()) + " values for " + std::to_string(n) + " vertices");
  if (window < 1) throw Error("the neighbourhood must hold at least one vertex");
  // Vertex adjacency as compressed rows; an edge is listed from both triangles on it, and the
  // duplicates are harmless to the ring walk below, which marks what it has seen.
  std::vector<int> start(n + 1, 0), next;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) start[mesh.triangles(t, k) + 1] += 2;
  for (int v = 0; v < n; ++v) start[v + 1] += start[v];
  next.resize(start[n]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k);
      next[fill[a]++] = mesh.triangles(t, (k + 1) % 3);
      next[fill[a]++] = mesh.triangles(t, (k + 2) % 3);
    }
  NeighbourhoodMeans out{Eigen::VectorXd(n), Eigen::VectorXi(n)};
  std::vector<int> seenBy(n, -1), ring, grown;
  for (int v = 0; v < n; ++v) {
    double sum = residual(v);
    int count = 1;
    seenBy[v] = v;
    ring.assign(1, v);
    while (count < window && !ring.empty()) {
      grown.clear();
      for (const int a : ring)
        for (int e = start[a]; e < start[a + 1]; ++e)
          if (seenBy[next[e]] != v) {
            seenBy[next[e]] = v;
            grown.push_back(next[e]);
            sum += residual(next[e]);
            ++count;
          }
      ring.swap(grown);
    }
    out.mean(v) = sum / count;
    out.count(v) = count;
  }
  return out;
}

ResidualBias residualBias(const TriangleMesh& mesh, const Eigen::VectorXd& residual, int window) {
  const Eigen::VectorXd mean = neighbourhoodMeans(mesh, residual, window).mean.cwiseAbs();
  ResidualBias bias;
  if (mean.size() > 0) {
    Eigen::Index at = 0;
    bias.max = mean.maxCoeff(&at);
    bias.at = static_cast<int>(at);
  }
  return bias;
}

}  // namespace holefill
