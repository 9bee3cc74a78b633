// Linear anisotropic FEMM blocks: Mu_x != Mu_y, and laminations along x or y (LamType 1, 2) with
// LamFill < 1, which FEMM's planar solver turns into mu f + 1 - f along the sheets and
// mu / (f + mu (1 - f)) across them (xfemm 35baec4, fsolver/static2d.cpp). References: the closed
// form of a layered medium (the mean of mu along the sheets, of 1/mu across them), the same stack
// drawn sheet by sheet, and a uniform field in a homogeneous block. The fields are 1D or uniform,
// so P2 on meshes that follow the sheets reproduces them to rounding (1e-8).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "case/femm_export.hpp"
#include "case/femm_import.hpp"
#include "core/constants.hpp"
#include "magnetostatics/element_kernel.hpp"
#include "magnetostatics/reluctivity.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/femm_text.hpp"

using namespace rheomag;
using namespace rheomag::magnetostatics;
using rheomag::testing::fem_block;
using rheomag::testing::FemText;

namespace {

constexpr double kL = 0.02, kH = 0.01, kDepth = 0.1;    // box [0, L] x [0, H] [m], depth [m]
constexpr double kMu = 200.0, kFill = 0.8, kA0 = 1e-4;  // sheet mu_r, fill, A drive [Wb/m]
constexpr int kSheets = 5;

/// mu_r of the stack along the sheets (the mean of mu) and across them (1 / the mean of 1/mu).
constexpr double kMuAlong = kFill * kMu + (1.0 - kFill);
constexpr double kMuAcross = 1.0 / (kFill / kMu + (1.0 - kFill));

/// A prescribed-A boundary A = a0 (+ A_1 x + A_2 y).
std::string boundary(const std::string& name, double a0, double a1 = 0.0, double a2 = 0.0) {
  return "<BeginBdry>\n<BdryName> = \"" + name +
         "\"\n<BdryType> = 0\n<A_0> = " + std::to_string(a0) + "\n<A_1> = " + std::to_string(a1) +
         "\n<A_2> = " + std::to_string(a2) + "\n<EndBdry>";
}

/// A linear block with its own Mu_x and Mu_y, lamination type and fill.
std::string block(const std::string& name, double mu_x, double mu_y, int lam_type, double fill) {
  std::string text = fem_block(name, mu_x, 0.0, 0.0, lam_type, fill);
  const std::string key = "<Mu_y> = ";
  const std::size_t at = text.find(key) + key.size();
  return text.replace(at, text.find('\n', at) - at, std::to_string(mu_y));
}

/// The box split at heights `ys` (ascending, 0 ... H), the layer between ys[k] and ys[k+1]
/// labelled with block label_block[k]. Driven `along` x (A = 0 at y = 0, A0 at y = H, the sides
/// free) or across it (A = 0 at x = 0, A0 at x = L, top and bottom free).
FemText layered_box(const std::vector<double>& ys, const std::vector<int>& label_block,
                    bool along) {
  FemText f;
  f.depth = kDepth;
  f.boundaries = {boundary("low", 0.0), boundary("high", kA0)};
  const int n = static_cast<int>(ys.size());
  for (double y : ys) f.points.push_back("0 " + std::to_string(y) + " 0 0");
  for (double y : ys) f.points.push_back(std::to_string(kL) + " " + std::to_string(y) + " 0 0");
  for (int k = 0; k < n; ++k) {  // horizontal lines: the bottom, the interfaces, the top
    const int bc = !along ? 0 : k == 0 ? 1 : k == n - 1 ? 2 : 0;
    f.segments.push_back(std::to_string(k) + " " + std::to_string(n + k) + " -1 " +
                         std::to_string(bc) + " 0 0");
  }
  for (int k = 0; k + 1 < n; ++k) {  // the left and right sides, piece by piece
    f.segments.push_back(std::to_string(k) + " " + std::to_string(k + 1) + " -1 " +
                         (along ? "0" : "1") + " 0 0");
    f.segments.push_back(std::to_string(n + k) + " " + std::to_string(n + k + 1) + " -1 " +
                         (along ? "0" : "2") + " 0 0");
  }
  for (int k = 0; k + 1 < n; ++k) {
    const double mid = 0.5 * (ys[k] + ys[k + 1]);
    f.labels.push_back(std::to_string(kL / 2) + " " + std::to_string(mid) + " " +
                       std::to_string(label_block[k]) + " 0.002 0 0 0 1 0");
  }
  return f;
}

/// `f` mirrored about the line y = x (x and y of every point and label exchanged): a stack of
/// horizontal layers becomes one of vertical layers, with the drives turned alike.
FemText transposed(FemText f) {
  const auto swap_first_two = [](std::string& line) {
    std::istringstream in(line);
    std::string x, y, rest;
    in >> x >> y;
    std::getline(in, rest);
    line = y + " " + x + rest;
  };
  for (std::string& point : f.points) swap_first_two(point);
  for (std::string& label : f.labels) swap_first_two(label);
  return f;
}

/// The stack drawn sheet by sheet: kSheets periods of iron (fill) under air.
FemText drawn_stack(bool along) {
  std::vector<double> ys{0.0};
  std::vector<int> blocks;
  const double period = kH / kSheets;
  for (int s = 0; s < kSheets; ++s) {
    ys.push_back(s * period + kFill * period), blocks.push_back(1);
    ys.push_back((s + 1) * period), blocks.push_back(2);
  }
  FemText f = layered_box(ys, blocks, along);
  f.blocks = {fem_block("iron", kMu), fem_block("air", 1.0)};
  return f;
}

/// The closed-form energy [J] of the stack: along x W = D L A0^2 / (2 mu0 H mu_along), across
/// W = D H A0^2 / (2 mu0 L mu_across).
double stack_energy(bool along) {
  return along ? kDepth * kL * kA0 * kA0 / (2 * kMu0 * kH * kMuAlong)
               : kDepth * kH * kA0 * kA0 / (2 * kMu0 * kL * kMuAcross);
}

SolveResult solve_text(const FemText& f) {
  return solve_problem(cases::parse_femm(f.str(), "stack.fem"));
}

}  // namespace

