// FEMM's prescribed A that varies in space, A = (A_0 + A_1 x + A_2 y) cos(phi) (xfemm 35baec4,
// fsolver/static2d.cpp, staticaxi.cpp): the usual way to put a body in a uniform field. References:
// the uniform field itself (exact: A is linear) and the closed form of a permeable sphere in a
// uniform field.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "case/femm_import.hpp"
#include "core/error.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/femm_text.hpp"

using namespace rheomag;
using namespace rheomag::magnetostatics;
using rheomag::testing::fem_block;
using rheomag::testing::FemText;

namespace {

/// A prescribed-A boundary with FEMM's A_0, A_1, A_2 and phase phi [deg].
std::string varying_a(double a0, double a1, double a2, double phi = 0.0) {
  return "<BeginBdry>\n<BdryName> = \"field\"\n<BdryType> = 0\n<A_0> = " + std::to_string(a0) +
         "\n<A_1> = " + std::to_string(a1) + "\n<A_2> = " + std::to_string(a2) +
         "\n<Phi> = " + std::to_string(phi) + "\n<EndBdry>";
}

/// B [T] at (r, z) [m].
std::array<double, 2> b_at(const SolveResult& s, double r, double z) {
  std::array<double, 2> b{};
  EXPECT_TRUE(flux_density_at(*s.solver, s.solution, {r, z}, -1, b));
  return b;
}

}  // namespace

// An empty planar box in millimetres with A_1 = -2e-4 and A_2 = -1e-4 Wb/m per millimetre (FEMM
// takes x and y in the file's unit), so A = 0.5 - 0.2 x - 0.1 y with x, y in metres and
// B = (dA/dy, -dA/dx) = (-0.1, 0.2) T, exact in P2 (1e-9). With phi = 60 degrees FEMM's static
// solver takes the real part: half.
TEST(FemmUniformField, LinearPrescribedAIsAUniformField) {
  for (const double phi : {0.0, 60.0}) {
    FemText f;
    f.header = "[LengthUnits] = millimeters\n";
    f.boundaries = {varying_a(0.5, -2e-4, -1e-4, phi)};
    f.blocks = {fem_block("air", 1.0)};
    f.points = {"0 0 0 0", "100 0 0 0", "100 50 0 0", "0 50 0 0"};
    f.segments = {"0 1 -1 1 0 0", "1 2 -1 1 0 0", "2 3 -1 1 0 0", "3 0 -1 1 0 0"};
    f.labels = {"50 25 1 5 0 0 0 1 0"};
    std::string text = f.str();
    text.erase(text.find("[LengthUnits] = meters\n"), 23);
    const SolveResult s = solve_problem(cases::parse_femm(text, "box.fem"));
    const double half = phi == 0.0 ? 1.0 : 0.5;
    const auto b = b_at(s, 0.03, 0.02);
    EXPECT_NEAR(b[0], -0.1 * half, 1e-9) << "phi " << phi;  // B_x = dA/dy = -1e-4 / 1e-3 m
    EXPECT_NEAR(b[1], 0.2 * half, 1e-9) << "phi " << phi;   // B_y = -dA/dx = 2e-4 / 1e-3 m
  }
}

// A sphere of mu_r = 100, radius a = 10 mm, in a uniform axial field B0 = 0.1 T prescribed as
// A = B0 r / 2 (A_1 = 0.05) on a box 10 a away: inside B = 3 mu_r / (mu_r + 2) B0 = 0.294118 T
// (the closed form in an unbounded field; the box's uniform condition perturbs it by about
// (a / R)^3 = 1e-3), tolerance 0.5 %. Without A_1 the model has no field at all.
TEST(FemmUniformField, PermeableSphereInAUniformFieldMatchesTheClosedForm) {
  constexpr double b0 = 0.1, mu = 100.0;
  FemText f;
  f.problem = "axisymmetric";
  f.boundaries = {varying_a(0.0, b0 / 2, 0.0)};
  f.blocks = {fem_block("air", 1.0), fem_block("iron", mu)};
  f.points = {"0 -0.1 0 0", "0.1 -0.1 0 0", "0.1 0.1 0 0",
              "0 0.1 0 0",  "0 -0.01 0 0",  "0 0.01 0 0"};
  f.segments = {"0 1 -1 1 0 0", "1 2 -1 1 0 0", "2 3 -1 1 0 0",
                "3 5 -1 0 0 0", "5 4 -1 0 0 0", "4 0 -1 0 0 0"};
  f.arcs = {"4 5 180 1 0 0 0"};
  f.labels = {"0.005 0 2 0.0005 0 0 0 1 0", "0.05 0.05 1 0.005 0 0 0 1 0"};
  const SolveResult s = solve_problem(cases::parse_femm(f.str(), "sphere.fem"));
  const double inside = 3 * mu / (mu + 2) * b0;
  for (const auto& [r, z] :
       {std::pair{0.0, 0.0}, std::pair{0.004, 0.003}, std::pair{0.0, -0.006}}) {
    const auto b = b_at(s, r, z);
    EXPECT_NEAR(b[1], inside, 5e-3 * inside) << "(" << r << ", " << z << ")";
    EXPECT_NEAR(b[0], 0.0, 5e-3 * inside) << "(" << r << ", " << z << ")";
  }
  // Far from the sphere, at the box's corner region, the field is the applied one.
  EXPECT_NEAR(b_at(s, 0.09, 0.09)[1], b0, 5e-3 * b0);
}

// In polar coordinates FEMM multiplies A_2 by the angle: not supported, said with both lines.
TEST(FemmUniformField, PolarCoordinatesWithAVaryingAAreRefused) {
  FemText f;
  f.header = "[Coordinates] = polar\n";
  f.boundaries = {varying_a(0.0, 1e-3, 0.0)};
  f.blocks = {fem_block("air", 1.0)};
  f.points = {"0 0 0 0", "1 0 0 0", "1 1 0 0", "0 1 0 0"};
  f.segments = {"0 1 -1 1 0 0", "1 2 -1 0 0 0", "2 3 -1 0 0 0", "3 0 -1 0 0 0"};
  f.labels = {"0.5 0.5 1 0.1 0 0 0 1 0"};
  try {
    cases::parse_femm(f.str(), "polar.fem");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                ::testing::HasSubstr("in polar coordinates ([Coordinates] = polar, line 7)"));
  }
}
