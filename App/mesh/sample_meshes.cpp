#include "mesh/sample_meshes.h"

#include <cmath>
#include <map>
#include <random>
#include <vector>

namespace holefill::samples {

namespace {
TriangleMesh fromLists(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3i>& t) {
  TriangleMesh m;
  m.vertices.resize(static_cast<Eigen::Index>(p.size()), 3);
  for (size_t i = 0; i < p.size(); ++i) m.vertices.row(i) = p[i].transpose();
  m.triangles.resize(static_cast<Eigen::Index>(t.size()), 3);
  for (size_t i = 0; i < t.size(); ++i) m.triangles.row(i) = t[i].transpose();
  return m;
}
}  // namespace

TriangleMesh gridPlane(int nx, int ny, double h) {
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Vector3i> t;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) p.emplace_back(i * h, j * h, 0);
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) { t.emplace_back(a, b, c); t.emplace_back(a, c, d); }
      else { t.emplace_back(a, b, d); t.emplace_back(b, c, d); }
    }
  return fromLists(p, t);
}

TriangleMesh icosphere(int level, double radius) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<Eigen::Vector3i> t = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (auto& q : p) q.normalize();
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back((p[a] + p[b]).normalized());
      return mid[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& f : t) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.emplace_back(f[0], ab, ca);
      next.emplace_back(f[1], bc, ab);
      next.emplace_back(f[2], ca, bc);
      next.emplace_back(ab, bc, ca);
    }
    t.swap(next);
  }
  for (auto& q : p) q *= radius;
  return fromLists(p, t);
}

TriangleMesh tube(int segments, int rings, double radius, double height, double squash) {
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Vector3i> t;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * M_PI * i / segments;
      p.emplace_back(radius * std::cos(a), squash * radius * std::sin(a), height * j / rings);
    }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const int a = j * segments + i, b = j * segments + (i + 1) % segments;
      const int c = b + segments, d = a + segments;
      t.emplace_back(a, b, c);  // outward normals
      t.emplace_back(a, c, d);
    }
  return fromLists(p, t);
}

TriangleMesh scanWithHoles() {
  const TriangleMesh sphere = icosphere(4, 25.0);
  const Eigen::Vector3d a = Eigen::Vector3d(0, 0, 1), b = Eigen::Vector3d(1, 0.3, 0.2).normalized(),
                        c = Eigen::Vector3d(-0.4, -1, -0.3).normalized(), d = Eigen::Vector3d(-0.6, -0.9, -0.1).normalized();
  return cutHole(sphere, [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d u = p.normalized();
    const bool slot = u.dot(c) > 0.96 || u.dot(d) > 0.96 || u.dot((c + d).normalized()) > 0.96;  // elongated
    return u.dot(a) > 0.9 || u.dot(b) > 0.97 || slot;
  }).mesh;
}

Eigen::MatrixX3d scanPatchCloud() {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> U(0, 40);
  std::normal_distribution<double> noise(0, 0.005);
  Eigen::MatrixX3d p(3000, 3);
  for (int k = 0; k < 3000; ++k) {
    const double x = U(rng), y = U(rng), u = x / 40, v = y / 40;
    const double z = 40 * (0.15 * std::sin(2.5 * u) * std::cos(1.8 * v) + 0.06 * std::exp(-40 * ((u - .6) * (u - .6) + (v - .4) * (v - .4))));
    p.row(k) << x + noise(rng), y + noise(rng), z + noise(rng);
  }
  return p;
}

TriangleMesh labeledRegion(std::string* labelsJson) {
  const int nx = 42, ny = 15, cutX = 30, cutY = 10;  // cells; the corner i >= cutX, j >= cutY is cut away
  const double R = 60, r = 25, spanU = 60 * M_PI / 180, spanV = 70 * M_PI / 180;  // cells about 2 × 2
  std::map<std::pair<int, int>, int> id;
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Vector3i> t;
  const auto inside = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny && !(i >= cutX && j >= cutY); };
  const auto vertex = [&](int i, int j) {
    const auto it = id.find({i, j});
    if (it != id.end()) return it->second;
    // Jitter interior grid points by a deterministic pattern (no two rows alike), not boundary ones.
    const bool boundary = !(inside(i - 1, j - 1) && inside(i, j - 1) && inside(i - 1, j) && inside(i, j));
    const double du = boundary ? 0 : 0.15 * std::sin(12.9898 * i + 78.233 * j), dv = boundary ? 0 : 0.15 * std::cos(39.3468 * i + 11.135 * j);
    const double a = (i + du) / nx * spanU - spanU / 2, b = (j + dv) / ny * spanV - spanV / 2;
    p.emplace_back((R + r * std::cos(b)) * std::sin(a), r * std::sin(b), (R + r * std::cos(b)) * std::cos(a) - R - r);
    return id[{i, j}] = static_cast<int>(p.size()) - 1;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (!inside(i, j)) continue;
      const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      if ((i + j) % 2) t.emplace_back(a, b, c), t.emplace_back(a, c, d);
      else t.emplace_back(a, b, d), t.emplace_back(b, c, d);
    }
  if (labelsJson) {
    std::string s = "{\"segments\": [";
    const auto segment = [&](const char* label, std::vector<std::pair<int, int>> ij, bool last) {
      s += std::string("{\"label\": \"") + label + "\", \"vertices\": [";
      for (size_t k = 0; k < ij.size(); ++k) s += (k ? ", " : "") + std::to_string(id.at(ij[k]));
      s += last ? "]}" : "]}, ";
    };
    std::vector<std::pair<int, int>> S, E, N, W;
    for (int i = 0; i <= nx; ++i) S.emplace_back(i, 0);
    for (int j = 0; j <= cutY; ++j) E.emplace_back(nx, j);
    for (int i = cutX; i >= 0; --i) N.emplace_back(i, ny);
    for (int j = ny; j >= 0; --j) W.emplace_back(0, j);
    segment("S", S, false);
    segment("E", E, false);
    segment("N", N, false);
    segment("W", W, true);
    *labelsJson = s + "]}";
  }
  return fromLists(p, t);
}

CutResult cutHole(const TriangleMesh& mesh, const std::function<bool(const Eigen::Vector3d&)>& inside) {
  std::vector<Eigen::Vector3i> kept, removed;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3i f = mesh.triangles.row(t).transpose();
    const Eigen::Vector3d c = (mesh.vertices.row(f[0]) + mesh.vertices.row(f[1]) + mesh.vertices.row(f[2])).transpose() / 3;
    (inside(c) ? removed : kept).push_back(f);
  }
  auto compact = [&](const std::vector<Eigen::Vector3i>& tris) {
    std::vector<int> map(mesh.vertices.rows(), -1);
    std::vector<Eigen::Vector3d> p;
    std::vector<Eigen::Vector3i> t;
    for (const auto& f : tris) {
      Eigen::Vector3i g;
      for (int k = 0; k < 3; ++k) {
        if (map[f[k]] < 0) { map[f[k]] = static_cast<int>(p.size()); p.push_back(mesh.vertices.row(f[k]).transpose()); }
        g[k] = map[f[k]];
      }
      t.push_back(g);
    }
    return fromLists(p, t);
  };
  return {compact(kept), compact(removed)};
}

}  // namespace holefill::samples
