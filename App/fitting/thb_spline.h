// Truncated hierarchical B-splines (THB) over [0, 1]² (bidgcn.md sec. 5, after Giannelli, Jüttler
// & Speleers, "THB-splines: the truncated basis for hierarchical splines", CAGD 29, 2012): level
// ℓ is the clamped uniform tensor-product spline space of the given degree with (cellsU·2^ℓ) ×
// (cellsV·2^ℓ) cells; the nested domains Ω^0 = [0,1]² ⊇ Ω^1 ⊇ … are unions of cells, grown by
// refining cells. The active functions are the level-ℓ B-splines whose support lies in Ω^ℓ but
// not in Ω^{ℓ+1}; each is truncated — written in the finer levels' bases (two-scale relation)
// with the coefficients of functions supported in the finer domain dropped — so the basis is a
// partition of unity with small supports, and spans the hierarchical spline space. Every
// function is kept as its coefficients at the finest level, where it is evaluated.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace holefill {

class ThbSpace {
 public:
  struct Function {
    int level, i, j;                                // the level-ℓ tensor B-spline N_i(u) N_j(v) it truncates
    std::map<std::pair<int, int>, double> finest;   // its coefficients in the finest level's basis
  };

  // Throws Error for a degree below 1 or fewer cells than the degree in a direction.
  ThbSpace(int degree, int cellsU, int cellsV);

  // Refines `cells` (column i, row j) of level `level` (each must lie in Ω^level): their four
  // children join Ω^{level+1}. Rebuilds the basis. Throws Error for a cell outside Ω^level.
  void refine(int level, const std::vector<std::pair<int, int>>& cells);

  int degree() const { return p_; }
  int levels() const { return static_cast<int>(domain_.size()); }
  int cellsU(int level) const { return nu_ << level; }
  int cellsV(int level) const { return nv_ << level; }
  bool inDomain(int level, int i, int j) const;  // cell (i, j) of `level` lies in Ω^level
  const std::vector<Function>& functions() const { return basis_; }
  // The hierarchical mesh: cells of Ω^ℓ \ Ω^{ℓ+1} of every level, as (level, i, j).
  std::vector<std::array<int, 3>> leafCells() const;

  // Values of all active functions at (u, v) in [0, 1]², as (function index, value) pairs.
  std::vector<std::pair<int, double>> evaluate(double u, double v) const;
  // Every active function in the finest level's tensor basis: a (finest functions) × (active
  // functions) matrix, the finest function (a, b) at row a · (cellsV(L) + degree) + b, so that
  // the finest B-spline's control points are this times the active functions' coefficients.
  Eigen::SparseMatrix<double> finestMap() const;
  // The finest-level coefficients of one tensor B-spline of `level`, untruncated (the
  // hierarchical, not truncated, basis function), for comparisons.
  std::map<std::pair<int, int>, double> hierarchical(int level, int i, int j) const;

 private:
  void rebuild();
  bool supportIn(int level, int i, int j, int domainLevel) const;  // level-`level` function's support ⊆ Ω^domainLevel
  std::vector<double> knots(int level, int dir) const;

  int p_, nu_, nv_;
  std::vector<std::vector<char>> domain_;         // per level, cell flags (row-major, cellsU wide)
  std::vector<std::array<Eigen::MatrixXd, 2>> refinement_;  // per level ℓ, 1D matrices: level-ℓ functions in level ℓ+1's basis
  std::vector<Function> basis_;
};

// The space of `degree` over cellsU × cellsV cells with `cells` (level, i, j) refined, level by
// level in the order given (a cell of level ℓ + 1 must lie in a cell refined at ℓ). Throws Error
// as the constructor and refine do.
ThbSpace refinedThbSpace(int degree, int cellsU, int cellsV, std::vector<std::array<int, 3>> cells);

}  // namespace holefill