// The reference itself: the stack drawn sheet by sheet (10 layers, mu_r 200 at fill 0.8) has the
// layered medium's closed-form energy in both directions (A is piecewise linear in y along the
// sheets, linear in x across them; the mesh follows the sheets).
TEST(FemmAnisotropic, DrawnStackHasTheLayeredClosedForm) {
  for (const bool along : {true, false}) {
    const SolveResult s = solve_text(drawn_stack(along));
    EXPECT_NEAR(s.results.energy, stack_energy(along), 1e-8 * stack_energy(along))
        << (along ? "along" : "across");
  }
  // The two directions differ by mu_along / mu_across = 32.7: the test tells them apart.
  EXPECT_GT(kMuAlong / kMuAcross, 30.0);
}

// One block laminated along x (LamType 1, Mu_x 200, fill 0.8) in place of the drawn stack: FEMM's
// mu_r along and across the sheets are the layered medium's, and the energy both ways is the
// stack's closed form (DrawnStackHasTheLayeredClosedForm). LamType 2 (sheets along y) takes
// Mu_y, with the two mu_r exchanged. (The block alone fixes its material and energy; the solver's
// use of each axis is LaminatedBlockBesideAirTakesEachAxis.)
TEST(FemmAnisotropic, LaminatedBlockIsTheDrawnStack) {
  for (const int lam_type : {1, 2}) {
    for (const bool along : {true, false}) {
      FemText f = layered_box({0.0, kH}, {1}, along);
      // LamType 2 uses Mu_y; Mu_x is then a value FEMM ignores.
      f.blocks = {lam_type == 1 ? block("laminated", kMu, 7.0, 1, kFill)
                                : block("laminated", 7.0, kMu, 2, kFill)};
      const cases::Problem problem = cases::parse_femm(f.str(), "laminated.fem");
      const cases::Material& m = problem.materials[problem.regions[0].material];
      ASSERT_TRUE(m.mu_r_axes.has_value());
      const std::array<double, 2> expected =
          lam_type == 1 ? std::array{kMuAlong, kMuAcross} : std::array{kMuAcross, kMuAlong};
      EXPECT_NEAR((*m.mu_r_axes)[0], expected[0], 1e-12 * expected[0]);
      EXPECT_NEAR((*m.mu_r_axes)[1], expected[1], 1e-12 * expected[1]);
      const SolveResult s = solve_problem(problem);
      const double reference = along ? kDepth * kL * kA0 * kA0 / (2 * kMu0 * kH * expected[0])
                                     : kDepth * kH * kA0 * kA0 / (2 * kMu0 * kL * expected[1]);
      EXPECT_NEAR(s.results.energy, reference, 1e-8 * reference)
          << "LamType " << lam_type << (along ? " along x" : " along y");
    }
  }
}

