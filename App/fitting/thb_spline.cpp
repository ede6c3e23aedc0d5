#include "fitting/thb_spline.h"

#include <algorithm>

#include "geometry/bspline_basis.h"
#include "geometry/error.h"

namespace holefill {

ThbSpace::ThbSpace(int degree, int cellsU, int cellsV) : p_(degree), nu_(cellsU), nv_(cellsV) {
  if (degree < 1) throw Error("a THB space needs degree 1 or more");
  if (cellsU < degree || cellsV < degree) throw Error("a THB space needs at least as many cells as its degree in each direction");
  domain_.push_back(std::vector<char>(static_cast<size_t>(nu_) * nv_, 1));
  rebuild();
}

std::vector<double> ThbSpace::knots(int level, int dir) const { return clampedUniformKnots(p_, dir == 0 ? cellsU(level) : cellsV(level), 0, 1); }

std::vector<std::array<int, 3>> ThbSpace::leafCells() const {
  std::vector<std::array<int, 3>> out;
  for (int l = 0; l < levels(); ++l)
    for (int i = 0; i < cellsU(l); ++i)
      for (int j = 0; j < cellsV(l); ++j)
        if (inDomain(l, i, j) && !(l + 1 < levels() && inDomain(l + 1, 2 * i, 2 * j))) out.push_back({l, i, j});
  return out;
}

bool ThbSpace::inDomain(int level, int i, int j) const {
  if (level < 0 || level >= levels() || i < 0 || j < 0 || i >= cellsU(level) || j >= cellsV(level)) return false;
  return domain_[level][static_cast<size_t>(j) * cellsU(level) + i] != 0;
}

bool ThbSpace::supportIn(int level, int i, int j, int domainLevel) const {
  if (domainLevel >= levels()) return false;
  // Function i of a clamped uniform level spans cells i−p … i (within the domain's range); the
  // same region at a finer level spans 2^(d) times as many cells.
  const int scale = 1 << (domainLevel - level);
  const int i0 = std::max(0, i - p_) * scale, i1 = (std::min(cellsU(level) - 1, i) + 1) * scale;
  const int j0 = std::max(0, j - p_) * scale, j1 = (std::min(cellsV(level) - 1, j) + 1) * scale;
  for (int a = i0; a < i1; ++a)
    for (int b = j0; b < j1; ++b)
      if (!inDomain(domainLevel, a, b)) return false;
  return true;
}

void ThbSpace::refine(int level, const std::vector<std::pair<int, int>>& cells) {
  for (const auto& [i, j] : cells)
    if (!inDomain(level, i, j))
      throw Error("cell (" + std::to_string(i) + ", " + std::to_string(j) + ") of level " + std::to_string(level) + " is not in that level's domain");
  if (level + 1 >= levels()) domain_.push_back(std::vector<char>(static_cast<size_t>(cellsU(level + 1)) * cellsV(level + 1), 0));
  for (const auto& [i, j] : cells)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) domain_[level + 1][static_cast<size_t>(2 * j + b) * cellsU(level + 1) + 2 * i + a] = 1;
  rebuild();
}

