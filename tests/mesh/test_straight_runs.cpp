// merge_straight_runs: the pieces of a cut segment joined back into one size source. Reference:
// the distance from any point to a union of edges is the least distance to one of them, exact
// for the pieces of a straight segment; the runs expected are known by construction.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mesh/straight_runs.hpp"

using rheomag::mesh::detail::merge_straight_runs;
using rheomag::mesh::detail::SizedEdge;

namespace {

/// The segment (ar, az) -> (br, bz) cut into n equal pieces of one size, as the mesher cuts it.
std::vector<SizedEdge> cut(double ar, double az, double br, double bz, int n, double size) {
  std::vector<SizedEdge> pieces;
  for (int k = 0; k < n; ++k) {
    const double s0 = static_cast<double>(k) / n, s1 = static_cast<double>(k + 1) / n;
    pieces.push_back({{ar + s0 * (br - ar), az + s0 * (bz - az)},
                      {ar + s1 * (br - ar), az + s1 * (bz - az)},
                      size});
  }
  return pieces;
}

/// The least of size + distance over the edges: the size field's source term at grading 1.
double field(const std::vector<SizedEdge>& edges, double r, double z) {
  double h = std::numeric_limits<double>::infinity();
  for (const SizedEdge& e : edges) {
    const double dr = e.b[0] - e.a[0], dz = e.b[1] - e.a[1];
    const double t =
        std::clamp(((r - e.a[0]) * dr + (z - e.a[1]) * dz) / (dr * dr + dz * dz), 0.0, 1.0);
    h = std::min(h, e.size + std::hypot(r - e.a[0] - t * dr, z - e.a[1] - t * dz));
  }
  return h;
}

void append(std::vector<SizedEdge>& to, const std::vector<SizedEdge>& more) {
  to.insert(to.end(), more.begin(), more.end());
}

}  // namespace

// A slanted segment cut into 10 000 pieces, shuffled and some reversed, is one run with the
// segment's own ends.
TEST(StraightRuns, ACutSegmentIsOneRun) {
  std::vector<SizedEdge> pieces = cut(0.01, 0.002, 0.02, 0.0073, 10000, 1e-6);
  std::mt19937 random(7);
  std::shuffle(pieces.begin(), pieces.end(), random);
  for (std::size_t i = 0; i < pieces.size(); i += 3) std::swap(pieces[i].a, pieces[i].b);
  const std::vector<SizedEdge> runs = merge_straight_runs(pieces);
  ASSERT_EQ(runs.size(), 1u);
  const bool forward = runs[0].a[0] < runs[0].b[0];
  const auto& lo = forward ? runs[0].a : runs[0].b;
  const auto& hi = forward ? runs[0].b : runs[0].a;
  EXPECT_DOUBLE_EQ(lo[0], 0.01);
  EXPECT_DOUBLE_EQ(lo[1], 0.002);
  EXPECT_DOUBLE_EQ(hi[0], 0.02);
  EXPECT_DOUBLE_EQ(hi[1], 0.0073);
  EXPECT_EQ(runs[0].size, 1e-6);
}

// Runs stop at a corner, at a change of size, and where a third edge meets the line (a
// T-junction); the field over the runs equals the field over the pieces at 2 000 random points
// (to 1e-15 m, rounding).
TEST(StraightRuns, RunsStopAtCornersSizeChangesAndJunctionsAndKeepTheField) {
  std::vector<SizedEdge> pieces;
  append(pieces, cut(0, 0, 0.01, 0, 50, 1e-4));           // bottom, to the corner
  append(pieces, cut(0.01, 0, 0.01, 0.01, 40, 1e-4));     // right side, up from the corner
  append(pieces, cut(0.01, 0.01, 0.02, 0.01, 30, 2e-4));  // straight on, another size
  append(pieces, cut(0.02, 0.01, 0.03, 0.01, 30, 2e-4));  // straight on, the same size,
  append(pieces, cut(0.02, 0.01, 0.02, 0.02, 10, 2e-4));  // but a branch meets it here
  const std::vector<SizedEdge> runs = merge_straight_runs(pieces);
  EXPECT_EQ(runs.size(), 5u);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> r(-0.005, 0.035), z(-0.005, 0.025);
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const double pr = r(random), pz = z(random);
    worst = std::max(worst, std::abs(field(runs, pr, pz) - field(pieces, pr, pz)));
  }
  EXPECT_LT(worst, 1e-15);
}

// Edges of one size that meet at a slight angle (1e-6 rad, far above rounding) are not joined:
// the run would pass beside the shared end.
TEST(StraightRuns, ABendIsNotStraightened) {
  const std::vector<SizedEdge> pieces = {{{0, 0}, {0.01, 0}, 1e-4},
                                         {{0.01, 0}, {0.02, 1e-8}, 1e-4}};
  EXPECT_EQ(merge_straight_runs(pieces).size(), 2u);
}
