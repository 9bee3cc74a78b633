// How a FEMM model's circuit currents spread over its blocks, as FEMM's solver spreads them (xfemm
// 35baec4, fsolver/static2d.cpp, staticaxi.cpp): a parallel circuit's current split by the
// blocks' conductivities, a solid one-turn conductor of an axisymmetric model carrying J ~ 1/r,
// and a block's own J taken back by its circuit. References: the 1D closed forms of a slot and
// of a long cylindrical shell, written in each test.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "case/femm_import.hpp"
#include "core/constants.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/femm_slot.hpp"
#include "tests/magnetostatics/femm_text.hpp"

using namespace rheomag;
using namespace rheomag::magnetostatics;
using rheomag::testing::fem_block;
using rheomag::testing::fem_boundary;
using rheomag::testing::fem_circuit;
using rheomag::testing::FemText;
using rheomag::testing::SlotSizes;

namespace {

SolveResult solve_text(const std::string& text) {
  return solve_problem(cases::parse_femm(text, "model.fem"));
}

/// B_y [T] in the slot's air, mid-height.
double slot_air_b(const SolveResult& s) {
  std::array<double, 2> b{};
  EXPECT_TRUE(flux_density_at(*s.solver, s.solution, {SlotSizes::L / 2, SlotSizes::H / 3}, -1, b));
  return b[1];
}

/// Energy [J] of the slot's 1D field with current densities j1 (left) and j2 (right) in the same
/// direction and dA/dn = 0 at x = 0: H_y = j1 x, then j1 a across the air, then j1 a + j2 s.
double slot_energy(double j1, double j2) {
  constexpr double a = SlotSizes::a, L = SlotSizes::L;
  const double h2 = j1 * j1 * a * a * a / 3 + j1 * j1 * a * a * (L - 2 * a) + j1 * j1 * a * a * a +
                    j1 * j2 * a * a * a + j2 * j2 * a * a * a / 3;
  return SlotSizes::D * SlotSizes::H * kMu0 / 2 * h2;
}

/// The slot with both conductors in one parallel circuit of `amps` and A = 0 on the right edge;
/// blocks: air, then conductors of sigma1 and sigma2 [MS/m]; `turns` on both labels.
FemText parallel_slot(double sigma1, double sigma2, int turns, double amps) {
  const std::string t = std::to_string(turns);
  FemText f = rheomag::testing::slot("2 0.004 1 0 0 " + t + " 0", "3 0.004 1 0 0 " + t + " 0");
  f.blocks = {fem_block("air", 1.0), fem_block("cu", 1.0, 0, 0, 0, 1, sigma1),
              fem_block("al", 1.0, 0, 0, 0, 1, sigma2)};
  f.circuits = {fem_circuit("bus", amps, 0)};
  f.boundaries = {fem_boundary("A=0", 0, 0.0)};
  f.segments[3] = "3 4 -1 1 0 0";  // the right edge x = L
  return f;
}

}  // namespace

// FEMM's parallel circuit over two solid conductors drives them with one voltage: J = sigma E, so
// the current splits 2 : 1 between 58 and 29 MS/m. The field is the slot's 1D field, exact in P2
// (1e-9). An even split (J1 = J2) would put B_y in the air 25 % lower.
TEST(FemmCircuits, ParallelCircuitSplitsItsCurrentByConductivity) {
  const double amps = 300.0, area = SlotSizes::a * SlotSizes::H;
  const SolveResult s = solve_text(parallel_slot(58.0, 29.0, 1, amps).str());
  const double j1 = 2.0 / 3.0 * amps / area, j2 = 1.0 / 3.0 * amps / area;
  EXPECT_NEAR(slot_air_b(s), kMu0 * j1 * SlotSizes::a, 1e-9 * kMu0 * j1 * SlotSizes::a);
  EXPECT_NEAR(s.results.energy, slot_energy(j1, j2), 1e-9 * slot_energy(j1, j2));
  ASSERT_EQ(s.results.circuits.size(), 1u);
  EXPECT_EQ(s.results.circuits[0].turns, 1.0);  // one current shared, whatever the labels say
  // FEMM's lambda = integral A . J dV / I, which for this linear field is 2 W / I.
  EXPECT_NEAR(s.results.circuits[0].flux_linkage, 2 * slot_energy(j1, j2) / amps,
              1e-9 * slot_energy(j1, j2));
}