// In one homogeneous block the potential above is linear whatever nu; beside air it is not. A
// laminated block (lower half) under air (upper half), driven A = 0 at y = 0, A0 at y = H: the
// field runs along x in both layers with one H_x, so W = D L A0^2 / (2 mu0 (mu_x + 1) H / 2)
// holds the block's mu_r along x. Mirrored about y = x (layers side by side, driven across x)
// the flux runs along y and W takes mu_r along y. LamType 1 and 2 (Mu 200, fill 0.8) give the
// four combinations of along / across the sheets and x / y; the two mu_r differ 32-fold.
TEST(FemmAnisotropic, LaminatedBlockBesideAirTakesEachAxis) {
  for (const int lam_type : {1, 2}) {
    for (const bool mirrored : {false, true}) {
      FemText f = layered_box({0.0, kH / 2, kH}, {1, 2}, true);
      f.blocks = {lam_type == 1 ? block("laminated", kMu, 7.0, 1, kFill)
                                : block("laminated", 7.0, kMu, 2, kFill),
                  fem_block("air", 1.0)};
      if (mirrored) f = transposed(f);
      const std::array<double, 2> axes =
          lam_type == 1 ? std::array{kMuAlong, kMuAcross} : std::array{kMuAcross, kMuAlong};
      const double mu = axes[mirrored ? 1 : 0];  // along the flux
      const double reference = kDepth * kL * kA0 * kA0 / (2 * kMu0 * (mu + 1.0) * kH / 2);
      const SolveResult s = solve_text(f);
      EXPECT_NEAR(s.results.energy, reference, 1e-8 * reference)
          << "LamType " << lam_type << (mirrored ? ", flux along y" : ", flux along x");
    }
  }
}

// Mu_x = 50, Mu_y = 5 (LamType 0, fill 1) in a uniform field prescribed as A = A_1 x + A_2 y on
// the whole boundary, B = (A_2, -A_1) = (0.3, -0.4) T: what the results make of it, H =
// (B_x / (mu0 mu_x), B_y / (mu0 mu_y)), W = V (B_x H_x + B_y H_y) / 2 and mu_r along B =
// |B| / (mu0 |H|) (6.23), all exact in P2.
TEST(FemmAnisotropic, UniformFieldInAnAnisotropicBlock) {
  FemText f;
  f.depth = kDepth;
  f.boundaries = {boundary("field", 0.0, 0.4, 0.3)};
  f.blocks = {block("skewed", 50.0, 5.0, 0, 1.0)};
  f.points = {"0 0 0 0", "0.02 0 0 0", "0.02 0.01 0 0", "0 0.01 0 0"};
  f.segments = {"0 1 -1 1 0 0", "1 2 -1 1 0 0", "2 3 -1 1 0 0", "3 0 -1 1 0 0"};
  f.labels = {"0.01 0.005 1 0.003 0 0 0 1 0"};
  const SolveResult s = solve_text(f);
  const double bx = 0.3, by = -0.4, hx = bx / (kMu0 * 50.0), hy = by / (kMu0 * 5.0);
  const double volume = 0.02 * 0.01 * kDepth, energy = 0.5 * volume * (bx * hx + by * hy);
  EXPECT_NEAR(s.results.energy, energy, 1e-8 * energy);
  EXPECT_NEAR(s.results.coenergy, energy, 1e-8 * energy);  // linear: W' = W
  const double mu_along_b = std::hypot(bx, by) / (kMu0 * std::hypot(hx, hy));
  for (std::size_t e = 0; e < s.results.element_hr.size(); ++e) {
    ASSERT_NEAR(s.results.element_br[e], bx, 1e-9) << e;
    ASSERT_NEAR(s.results.element_bz[e], by, 1e-9) << e;
    ASSERT_NEAR(s.results.element_hr[e], hx, 1e-8 * std::abs(hx)) << e;
    ASSERT_NEAR(s.results.element_hz[e], hy, 1e-8 * std::abs(hy)) << e;
    ASSERT_NEAR(s.results.element_mu_r[e], mu_along_b, 1e-8 * mu_along_b) << e;
  }
}

