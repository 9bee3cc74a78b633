// Meshing speed on a valve-like axisymmetric geometry at several element sizes.
// Counters: triangles and nodes of the quadratic mesh (about the solver's P2 DOF count).

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "case/region_pslg.hpp"
#include "mesh/elevate.hpp"
#include "mesh/mesher.hpp"

namespace {

using rheomag::mesh::GapKind;
using rheomag::mesh::Pslg;

/// Core with a coil pocket, a 1 mm annular gap, a housing and an air box (marker 0 outside) [m].
Pslg valve_pslg() {
  Pslg pslg;
  std::map<std::pair<double, double>, int> index;
  auto point = [&](double r, double z) {
    auto [it, inserted] = index.try_emplace({r, z}, static_cast<int>(pslg.points.size()));
    if (inserted) pslg.points.push_back({r, z});
    return it->second;
  };
  auto rectangle = [&](double r0, double z0, double r1, double z1, int boundary) {
    const int a = point(r0, z0), b = point(r1, z0), c = point(r1, z1), d = point(r0, z1);
    pslg.segments.push_back({a, b, boundary, 0.0});
    pslg.segments.push_back({b, c, boundary, 0.0});
    pslg.segments.push_back({c, d, boundary, 0.0});
    pslg.segments.push_back({d, a, -1, 0.0});  // the side on the axis r = 0 stays unmarked
  };
  rectangle(0.0, -0.05, 0.05, 0.05, 0);
  rectangle(0.0, -0.02, 0.0195, 0.02, -1);
  rectangle(0.012, -0.008, 0.0195, 0.008, -1);
  rectangle(0.0195, -0.02, 0.0205, 0.02, -1);
  rectangle(0.0205, -0.02, 0.025, 0.02, -1);
  pslg.regions = {{{0.005, 0.0}, "core", 0.0, GapKind::none, false},
                  {{0.015, 0.0}, "coil", 0.0, GapKind::none, false},
                  {{0.02, 0.0}, "gap", 0.0, GapKind::annular, false},
                  {{0.023, 0.0}, "housing", 0.0, GapKind::none, false},
                  {{0.04, 0.0}, "air", 0.0, GapKind::none, false}};
  pslg.source = "bench valve";
  return pslg;
}

/// Argument: default element size in micrometres.
void BM_GenerateMeshP2(benchmark::State& state) {
  const Pslg pslg = valve_pslg();
  rheomag::mesh::MeshOptions options;
  options.default_size = static_cast<double>(state.range(0)) * 1e-6;
  rheomag::mesh::Mesh mesh;
  for (auto _ : state) {
    mesh = rheomag::mesh::generate_mesh(pslg, options);
    benchmark::DoNotOptimize(mesh.nodes.data());
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  state.counters["nodes"] = static_cast<double>(mesh.nodes.size());
}
BENCHMARK(BM_GenerateMeshP2)
    ->Arg(2000)
    ->Arg(1000)
    ->Arg(500)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond);

/// Argument: default element size in micrometres; times P1 -> P2 only.
void BM_ElevateToP2(benchmark::State& state) {
  rheomag::mesh::MeshOptions options;
  options.order = 1;
  options.default_size = static_cast<double>(state.range(0)) * 1e-6;
  const rheomag::mesh::Mesh linear = rheomag::mesh::generate_mesh(valve_pslg(), options);
  for (auto _ : state) {
    rheomag::mesh::Mesh quadratic = rheomag::mesh::elevate_to_p2(linear);
    benchmark::DoNotOptimize(quadratic.nodes.data());
  }
  state.counters["triangles"] = static_cast<double>(linear.triangles.size());
}
BENCHMARK(BM_ElevateToP2)->Arg(500)->Arg(250)->Unit(benchmark::kMillisecond);

/// Argument: number of 0.2 mm square regions on a 0.3 mm grid (plus a background); times the
/// case's geometry checks and the PSLG (outlines_to_pslg) and the mesh of it (issue #36: 10^4
/// regions took 28 s, 10^5 minutes, in pairwise checks; now grid-filed).
void BM_ManyRegions(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  std::vector<rheomag::cases::RegionOutline> outlines;
  for (int k = 0; k < n; ++k) {
    const double r = 1e-3 + 3e-4 * (k / side), z = 3e-4 * (k % side);
    rheomag::cases::RegionOutline o;
    o.name = "r" + std::to_string(k);
    o.material = "Air";
    o.outline = {{r, z}, {r + 2e-4, z}, {r + 2e-4, z + 2e-4}, {r, z + 2e-4}};
    o.where = "bench";
    outlines.push_back(std::move(o));
  }
  rheomag::mesh::Mesh mesh;
  for (auto _ : state) {
    const Pslg pslg = rheomag::cases::outlines_to_pslg(outlines, "bench", "air");
    mesh = rheomag::mesh::generate_mesh(pslg);
    benchmark::DoNotOptimize(mesh.nodes.data());
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}
BENCHMARK(BM_ManyRegions)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

/// Argument: number of pieces the gap's 40 mm outer wall is cut into (Segment::max_length);
/// times the mesh graded away from it (session 77: 10^4 pieces of one 10 mm segment took
/// 1 min 54 s, the size field scanning every piece as its own source).
void BM_FinelyCutSegment(benchmark::State& state) {
  Pslg pslg = valve_pslg();
  const double pieces = static_cast<double>(state.range(0));
  for (auto& s : pslg.segments) {
    const auto& a = pslg.points[static_cast<std::size_t>(s.a)];
    const auto& b = pslg.points[static_cast<std::size_t>(s.b)];
    if (a.r == 0.0205 && b.r == 0.0205) s.max_length = std::abs(b.z - a.z) / pieces;
  }
  rheomag::mesh::Mesh mesh;
  for (auto _ : state) {
    mesh = rheomag::mesh::generate_mesh(pslg);
    benchmark::DoNotOptimize(mesh.nodes.data());
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}
BENCHMARK(BM_FinelyCutSegment)->Arg(1000)->Arg(10000)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
