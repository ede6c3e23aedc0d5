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

std::vector<char> verticesMissedPastNoise(const TriangleMesh& mesh, const std::vector<MeshHole>& boundary, const Eigen::VectorXd& residual,
                                          double sigma) {
  if (!(sigma > 0)) throw Error("the scan noise must be positive to tell a miss from it");
  const Eigen::VectorXd squared = residual.array().square();
  std::vector<char> missed(static_cast<size_t>(residual.size()), 0);
  const auto limit = [&](int w) {
    const double a = 2.0 / (9.0 * w);
    return sigma * sigma * std::pow(1 - a + 4.4 * std::sqrt(a), 3);
  };
  for (int w : {1, 7, 25}) {
    const NeighbourhoodMeans m = neighbourhoodMeans(mesh, squared, w);
    for (Eigen::Index v = 0; v < squared.size(); ++v)
      if (m.mean(v) > limit(m.count(v))) missed[v] = 1;
  }
  for (const MeshHole& loop : boundary) {
    const int n = static_cast<int>(loop.loop.size());
    for (int w : {3, 5, 9}) {
      if (w > n) break;
      for (int k = 0; k < n; ++k) {
        double sum = 0;
        for (int q = 0; q < w; ++q) sum += squared(loop.loop[(k + q) % n]);
        if (sum / w > limit(w))
          for (int q = 0; q < w; ++q) missed[loop.loop[(k + q) % n]] = 1;
      }
    }
  }
  return missed;
}

}  // namespace holefill