void ThbSpace::rebuild() {
  // 1D two-scale matrices: level-ℓ functions in level ℓ+1's basis, by collocation at the finer
  // level's Greville abscissae (exact: the spaces are nested and the collocation is unisolvent).
  while (static_cast<int>(refinement_.size()) + 1 < levels()) {
    const int l = static_cast<int>(refinement_.size());
    std::array<Eigen::MatrixXd, 2> R;
    for (int dir = 0; dir < 2; ++dir) {
      const std::vector<double> Uc = knots(l, dir), Uf = knots(l + 1, dir);
      const int mc = static_cast<int>(Uc.size()) - p_ - 1, mf = static_cast<int>(Uf.size()) - p_ - 1;
      Eigen::MatrixXd G = Eigen::MatrixXd::Zero(mf, mf), C = Eigen::MatrixXd::Zero(mf, mc);
      for (int k = 0; k < mf; ++k) {
        double g = 0;
        for (int q = 1; q <= p_; ++q) g += Uf[k + q] / p_;
        const int sf = findSpan(Uf, p_, g), sc = findSpan(Uc, p_, g);
        const Eigen::MatrixXd bf = basisDerivatives(Uf, p_, sf, g, 0), bc = basisDerivatives(Uc, p_, sc, g, 0);
        for (int q = 0; q <= p_; ++q) G(k, sf - p_ + q) = bf(0, q), C(k, sc - p_ + q) = bc(0, q);
      }
      R[dir] = G.fullPivLu().solve(C);
      R[dir] = R[dir].unaryExpr([](double x) { return std::abs(x) < 1e-13 ? 0.0 : x; });
    }
    refinement_.push_back(R);
  }
  basis_.clear();
  const int L = levels() - 1;
  for (int l = 0; l <= L; ++l) {
    const int mu = cellsU(l) + p_, mv = cellsV(l) + p_;
    for (int i = 0; i < mu; ++i)
      for (int j = 0; j < mv; ++j) {
        if (!supportIn(l, i, j, l) || supportIn(l, i, j, l + 1)) continue;
        Function f{l, i, j, {}};
        std::map<std::pair<int, int>, double> c{{{i, j}, 1.0}};
        for (int m = l; m < L; ++m) {
          // Two-scale step, then truncation: drop the finer functions supported in Ω^{m+1}.
          std::map<std::pair<int, int>, double> next;
          for (const auto& [ij, x] : c)
            for (Eigen::Index a = 0; a < refinement_[m][0].rows(); ++a) {
              const double ru = refinement_[m][0](a, ij.first);
              if (ru == 0) continue;
              for (Eigen::Index b = 0; b < refinement_[m][1].rows(); ++b) {
                const double rv = refinement_[m][1](b, ij.second);
                if (rv != 0) next[{static_cast<int>(a), static_cast<int>(b)}] += x * ru * rv;
              }
            }
          for (auto it = next.begin(); it != next.end();)
            it = supportIn(m + 1, it->first.first, it->first.second, m + 1) ? next.erase(it) : std::next(it);
          c.swap(next);
        }
        f.finest = std::move(c);
        basis_.push_back(std::move(f));
      }
  }
}

ThbSpace refinedThbSpace(int degree, int cellsU, int cellsV, std::vector<std::array<int, 3>> cells) {
  ThbSpace space(degree, cellsU, cellsV);
  std::stable_sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; });
  for (size_t k = 0; k < cells.size();) {
    std::vector<std::pair<int, int>> level;
    const int l = cells[k][0];
    for (; k < cells.size() && cells[k][0] == l; ++k) level.push_back({cells[k][1], cells[k][2]});
    space.refine(l, level);
  }
  return space;
}

Eigen::SparseMatrix<double> ThbSpace::finestMap() const {
  const int L = levels() - 1, nv = cellsV(L) + p_, nFine = (cellsU(L) + p_) * nv;
  std::vector<Eigen::Triplet<double>> t;
  for (size_t k = 0; k < basis_.size(); ++k)
    for (const auto& [ab, c] : basis_[k].finest) t.emplace_back(ab.first * nv + ab.second, static_cast<int>(k), c);
  Eigen::SparseMatrix<double> T(nFine, static_cast<int>(basis_.size()));
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

std::map<std::pair<int, int>, double> ThbSpace::hierarchical(int level, int i, int j) const {
  std::map<std::pair<int, int>, double> c{{{i, j}, 1.0}};
  for (int m = level; m + 1 < levels(); ++m) {
    std::map<std::pair<int, int>, double> next;
    for (const auto& [ij, x] : c)
      for (Eigen::Index a = 0; a < refinement_[m][0].rows(); ++a)
        for (Eigen::Index b = 0; b < refinement_[m][1].rows(); ++b) {
          const double r = refinement_[m][0](a, ij.first) * refinement_[m][1](b, ij.second);
          if (r != 0) next[{static_cast<int>(a), static_cast<int>(b)}] += x * r;
        }
    c.swap(next);
  }
  return c;
}

std::vector<std::pair<int, double>> ThbSpace::evaluate(double u, double v) const {
  const int L = levels() - 1;
  const std::vector<double> Uu = knots(L, 0), Uv = knots(L, 1);
  u = std::clamp(u, 0.0, 1.0), v = std::clamp(v, 0.0, 1.0);
  const int su = findSpan(Uu, p_, u), sv = findSpan(Uv, p_, v);
  const Eigen::MatrixXd bu = basisDerivatives(Uu, p_, su, u, 0), bv = basisDerivatives(Uv, p_, sv, v, 0);
  std::vector<std::pair<int, double>> out;
  for (size_t k = 0; k < basis_.size(); ++k) {
    double value = 0;
    for (int a = 0; a <= p_; ++a)
      for (int b = 0; b <= p_; ++b) {
        const auto it = basis_[k].finest.find({su - p_ + a, sv - p_ + b});
        if (it != basis_[k].finest.end()) value += it->second * bu(0, a) * bv(0, b);
      }
    if (value != 0) out.emplace_back(static_cast<int>(k), value);
  }
  return out;
}

}  // namespace holefill
