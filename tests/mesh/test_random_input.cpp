// Random PSLGs (fixed seed): generate_mesh either throws InputError or returns a valid mesh;
// it never crashes, hangs or returns garbage.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <string>

#include "core/error.hpp"
#include "mesh/mesher.hpp"
#include "pslg_fixtures.hpp"

namespace rheomag::mesh {
namespace {

/// A random outer polygon (star-shaped about (0.5, 0.5), or with corners in random order and
/// then often self-intersecting), sometimes an inner triangle, 1-3 seeds (the first near the
/// centre), gap kinds and default region at random.
Pslg random_pslg(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> corners(3, 9), seeds(1, 3), coin(0, 1);
  fixtures::PslgBuilder b;
  std::vector<Point> outer(static_cast<std::size_t>(corners(rng)));
  if (coin(rng)) {
    std::vector<double> angle(outer.size());
    for (double& a : angle) a = 2.0 * std::numbers::pi * unit(rng);
    std::sort(angle.begin(), angle.end());
    for (std::size_t k = 0; k < outer.size(); ++k) {
      const double radius = 0.1 + 0.4 * unit(rng);
      outer[k] = {0.5 + radius * std::cos(angle[k]), 0.5 + radius * std::sin(angle[k])};
    }
  } else {
    for (Point& p : outer) p = {unit(rng), unit(rng)};
  }
  b.polygon(outer, 0);
  if (coin(rng)) {
    std::vector<Point> inner(3);
    for (Point& p : inner) p = {0.3 + 0.4 * unit(rng), 0.3 + 0.4 * unit(rng)};
    b.polygon(inner);
  }
  const int n = seeds(rng);
  for (int i = 0; i < n; ++i) {
    std::string name = "r";
    name += std::to_string(i);
    const Point seed = i == 0 ? Point{0.5 + 0.02 * unit(rng), 0.5 + 0.02 * unit(rng)}
                              : Point{unit(rng), unit(rng)};
    b.region(seed.r, seed.z, name, 0.0, coin(rng) ? GapKind::annular : GapKind::none);
  }
  b.pslg.default_region = coin(rng) ? 0 : -1;
  b.pslg.source = "random";
  return b.pslg;
}

TEST(RandomInput, EitherAValidMeshOrAnInputError) {
  std::mt19937 rng(20240611);
  int meshed = 0, rejected = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Pslg pslg = random_pslg(rng);
    MeshOptions options;
    options.order = 1;
    options.max_elements = 200'000;
    try {
      const Mesh mesh = generate_mesh(pslg, options);
      ++meshed;
      ASSERT_FALSE(mesh.triangles.empty()) << "trial " << trial;
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        ASSERT_GT(fixtures::signed_area(mesh, t), 0.0) << "trial " << trial;
        ASSERT_GE(mesh.region[t], 0) << "trial " << trial;
        ASSERT_LT(mesh.region[t], static_cast<int>(pslg.regions.size())) << "trial " << trial;
      }
    } catch (const InputError& e) {
      ++rejected;
      ASSERT_EQ(std::string(e.what()).rfind("random: ", 0), 0u) << e.what();
    }
  }
  // Both outcomes must occur, or the generator tests nothing.
  EXPECT_GT(meshed, 50);
  EXPECT_GT(rejected, 50);
  std::cout << meshed << " meshed, " << rejected << " rejected\n";
}

}  // namespace
}  // namespace rheomag::mesh
