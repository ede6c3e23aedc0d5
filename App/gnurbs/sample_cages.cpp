#include "gnurbs/sample_cages.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "geometry/error.h"

namespace holefill::cages {

double height(double x, double y) { return 0.25 * std::sin(0.8 * x + 0.3) * std::cos(0.6 * y) + 0.04 * x * y; }

QuadCage polarCage(int n, int k, const std::function<double(int, int)>& interval) {
  QuadCage c;
  c.vertices.resize(1 + n * k + n * k * k, 3);
  auto along = [&](int spoke, int a) {
    double t = 0;
    for (int j = 0; j < a; ++j) t += interval(spoke % n, j);
    return t;
  };
  auto pos = [&](int i, int a, int b) {
    const double ai = 2 * M_PI * i / n, aj = 2 * M_PI * (i + 1) / n, ta = along(i, a), tb = along(i + 1, b);
    const double x = ta * std::cos(ai) + tb * std::cos(aj), y = ta * std::sin(ai) + tb * std::sin(aj);
    return Eigen::RowVector3d(x, y, height(x, y));
  };
  auto id = [&](int i, int a, int b) {
    i %= n;
    if (a == 0 && b == 0) return 0;
    if (b == 0) return 1 + i * k + (a - 1);
    if (a == 0) return 1 + ((i + 1) % n) * k + (b - 1);
    return 1 + n * k + i * k * k + (a - 1) * k + (b - 1);
  };
  for (int i = 0; i < n; ++i)
    for (int a = 0; a <= k; ++a)
      for (int b = 0; b <= k; ++b) c.vertices.row(id(i, a, b)) = pos(i, a, b);
  c.quads.resize(n * k * k, 4);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) {
        c.quads.row((i * k + a) * k + b) << id(i, a, b), id(i, a + 1, b), id(i, a + 1, b + 1), id(i, a, b + 1);
        c.setKnot(id(i, a, b), id(i, a + 1, b), interval(i, a));
        c.setKnot(id(i, a, b), id(i, a, b + 1), interval((i + 1) % n, b));
      }
  for (int i = 0; i < n; ++i)  // the outer boundary edges
    for (int a = 0; a < k; ++a) {
      c.setKnot(id(i, a, k), id(i, a + 1, k), interval(i, a));
      c.setKnot(id(i, k, a), id(i, k, a + 1), interval((i + 1) % n, a));
    }
  return c;
}

