// A non-rational tensor-product B-spline surface with clamped knot vectors, as
// plain data the solvers can fill directly (poles row-major: index i*numV()+j,
// i along u). Evaluation of points and partial derivatives (The NURBS Book
// A3.6), Boehm knot insertion (A5.1 applied per row/column) and conversion to
// and from OCCT's Geom_BSplineSurface.
#pragma once

#include <Eigen/Dense>
#include <Geom_BSplineSurface.hxx>
#include <array>
#include <vector>

namespace holefill {

struct BSplineSurface {
  int degreeU = 3, degreeV = 3;
  std::vector<double> knotsU, knotsV;  // full clamped knot vectors
  Eigen::MatrixX3d poles;              // numU()*numV() rows

  int numU() const { return static_cast<int>(knotsU.size()) - degreeU - 1; }
  int numV() const { return static_cast<int>(knotsV.size()) - degreeV - 1; }
  int index(int i, int j) const { return i * numV() + j; }

  Eigen::Vector3d point(double u, double v) const;
  // d[k][l] = d^{k+l} S / du^k dv^l for k + l <= order (order <= 3).
  std::array<std::array<Eigen::Vector3d, 4>, 4> derivatives(double u, double v, int order) const;
};

// Surface with the knot inserted once in u (dir = 0) or v (dir = 1); the geometry is unchanged.
BSplineSurface insertKnot(const BSplineSurface& s, int dir, double knot);

Handle(Geom_BSplineSurface) toOcct(const BSplineSurface& s);
BSplineSurface fromOcct(const Handle(Geom_BSplineSurface)& s);

}  // namespace holefill