// The element kernel of an anisotropic law: the residual is K a with K the tangent (the law is
// linear), K is symmetric, and with equal axes it is the isotropic kernel's to rounding.
TEST(FemmAnisotropic, ElementKernelIsLinearAndReducesToTheIsotropicOne) {
  cases::Material skewed, round, round_axes;
  skewed.name = "skewed", round.name = "round", round_axes.name = "round axes";
  skewed.mu_r_axes = std::array{40.0, 3.0};
  round.mu_r = 40.0;
  round_axes.mu_r_axes = std::array{40.0, 40.0};
  const Reluctivity anisotropic(skewed), isotropic(round), equal_axes(round_axes);
  EXPECT_TRUE(anisotropic.anisotropic());
  EXPECT_FALSE(equal_axes.anisotropic());
  for (const auto symmetry : {cases::Symmetry::planar, cases::Symmetry::axisymmetric}) {
    ElementQuadrature q;
    element_quadrature(symmetry, 0.1, 2, {mesh::Point{0.01, 0.0}, {0.013, 0.002}, {0.009, 0.004}},
                       q);
    const double a[6] = {1e-4, -2e-4, 3e-4, 0.5e-4, -1e-4, 2.5e-4};
    double r[6], k[36], r_iso[6], k_iso[36], r_eq[6], k_eq[36];
    element_residual_tangent(q, a, anisotropic, r, k);
    element_residual_tangent(q, a, isotropic, r_iso, k_iso);
    element_residual_tangent(q, a, equal_axes, r_eq, k_eq);
    for (int i = 0; i < 6; ++i) {
      double ka = 0.0;
      for (int j = 0; j < 6; ++j) {
        ka += k[i * 6 + j] * a[j];
        EXPECT_DOUBLE_EQ(k[i * 6 + j], k[j * 6 + i]);
        EXPECT_NEAR(k_eq[i * 6 + j], k_iso[i * 6 + j], 1e-12 * std::abs(k_iso[i * 6 + i]));
      }
      EXPECT_NEAR(r[i], ka, 1e-12 * std::abs(k[i * 6 + i]) * 3e-4);
      EXPECT_NEAR(r_eq[i], r_iso[i], 1e-12 * std::abs(k_iso[i * 6 + i]) * 3e-4);
    }
    // The energy is a r / 2 for a linear law.
    double half_a_r = 0.0;
    for (int i = 0; i < 6; ++i) half_a_r += 0.5 * a[i] * r[i];
    EXPECT_NEAR(element_stored_energy(q, a, anisotropic), half_a_r, 1e-12 * std::abs(half_a_r));
  }
}

// `export` writes an anisotropic material as FEMM's LamType 0 at fill 1 with its Mu_x and Mu_y
// (the fill folded in): read back, the same two mu_r (to the 17 digits written) and the same
// energy as the laminated block it came from.
TEST(FemmAnisotropic, ExportWritesBothPermeabilities) {
  FemText f = layered_box({0.0, kH}, {1}, false);
  f.blocks = {block("laminated", kMu, 1.0, 1, kFill)};
  const cases::Problem problem = cases::parse_femm(f.str(), "laminated.fem");
  const std::string written = cases::write_femm(problem, {});
  EXPECT_THAT(written, ::testing::HasSubstr("<LamType> = 0"));
  const cases::Problem back = cases::parse_femm(written, "back.fem");
  const cases::Material& m = back.materials[back.regions[0].material];
  ASSERT_TRUE(m.mu_r_axes.has_value());
  EXPECT_NEAR((*m.mu_r_axes)[0], kMuAlong, 1e-14 * kMuAlong);
  EXPECT_NEAR((*m.mu_r_axes)[1], kMuAcross, 1e-14 * kMuAcross);
  const double before = solve_problem(problem).results.energy;
  EXPECT_NEAR(solve_problem(back).results.energy, before, 1e-10 * before);
}

