// The learned-model backend of HoleFill: libtorch, linked into App/learn/ and
// nowhere else (DESIGN.md). Models (UVTran, BIDGCN) live beside this file and
// reach the rest of the core through plain Eigen/std interfaces, so only files
// in this folder include torch headers. This header reports what backend the
// build has, for `holefill --version` and the Python module.
#pragma once

#include <string>

namespace holefill::learn {

// "libtorch <version> (<threads> threads)" after a real tensor round trip, or "unavailable: <why>".
std::string backendInfo();

}  // namespace holefill::learn