// Without conductivity (or with windings: more than one turn, which FEMM gives a bulk
// conductivity of 0 and whose turns a parallel circuit ignores) the current spreads evenly over
// the circuit's whole area.
TEST(FemmCircuits, ParallelCircuitWithoutSolidConductorsSpreadsEvenly) {
  const double amps = 300.0, j = amps / (2 * SlotSizes::a * SlotSizes::H);
  for (const auto& [sigma, turns] : {std::pair{0.0, 1}, std::pair{58.0, 5}}) {
    const SolveResult s = solve_text(parallel_slot(sigma, sigma / 2, turns, amps).str());
    EXPECT_NEAR(slot_air_b(s), kMu0 * j * SlotSizes::a, 1e-9 * kMu0 * j * SlotSizes::a)
        << "sigma " << sigma << ", turns " << turns;
    EXPECT_NEAR(s.results.energy, slot_energy(j, j), 1e-9 * slot_energy(j, j));
  }
}

// A block J inside a circuit: FEMM's circuit carries its stated current in total, so it takes
// the block's own current back (the left conductor's 3 MA/m^2 changes nothing). Reference: the
// field without the block J, the slot's closed form, 1e-9.
TEST(FemmCircuits, CircuitTakesBackItsBlocksOwnCurrent) {
  FemText f = rheomag::testing::slot("3 0.004 1 0 0 100 0", "2 0.004 1 0 0 -100 0");
  f.blocks.push_back(fem_block("copper with J", 1.0, 0, 3.0));
  f.circuits = {fem_circuit("coil", 2.0)};
  f.boundaries = {fem_boundary("A=0", 0, 0.0)};
  f.segments[3] = "3 4 -1 1 0 0";
  const SolveResult s = solve_text(f.str());
  const double j = 100 * 2.0 / (SlotSizes::a * SlotSizes::H);
  EXPECT_NEAR(slot_air_b(s), kMu0 * j * SlotSizes::a, 1e-9 * kMu0 * j * SlotSizes::a);
}

// A one-turn solid copper ring in an axisymmetric model: FEMM drives it by a voltage around the
// axis, E = V / (2 pi r), so J = C / r. The ring is a long shell (a = 10 mm to b = 30 mm, height
// h = 20 mm, the field 1D: dA/dn = 0 on top and bottom, A = 0 at r = 40 mm), so
// B_z(r) - B_z(r < a) = -mu0 C ln(r / a) in the shell, C = I / (h ln(b / a)), and across the whole
// shell B_z drops by mu0 I / h (Ampere, any distribution). FEMM's centroid rule (J constant on
// each triangle, 0.5 mm) against the closed form: 0.3 %. An even J would be 26 % off at 20 mm,
// which is what the same ring gives as a 2-turn winding (J = I / (h (b - a))).
TEST(FemmCircuits, AxisymmetricSolidRingCarriesCurrentAsOneOverR) {
  constexpr double ra = 0.01, rb = 0.03, R = 0.04, h = 0.02, amps = 100.0;
  const auto ring = [&](int turns) {
    FemText f;
    f.problem = "axisymmetric";
    f.blocks = {fem_block("air", 1.0), fem_block("copper", 1.0, 0, 0, 0, 1, 58.0)};
    f.circuits = {fem_circuit("ring", amps / turns)};
    f.boundaries = {fem_boundary("A=0", 0, 0.0)};
    const double rs[] = {0, ra, rb, R};
    for (double r : rs) f.points.push_back(std::to_string(r) + " 0 0 0");
    for (int i = 3; i >= 0; --i)
      f.points.push_back(std::to_string(rs[i]) + " " + std::to_string(h) + " 0 0");
    for (auto [p, q] :
         {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}, {1, 6}, {2, 5}})
      f.segments.push_back(std::to_string(p) + " " + std::to_string(q) + " -1 " +
                           (p == 3 ? "1" : "0") + " 0 0");
    f.labels = {"0.005 0.01 1 0.0005 0 0 0 1 0",
                "0.02 0.01 2 0.0005 1 0 0 " + std::to_string(turns) + " 0",
                "0.035 0.01 1 0.0005 0 0 0 1 0"};
    return solve_text(f.str());
  };
  const auto b_z = [](const SolveResult& s, double r) {
    std::array<double, 2> b{};
    EXPECT_TRUE(flux_density_at(*s.solver, s.solution, {r, 0.01}, -1, b));
    return b[1];
  };
  const SolveResult solid = ring(1), wound = ring(2);
  const double c = amps / (h * std::log(rb / ra)), j_even = amps / (h * (rb - ra));
  for (const SolveResult* s : {&solid, &wound})
    EXPECT_NEAR(b_z(*s, 0.005) - b_z(*s, 0.035), kMu0 * amps / h, 3e-3 * kMu0 * amps / h);
  for (double r : {0.015, 0.02, 0.025}) {
    const double exact = -kMu0 * c * std::log(r / ra), even = -kMu0 * j_even * (r - ra);
    EXPECT_NEAR(b_z(solid, r) - b_z(solid, 0.005), exact, 3e-3 * std::abs(exact)) << "r = " << r;
    EXPECT_NEAR(b_z(wound, r) - b_z(wound, 0.005), even, 3e-3 * std::abs(even)) << "r = " << r;
  }
}
