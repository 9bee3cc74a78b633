#pragma once
// One integer key per undirected mesh edge, for hash maps over edges.

#include <cstdint>
#include <utility>

namespace rheomag::mesh {

/// Key of the undirected edge (a, b): the same for (b, a).
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace rheomag::mesh
