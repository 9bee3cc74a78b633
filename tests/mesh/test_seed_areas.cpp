// seed_areas: which enclosed area of a PSLG each seed lies in (used by the FEMM reader for
// FEMM's <No Mesh> rule). Reference: the areas of two nested squares, known by construction.

#include <gtest/gtest.h>

#include <vector>

#include "mesh/seed_areas.hpp"
#include "tests/mesh/pslg_fixtures.hpp"

using namespace rheomag::mesh;

// Outer square [0, 4]^2 around an inner square [1, 3]^2 (a ring and a core), and a square
// [5, 6]^2 beside them: two seeds in the ring share its area, the core and the other square
// have their own, a seed outside everything gets -1.
TEST(SeedAreas, SeedsInOneAreaShareItsNumber) {
  fixtures::PslgBuilder b;
  b.rectangle(0, 0, 4, 4);
  b.rectangle(1, 1, 3, 3);
  b.rectangle(5, 0, 6, 1);
  b.region(0.5, 0.5, "ring a");
  b.region(2.0, 2.0, "core");
  b.region(3.5, 3.5, "ring b", 0.0, GapKind::none, true);
  b.region(7.0, 7.0, "outside");
  b.region(5.5, 0.5, "beside");
  const std::vector<int> area = seed_areas(b.pslg);
  ASSERT_EQ(area.size(), 5u);
  EXPECT_EQ(area[0], area[2]);
  EXPECT_GE(area[0], 0);
  EXPECT_GE(area[1], 0);
  EXPECT_NE(area[1], area[0]);
  EXPECT_EQ(area[3], -1);
  EXPECT_GE(area[4], 0);
  EXPECT_NE(area[4], area[0]);
  EXPECT_NE(area[4], area[1]);
}

// An inner square whose side is left open is one area with the ring around it.
TEST(SeedAreas, AnOpenBoundaryJoinsTwoAreas) {
  fixtures::PslgBuilder b;
  b.rectangle(0, 0, 4, 4);
  const int p0 = b.point(1, 1), p1 = b.point(3, 1), p2 = b.point(3, 3), p3 = b.point(1, 3);
  b.pslg.segments.push_back({p0, p1, -1, 0.0});
  b.pslg.segments.push_back({p1, p2, -1, 0.0});
  b.pslg.segments.push_back({p2, p3, -1, 0.0});  // the side p3-p0 is missing
  b.region(0.5, 0.5, "ring");
  b.region(2.0, 2.0, "core");
  const std::vector<int> area = seed_areas(b.pslg);
  EXPECT_EQ(area[0], area[1]);
}
