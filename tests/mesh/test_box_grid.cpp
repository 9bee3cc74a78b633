// The box grid behind the geometry checks of cases with many regions (issue #36: a case with
// 10^5 regions took minutes in pairwise checks): its candidates hold every box that overlaps the
// query (compared with the brute-force test over all boxes), each once and in ascending order.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mesh/box_grid.hpp"

namespace rheomag::mesh {
namespace {

bool overlap(const Box2& a, const Box2& b) {
  return !(a.r_hi < b.r_lo || b.r_hi < a.r_lo || a.z_hi < b.z_lo || b.z_hi < a.z_lo);
}

Box2 random_box(std::mt19937& rng, double extent, double size) {
  std::uniform_real_distribution<double> at(0.0, extent), length(0.0, size);
  const double r = at(rng), z = at(rng);
  return {r, z, r + length(rng), z + length(rng)};
}

}  // namespace

// 2000 small boxes, 20 long thin ones (kept aside), points (zero-size boxes); 500 queries of
// every size: the candidates are a sorted, duplicate-free superset of the overlapping boxes.
TEST(BoxGrid, CandidatesHoldEveryOverlappingBoxOnce) {
  std::mt19937 rng(7);
  std::vector<Box2> boxes;
  for (int k = 0; k < 2000; ++k) boxes.push_back(random_box(rng, 1.0, 0.02));
  for (int k = 0; k < 20; ++k) boxes.push_back({0.0, 0.01 * k, 1.0, 0.01 * k});  // long edges
  for (int k = 0; k < 200; ++k) {
    const Box2 b = random_box(rng, 1.0, 0.0);
    boxes.push_back({b.r_lo, b.z_lo, b.r_lo, b.z_lo});  // points
  }
  const BoxGrid grid(boxes);
  for (int q = 0; q < 500; ++q) {
    const Box2 query = random_box(rng, 1.2, q % 50 == 0 ? 1.0 : 0.05);
    const std::vector<int> found = grid.candidates(query);
    EXPECT_TRUE(std::is_sorted(found.begin(), found.end()));
    EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (!overlap(boxes[i], query)) continue;
      EXPECT_TRUE(std::binary_search(found.begin(), found.end(), static_cast<int>(i)))
          << "box " << i << " overlaps query " << q << " but is not a candidate";
    }
  }
}

// A query with a non-finite side, and a non-finite box, are answered with every box (nothing
// can be ruled out), not with a wrong cell.
TEST(BoxGrid, NonFiniteBoxesAreNeverRuledOut) {
  const double inf = std::numeric_limits<double>::infinity();
  const BoxGrid grid({{0, 0, 1, 1}, {2, 2, 3, 3}, {0, 0, inf, 1}});
  EXPECT_EQ(grid.candidates({0.5, 0.5, 0.5, 0.5}), (std::vector<int>{0, 2}));
  EXPECT_EQ(grid.candidates({std::nan(""), 0, 1, 1}), (std::vector<int>{0, 1, 2}));
  const BoxGrid empty({});
  EXPECT_TRUE(empty.candidates({0, 0, 1, 1}).empty());
}

}  // namespace rheomag::mesh
