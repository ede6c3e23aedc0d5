#include "geometry/bezier_patch.h"

#include <cmath>

#include "geometry/error.h"

namespace holefill {

namespace {

std::vector<double> bezierKnots(int p) {
  std::vector<double> k(2 * (p + 1), 0.0);
  for (int i = p + 1; i < 2 * (p + 1); ++i) k[i] = 1.0;
  return k;
}

// Applies `f` to every row (fixed i, along v) or column (fixed j, along u) of control points.
template <typename F>
Eigen::MatrixX3d mapLines(const Eigen::MatrixX3d& poles, int nu, int nv, bool alongU, int outCount, F f) {
  Eigen::MatrixX3d out(alongU ? outCount * nv : nu * outCount, 3);
  const int lines = alongU ? nv : nu, len = alongU ? nu : nv;
  for (int l = 0; l < lines; ++l) {
    Eigen::MatrixX3d line(len, 3);
    for (int k = 0; k < len; ++k) line.row(k) = poles.row(alongU ? k * nv + l : l * nv + k);
    const Eigen::MatrixX3d mapped = f(line);
    for (int k = 0; k < outCount; ++k) out.row(alongU ? k * nv + l : l * outCount + k) = mapped.row(k);
  }
  return out;
}

Eigen::MatrixX3d elevateCurve(const Eigen::MatrixX3d& c, int to) {
  Eigen::MatrixX3d cur = c;
  for (int p = static_cast<int>(c.rows()) - 1; p < to; ++p) {
    Eigen::MatrixX3d next(p + 2, 3);
    next.row(0) = cur.row(0);
    next.row(p + 1) = cur.row(p);
    for (int i = 1; i <= p; ++i) {
      const double a = static_cast<double>(i) / (p + 1);
      next.row(i) = a * cur.row(i - 1) + (1 - a) * cur.row(i);
    }
    cur = next;
  }
  return cur;
}

// De Casteljau at t: the left and right halves' control points of a curve.
std::pair<Eigen::MatrixX3d, Eigen::MatrixX3d> splitCurve(const Eigen::MatrixX3d& c, double t) {
  const int n = static_cast<int>(c.rows());
  Eigen::MatrixX3d work = c, left(n, 3), right(n, 3);
  for (int r = 0; r < n; ++r) {
    left.row(r) = work.row(0);
    right.row(n - 1 - r) = work.row(n - 1 - r);
    for (int i = 0; i < n - 1 - r; ++i) work.row(i) = (1 - t) * work.row(i) + t * work.row(i + 1);
  }
  return {left, right};
}

}  // namespace

BSplineSurface bezierPatch(int degreeU, int degreeV, const Eigen::MatrixX3d& poles) {
  HF_CHECK(degreeU >= 1 && degreeV >= 1, "a Bézier patch needs degree >= 1 in both directions");
  HF_CHECK(poles.rows() == (degreeU + 1) * (degreeV + 1), "a Bézier patch of degree (p, q) needs (p+1)(q+1) poles");
  BSplineSurface s;
  s.degreeU = degreeU;
  s.degreeV = degreeV;
  s.knotsU = bezierKnots(degreeU);
  s.knotsV = bezierKnots(degreeV);
  s.poles = poles;
  return s;
}

bool isBezierPatch(const BSplineSurface& s) {
  return s.numU() == s.degreeU + 1 && s.numV() == s.degreeV + 1 && s.knotsU.front() == 0 && s.knotsU.back() == 1 &&
         s.knotsV.front() == 0 && s.knotsV.back() == 1;
}

BSplineSurface elevateBezier(const BSplineSurface& patch, int degreeU, int degreeV) {
  HF_CHECK(isBezierPatch(patch), "degree elevation here is for Bézier patches");
  HF_CHECK(degreeU >= patch.degreeU && degreeV >= patch.degreeV, "degree elevation cannot lower a degree");
  const int nu = patch.degreeU + 1, nv = patch.degreeV + 1;
  Eigen::MatrixX3d p = mapLines(patch.poles, nu, nv, true, degreeU + 1, [&](const Eigen::MatrixX3d& c) { return elevateCurve(c, degreeU); });
  p = mapLines(p, degreeU + 1, nv, false, degreeV + 1, [&](const Eigen::MatrixX3d& c) { return elevateCurve(c, degreeV); });
  return bezierPatch(degreeU, degreeV, p);
}

std::array<BSplineSurface, 4> splitBezier(const BSplineSurface& patch, double u, double v) {
  HF_CHECK(isBezierPatch(patch), "de Casteljau splitting here is for Bézier patches");
  HF_CHECK(u > 0 && u < 1 && v > 0 && v < 1, "a Bézier patch is split strictly inside its domain");
  const int nu = patch.degreeU + 1, nv = patch.degreeV + 1;
  std::array<BSplineSurface, 4> out;
  for (int hu = 0; hu < 2; ++hu) {
    const Eigen::MatrixX3d pu = mapLines(patch.poles, nu, nv, true, nu, [&](const Eigen::MatrixX3d& c) {
      const auto halves = splitCurve(c, u);
      return hu ? halves.second : halves.first;
    });
    for (int hv = 0; hv < 2; ++hv) {
      const Eigen::MatrixX3d p = mapLines(pu, nu, nv, false, nv, [&](const Eigen::MatrixX3d& c) {
        const auto halves = splitCurve(c, v);
        return hv ? halves.second : halves.first;
      });
      out[2 * hv + hu] = bezierPatch(patch.degreeU, patch.degreeV, p);
    }
  }
  return out;
}

}  // namespace holefill
