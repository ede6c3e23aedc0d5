// One 64-bit key per undirected edge (higher vertex index in the high half), for hash maps and
// sorted edge lists over meshes and cages.
#pragma once

#include <algorithm>
#include <cstdint>

namespace holefill {

inline std::uint64_t undirectedEdgeKey(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

}  // namespace holefill