// FEMM's axisymmetric solver departs from its planar one (xfemm 35baec4, staticaxi.cpp): a linear
// LamType 2 block is laminated along r there, as LamType 1, and LamType 0 takes f Mu. rheomag
// keeps the planar rule and the manual's (LamType 2 laminated along z) and says what FEMM would
// do (measured side by side in docs/validation.md).
TEST(FemmAnisotropic, AxisymmetricLaminationsNoteWhereFemmDiffers) {
  const auto read = [](const std::string& block_text) {
    FemText f = layered_box({0.0, kH}, {1}, true);
    f.problem = "axisymmetric";
    f.blocks = {block_text};
    return cases::parse_femm(f.str(), "ring.fem");
  };
  const cases::Problem z = read(block("core", 7.0, kMu, 2, kFill));
  const cases::Material& m = z.materials[z.regions[0].material];
  ASSERT_TRUE(m.mu_r_axes.has_value());
  EXPECT_NEAR((*m.mu_r_axes)[0], kMuAcross, 1e-12 * kMuAcross);
  EXPECT_NEAR((*m.mu_r_axes)[1], kMuAlong, 1e-12 * kMuAlong);
  ASSERT_EQ(z.warnings.size(), 1u);
  EXPECT_THAT(z.warnings[0], ::testing::HasSubstr("ring.fem:"));
  EXPECT_THAT(z.warnings[0], ::testing::HasSubstr("laminates a linear block of LamType 2 along r, "
                                                  "as LamType 1 (mu_r 160.2 along r, "));
  // A weakly magnetic block at half fill: FEMM's f Mu = 1 against f Mu + 1 - f = 1.5.
  const cases::Problem half = read(block("filler", 2.0, 2.0, 0, 0.5));
  ASSERT_EQ(half.warnings.size(), 1u);
  EXPECT_THAT(half.warnings[0], ::testing::HasSubstr("takes f Mu (mu_r 1 along r, 1 along z), its "
                                                     "planar solver and rheomag f Mu + 1 - f "
                                                     "(mu_r 1.5 along r, 1.5 along z)"));
  // Iron at fill 0.9 (f Mu 900 against 900.1) and LamType 1: nothing to say.
  EXPECT_TRUE(read(block("iron", 1000.0, 1000.0, 0, 0.9)).warnings.empty());
  EXPECT_TRUE(read(block("sheets", kMu, kMu, 1, kFill)).warnings.empty());
}

// The axisymmetric kernel: a laminated core r < R/2 inside an air shell R/2 < r < R (R = 10 mm,
// 20 mm long), A = 0 on the axis and A0 at r = R, the ends free. The field is axial with one H_z
// (tangential to every interface), B_z = mu0 mu_z H_z in each shell and the flux 2 pi R A0, so
// W = l (2 pi R A0)^2 / (2 mu0 pi (mu_z (R/2)^2 + R^2 - (R/2)^2)) takes the core's mu_r along z:
// across the sheets for LamType 1, along them for LamType 2. A = B r / 2 + c / r is not
// polynomial: P2 converges (LamType 2, mu_z 160: 6.8e-3 at 2 mm elements, 4.6e-5 at 0.5 mm;
// LamType 1 5.7e-7), so 0.5 mm and 2e-4.
TEST(FemmAnisotropic, AxisymmetricCoreTakesItsPermeabilityAlongZ) {
  for (const int lam_type : {1, 2}) {
    FemText f = transposed(layered_box({0.0, kH / 2, kH}, {1, 2}, true));
    f.problem = "axisymmetric";
    for (std::string& label : f.labels) label.replace(label.find(" 0.002 "), 7, " 0.0005 ");
    f.blocks = {
        lam_type == 1 ? block("core", kMu, 7.0, 1, kFill) : block("core", 7.0, kMu, 2, kFill),
        fem_block("air", 1.0)};
    const double mu_z = lam_type == 1 ? kMuAcross : kMuAlong, r_core = kH / 2;
    const double flux = 2 * std::numbers::pi * kH * kA0;
    const double reference =
        kL * flux * flux /
        (2 * kMu0 * std::numbers::pi * (mu_z * r_core * r_core + kH * kH - r_core * r_core));
    const SolveResult s = solve_text(f);
    EXPECT_NEAR(s.results.energy, reference, 2e-4 * reference) << "LamType " << lam_type;
  }
}
