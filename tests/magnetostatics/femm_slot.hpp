#pragma once
// A planar slot of two conductors with air between, as a .fem text: its field is 1D, so the
// closed forms of its energy and flux density hold exactly (A is piecewise quadratic).

#include <string>

#include "tests/magnetostatics/femm_text.hpp"

namespace rheomag::testing {

/// The slot's sizes [m]: [0, L] x [0, H], conductors x in [0, a] and [L - a, L]; depth D.
struct SlotSizes {
  static constexpr double L = 0.1, H = 0.02, a = 0.01, D = 0.5;
};

/// The slot with blocks air (1) and copper (2) and labels "block size circuit magdir group turns
/// external" for the left conductor, the air and the right conductor; segment 3 is the right
/// edge x = L.
inline FemText slot(const std::string& left, const std::string& right) {
  constexpr double L = SlotSizes::L, H = SlotSizes::H, a = SlotSizes::a;
  FemText f;
  f.depth = SlotSizes::D;
  f.blocks = {fem_block("air", 1.0), fem_block("copper", 1.0)};
  const double xs[] = {0, a, L - a, L};
  for (double x : xs) f.points.push_back(std::to_string(x) + " 0 0 0");
  for (int i = 3; i >= 0; --i)
    f.points.push_back(std::to_string(xs[i]) + " " + std::to_string(H) + " 0 0");
  // bottom 0-1-2-3, right 3-4, top 4-5-6-7, left 7-0, internal 1-6 and 2-5.
  for (auto [p, q] :
       {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}, {1, 6}, {2, 5}})
    f.segments.push_back(std::to_string(p) + " " + std::to_string(q) + " -1 0 0 0");
  f.labels = {std::to_string(a / 2) + " 0.01 " + left,
              std::to_string(L / 2) + " 0.01 1 0.004 0 0 0 1 0",
              std::to_string(L - a / 2) + " 0.01 " + right};
  return f;
}

}  // namespace rheomag::testing
