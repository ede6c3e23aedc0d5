// The sample cages (gnurbs/sample_cages.h) under the tests' names, and the cage diagonal.
#pragma once

#include "gnurbs/sample_cages.h"

namespace holefill::testcages {

using cages::cubeCage;
using cages::edgeStarCage;
using cages::height;
using cages::polarCage;

inline double diagonal(const QuadCage& c) { return (c.vertices.colwise().maxCoeff() - c.vertices.colwise().minCoeff()).norm(); }

}  // namespace holefill::testcages
