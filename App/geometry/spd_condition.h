// The condition number of a symmetric positive (semi)definite matrix, the normal matrix of a
// least-squares fit, as its fitting reports and benchmarks quote it (log10 of the ratio of the
// extreme eigenvalues). Small matrices get an exact dense eigensolve; large ones (a 40 × 40
// control grid has 1,600 unknowns, whose dense eigensolve takes seconds) an estimate: the largest
// eigenvalue by power iteration, the smallest by inverse iteration through a sparse
// factorization, each to a few per cent, which log10 does not see.
#pragma once

#include <Eigen/Sparse>

namespace holefill {

// Infinity when the matrix is singular (smallest eigenvalue ≤ 1e-15 × largest, or a failed
// factorization). `exactUpTo`: the largest size solved exactly.
double log10Condition(const Eigen::SparseMatrix<double>& N, int exactUpTo = 400);

}  // namespace holefill