QuadCage edgeStarCage(int nA, int nB, int rings) {
  std::vector<Eigen::Vector4i> quads;
  int next = 2;
  std::vector<int> a(nA), b(nB);  // spokes a[1..nA-1] of vertex 0, b[1..nB-1] of vertex 1
  for (int j = 1; j < nA; ++j) a[j] = next++;
  std::vector<int> c(nA);  // corners of vertex 0's faces between a[j] and a[j+1]
  for (int j = 1; j + 1 < nA; ++j) c[j] = next++;
  b[1] = next++;
  for (int k = 2; k + 1 < nB; ++k) b[k] = next++;
  b[nB - 1] = next++;
  std::vector<int> d(nB);
  for (int k = 1; k + 1 < nB; ++k) d[k] = next++;
  quads.push_back({0, 1, b[nB - 1], a[1]});       // the face north of the edge
  quads.push_back({0, a[nA - 1], b[1], 1});       // the face south of it
  for (int j = 1; j + 1 < nA; ++j) quads.push_back({0, a[j], c[j], a[j + 1]});
  for (int k = 1; k + 1 < nB; ++k) quads.push_back({1, b[k], d[k], b[k + 1]});
  struct PolyVertex {
    int v, inside;  // vertex, quads it lies in so far
  };
  std::vector<PolyVertex> poly;  // counter-clockwise
  for (int j = 1; j < nA; ++j) {
    poly.push_back({a[j], 2});
    if (j + 1 < nA) poly.push_back({c[j], 1});
  }
  for (int k = 1; k < nB; ++k) {
    poly.push_back({b[k], 2});
    if (k + 1 < nB) poly.push_back({d[k], 1});
  }
  for (int r = 0; r < rings; ++r) {
    const int m = static_cast<int>(poly.size());
    std::vector<int> outPrev(m), outNext(m);
    std::vector<PolyVertex> grown;
    for (int i = 0; i < m; ++i) {
      if (poly[i].inside == 2) {
        outPrev[i] = outNext[i] = next++;
        grown.push_back({outPrev[i], 2});
      } else {
        outPrev[i] = next++;
        const int diag = next++;
        outNext[i] = next++;
        quads.push_back({poly[i].v, outPrev[i], diag, outNext[i]});
        grown.push_back({outPrev[i], 2});
        grown.push_back({diag, 1});
        grown.push_back({outNext[i], 2});
      }
    }
    for (int i = 0; i < m; ++i) {
      const int j = (i + 1) % m;
      quads.push_back({poly[j].v, poly[i].v, outNext[i], outPrev[j]});
    }
    poly = grown;
  }
  // Tutte: boundary on a circle, every interior vertex the mean of its neighbours.
  const int nv = next, m = static_cast<int>(poly.size());
  std::vector<std::vector<int>> nbr(nv);
  for (const auto& q : quads)
    for (int k = 0; k < 4; ++k) {
      const int u = q[k], w = q[(k + 1) % 4];
      if (std::find(nbr[u].begin(), nbr[u].end(), w) == nbr[u].end()) nbr[u].push_back(w);
      if (std::find(nbr[w].begin(), nbr[w].end(), u) == nbr[w].end()) nbr[w].push_back(u);
    }
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(nv, nv), rhs = Eigen::MatrixXd::Zero(nv, 2);
  std::vector<bool> onRim(nv, false);
  const double radius = rings + 1.5;
  for (int i = 0; i < m; ++i) {
    const int v = poly[i].v;
    onRim[v] = true;
    L(v, v) = 1;
    rhs.row(v) << radius * std::cos(2 * M_PI * i / m), radius * std::sin(2 * M_PI * i / m);
  }
  for (int v = 0; v < nv; ++v) {
    if (onRim[v]) continue;
    L(v, v) = static_cast<double>(nbr[v].size());
    for (int w : nbr[v]) L(v, w) = -1;
  }
  const Eigen::MatrixXd xy = L.partialPivLu().solve(rhs);
  QuadCage cage;
  cage.vertices.resize(nv, 3);
  for (int v = 0; v < nv; ++v) cage.vertices.row(v) << xy(v, 0), xy(v, 1), height(xy(v, 0), xy(v, 1));
  cage.quads.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (size_t f = 0; f < quads.size(); ++f) cage.quads.row(static_cast<Eigen::Index>(f)) = quads[f].transpose();
  return cage;
}

QuadCage cubeCage() {
  QuadCage c;
  c.vertices.resize(8, 3);
  for (int v = 0; v < 8; ++v) c.vertices.row(v) << (v & 1 ? 1 : -1), (v & 2 ? 1 : -1), (v & 4 ? 1 : -1);
  c.quads.resize(6, 4);
  c.quads << 0, 2, 3, 1,  //
      4, 5, 7, 6,         //
      0, 1, 5, 4,         //
      2, 6, 7, 3,         //
      0, 4, 6, 2,         //
      1, 3, 7, 5;
  return c;
}

void setSharpSpokeLine(QuadCage& polar, int k, int spoke) {
  int prev = 0;
  for (int a = 1; a <= k; ++a) {
    const int v = 1 + spoke * k + (a - 1);  // polarCage's numbering of spoke vertices
    polar.setSharp(prev, v);
    prev = v;
  }
}

std::vector<std::string> sampleCageNames() { return {"cage_valence3", "cage_valence5", "cage_valence8", "cage_adjacent_3_5", "cage_cube"}; }

QuadCage sampleCage(const std::string& name) {
  if (name == "cage_valence3") return polarCage(3, 3);
  if (name == "cage_valence5") return polarCage(5, 3);
  if (name == "cage_valence8") return polarCage(8, 3);
  if (name == "cage_adjacent_3_5") return edgeStarCage(3, 5, 3);
  if (name == "cage_cube") return cubeCage();
  throw Error("no sample cage named '" + name + "'");
}

}  // namespace holefill::cages
