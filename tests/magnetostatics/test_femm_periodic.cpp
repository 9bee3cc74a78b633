// Periodic and antiperiodic boundaries (FEMM BdryType 4 and 5) against the exact field of a
// planar strip carrying a square wave of current: one period solved with periodic sides, half a
// period with antiperiodic sides, and the refusals of pairs that cannot be paired.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "case/femm_import.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/femm_text.hpp"

using namespace rheomag;
using namespace rheomag::magnetostatics;
using rheomag::testing::FemText;
using ::testing::HasSubstr;

namespace {

// Period P along x; current layer 0 < y < h with J = +J0 for x in [0, 0.15 P) and [0.65 P, P),
// -J0 for x in [0.15 P, 0.65 P) (a square wave centred at c = -0.1 P, antiperiodic over P / 2;
// the sides x = 0 and P / 2 are no symmetry lines of the field);
// air up to y = Ht; A = 0 at y = 0, dA/dn = 0 at y = Ht. Depth 1 m.
constexpr double P = 0.1, h = 0.01, Ht = 0.03, J0 = 1e6, c = -0.1 * P;

/// The exact field: J = sum over odd n of j_n cos(k_n (x - c)), j_n = 4 J0 (-1)^((n-1)/2) / (n
/// pi), k_n = 2 pi n / P; each harmonic's a_n(y) solves a'' - k^2 a = -mu0 j_n (layer) or 0
/// (air), a(0) = 0, a'(Ht) = 0, a and a' continuous at h. In decaying exponentials (no
/// cancellation at large k): layer a = p + C e^{k(y-h)} + D e^{-ky}, p = mu0 j / k^2; air
/// a = F (e^{-k(y-h)} + e^{k(y-h) - 2k(Ht-h)}). Odd n up to 2001 (the neglected tail of B falls
/// as n^-2 below 1e-4 of |B|, of the energy as n^-4).
struct Exact {
  struct Harmonic {
    double k, j, p, cc, d, f;
  };
  std::vector<Harmonic> harmonics;

  Exact() {
    for (int n = 1; n <= 2001; n += 2) {
      Harmonic m;
      m.k = 2 * std::numbers::pi * n / P;
      m.j = 4 * J0 * (((n - 1) / 2) % 2 == 0 ? 1.0 : -1.0) / (n * std::numbers::pi);
      m.p = kMu0 * m.j / (m.k * m.k);
      const double e = std::exp(-m.k * h), g2 = std::exp(-2 * m.k * (Ht - h));
      // a(0) = 0: C e + D = -p; a(h): C + D e - F (1 + g2) = -p; a'(h): C - D e - F (g2 - 1) = 0.
      Eigen::Matrix3d a;
      a << e, 1, 0, 1, e, -(1 + g2), 1, -e, -(g2 - 1);
      const Eigen::Vector3d s = a.lu().solve(Eigen::Vector3d(-m.p, -m.p, 0));
      m.cc = s[0];
      m.d = s[1];
      m.f = s[2];
      harmonics.push_back(m);
    }
  }
  /// (a_n(y), a_n'(y)) of one harmonic.
  static std::array<double, 2> profile(const Harmonic& m, double y) {
    if (y < h) {
      const double up = std::exp(m.k * (y - h)), down = std::exp(-m.k * y);
      return {m.p + m.cc * up + m.d * down, m.k * (m.cc * up - m.d * down)};
    }
    const double down = std::exp(-m.k * (y - h)), up = std::exp(m.k * (y - h) - 2 * m.k * (Ht - h));
    return {m.f * (down + up), m.k * m.f * (up - down)};
  }
  /// (B_x, B_y) = (dA/dy, -dA/dx) at (x, y).
  std::array<double, 2> b(double x, double y) const {
    std::array<double, 2> out{0, 0};
    for (const Harmonic& m : harmonics) {
      const auto [a, da] = profile(m, y);
      out[0] += da * std::cos(m.k * (x - c));
      out[1] += a * m.k * std::sin(m.k * (x - c));
    }
    return out;
  }
  /// Energy of one period per metre of depth: W = 1/2 integral J A = sum (P / 4) j_n integral_0^h
  /// a_n dy.
  double energy_per_period() const {
    double w = 0;
    for (const Harmonic& m : harmonics) {
      const double e = std::exp(-m.k * h);
      w += P / 4 * m.j * (m.p * h + (m.cc + m.d) * (1 - e) / m.k);
    }
    return w;
  }
};

/// The strip from x = 0 to `width` (P: one period; P / 2: half of it), with the current blocks
/// cut at the x positions of the square wave. Its two sides are each two segments (current
/// layer, air): two pairs named "layer" and "air" of BdryType `type` (0 = no condition on the
/// sides). The pairing follows the domain (FEMM's rule: both edges run with the domain on their
/// left, the first's start pairs with the second's end), not the direction the file writes a
/// segment in: the right layer segment runs upwards, the right air segment downwards.
/// `right_top` moves the right side's top point (a mismatched pair).
FemText strip(double width, int type, double right_top = Ht) {
  FemText f;
  f.blocks = {rheomag::testing::fem_block("air", 1.0),
              rheomag::testing::fem_block("plus", 1.0, 0.0, J0 * 1e-6),
              rheomag::testing::fem_block("minus", 1.0, 0.0, -J0 * 1e-6)};
  f.boundaries = {rheomag::testing::fem_boundary("ground", 0, 0.0)};
  if (type != 0)
    for (const char* name : {"layer", "air"})
      f.boundaries.push_back(rheomag::testing::fem_boundary(name, type, 0.0));
  std::vector<double> xs{0.0, 0.15 * P};
  if (width > 0.65 * P) xs.push_back(0.65 * P);
  xs.push_back(width);
  const int n = static_cast<int>(xs.size());
  auto point = [&](double x, double y) {
    f.points.push_back(std::to_string(x) + " " + std::to_string(y) + " 0 0");
  };
  for (double x : xs) point(x, 0);  // 0 .. n-1
  for (double x : xs) point(x, h);  // n .. 2n-1
  point(0, Ht);                     // 2n
  point(width, right_top);          // 2n + 1
  auto segment = [&](int p, int q, int marker) {
    f.segments.push_back(std::to_string(p) + " " + std::to_string(q) + " -1 " +
                         std::to_string(marker) + " 0 0");
  };
  const int side = type == 0 ? 0 : 2;
  segment(0, n, side);                               // left, layer
  segment(n, 2 * n, side == 0 ? 0 : 3);              // left, air
  segment(n - 1, 2 * n - 1, side);                   // right, layer
  segment(2 * n + 1, 2 * n - 1, side == 0 ? 0 : 3);  // right, air
  for (int i = 0; i + 1 < n; ++i) {
    segment(i, i + 1, 1);          // bottom: A = 0
    segment(n + i, n + i + 1, 0);  // top of the layer
  }
  for (int i = 1; i + 1 < n; ++i) segment(i, n + i, 0);  // block cuts
  segment(2 * n, 2 * n + 1, 0);                          // top: dA/dn = 0
  auto label = [&](double x, double y, int block) {
    f.labels.push_back(std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(block) +
                       " 0.0015 0 0 0 1 0");
  };
  for (int i = 0; i + 1 < n; ++i) {
    const double mid = 0.5 * (xs[i] + xs[i + 1]);
    label(mid, h / 2, mid < 0.15 * P || mid > 0.65 * P ? 2 : 3);
  }
  label(width / 2, (h + Ht) / 2, 1);
  return f;
}

SolveResult solve_text(const std::string& text) {
  return solve_problem(cases::parse_femm(text, "strip.fem"));
}

/// The InputError message of reading `text`, or "" when it reads.
std::string error_of(const std::string& text) {
  try {
    cases::parse_femm(text, "strip.fem");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const double kPoints[][2] = {{0.01, 0.005}, {0.045, 0.002}, {0.002, 0.015}, {0.04, 0.025}};

}  // namespace

// One period with periodic sides and half a period with antiperiodic sides against the exact
// series solution: energy within 0.05 %, B at points in the layer and in the air within 0.5 % of
// mu0 J0 h (P2 on a 1.5 mm mesh). The two models agree with each other: half the energy, the same
// B at points of the half period. With no condition on the sides (dA/dn = 0) B_y next to a side
// is off by more than five times that tolerance: the pairing is what makes the answer right.
TEST(FemmPeriodic, StripWithSquareWaveCurrentIsExact) {
  const Exact exact;
  const double w_exact = exact.energy_per_period();
  const double b_scale = kMu0 * J0 * h;  // the order of |B|

  const SolveResult periodic = solve_text(strip(P, 4).str());
  EXPECT_LT(periodic.solver->dofs().gauge_node, 0);  // A = 0 at the bottom fixes it
  EXPECT_TRUE(periodic.solver->dofs().constrained());
  EXPECT_NEAR(periodic.results.energy, w_exact, 5e-4 * w_exact);

  const SolveResult anti = solve_text(strip(P / 2, 5).str());
  EXPECT_TRUE(anti.solver->dofs().constrained());
  EXPECT_NEAR(anti.results.energy, w_exact / 2, 5e-4 * w_exact / 2);
  EXPECT_NEAR(anti.results.energy, periodic.results.energy / 2, 5e-4 * w_exact / 2);

  for (const auto& [x, y] : kPoints) {
    const std::array<double, 2> e = exact.b(x, y);
    std::array<double, 2> bp{}, ba{};
    ASSERT_TRUE(flux_density_at(*periodic.solver, periodic.solution, {x, y}, -1, bp));
    EXPECT_NEAR(bp[0], e[0], 5e-3 * b_scale) << "periodic B_x at " << x << ", " << y;
    EXPECT_NEAR(bp[1], e[1], 5e-3 * b_scale) << "periodic B_y at " << x << ", " << y;
    if (x < P / 2) {
      ASSERT_TRUE(flux_density_at(*anti.solver, anti.solution, {x, y}, -1, ba));
      EXPECT_NEAR(ba[0], e[0], 5e-3 * b_scale) << "antiperiodic B_x at " << x << ", " << y;
      EXPECT_NEAR(ba[1], e[1], 5e-3 * b_scale) << "antiperiodic B_y at " << x << ", " << y;
    }
  }

  // Next to the side x = 0, where the pairing matters most: periodic exact, dA/dn = 0 far off.
  const std::array<double, 2> side = exact.b(0.0005, h / 2);
  std::array<double, 2> bp{}, bn{};
  ASSERT_TRUE(flux_density_at(*periodic.solver, periodic.solution, {0.0005, h / 2}, -1, bp));
  EXPECT_NEAR(bp[1], side[1], 5e-3 * b_scale);
  const SolveResult neumann = solve_text(strip(P, 0).str());
  ASSERT_TRUE(flux_density_at(*neumann.solver, neumann.solution, {0.0005, h / 2}, -1, bn));
  EXPECT_GT(std::abs(bn[1] - side[1]), 5 * 5e-3 * b_scale);
}

// Without the A = 0 ground edge the periodic strip's A is fixed only up to a constant (pinned at
// one non-slave node); the antiperiodic half period is determined by its pairs alone. Energy and
// B stay those of the grounded models: the exact field has A(0) = 0 only through the ground, so
// this compares against the grounded solve's gauge-free quantities.
TEST(FemmPeriodic, PairsWithoutDirichletEdgeAreGaugeFree) {
  FemText periodic = strip(P, 4), anti = strip(P / 2, 5);
  // Make "ground" a mixed edge with c0 = 0 (FEMM's dA/dn = 0): no prescribed A left.
  periodic.boundaries[0] = anti.boundaries[0] =
      rheomag::testing::fem_boundary("ground", 2, 0.0, 0.0, 0.0);
  const SolveResult sp = solve_text(periodic.str());
  const SolveResult sa = solve_text(anti.str());
  EXPECT_GE(sp.solver->dofs().gauge_node, 0);
  EXPECT_LT(sa.solver->dofs().gauge_node, 0);  // antiperiodic pairs exclude the constant
  // The square wave has no mean: dA/dn = 0 at y = 0 changes the exact field, but both models
  // carry the same one (the half period is the full period's antiperiodic half).
  EXPECT_NEAR(sa.results.energy, sp.results.energy / 2, 1e-3 * sp.results.energy);
  for (const auto& [x, y] : kPoints) {
    if (x >= P / 2) continue;
    std::array<double, 2> bp{}, ba{};
    ASSERT_TRUE(flux_density_at(*sp.solver, sp.solution, {x, y}, -1, bp));
    ASSERT_TRUE(flux_density_at(*sa.solver, sa.solution, {x, y}, -1, ba));
    EXPECT_NEAR(ba[0], bp[0], 5e-3 * kMu0 * J0 * h);
    EXPECT_NEAR(ba[1], bp[1], 5e-3 * kMu0 * J0 * h);
  }
}

// Pairs that cannot be paired are refused by name: edges of different lengths, a property on
// three edges, a segment paired with an arc.
TEST(FemmPeriodic, UnpairableEdgesAreRefusedByName) {
  const std::string lengths = error_of(strip(P, 4, 0.9 * Ht).str());
  EXPECT_THAT(lengths, HasSubstr("periodic boundary 'air'"));
  EXPECT_THAT(lengths, HasSubstr("different lengths"));
  FemText three = strip(P, 4);
  three.segments.back() = "8 9 -1 3 0 0";  // the top edge also carries "air"
  const std::string count = error_of(three.str());
  EXPECT_THAT(count, HasSubstr("boundary 'air'"));
  EXPECT_THAT(count, HasSubstr("3 edge(s)"));
  FemText mixed = strip(P, 5);
  mixed.segments[3] = "9 7 -1 0 0 0";      // right air side: no condition, ...
  mixed.arcs.push_back("9 7 10 1 3 0 0");  // ... an arc carries "air" instead
  const std::string kinds = error_of(mixed.str());
  EXPECT_THAT(kinds, HasSubstr("antiperiodic boundary 'air'"));
  EXPECT_THAT(kinds, HasSubstr("segment with an arc"));
}

// From the command line: a mismatched pair exits with 2 and names the boundary.
TEST(FemmPeriodic, CliRefusesMismatchedPairWithExitTwo) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::filesystem::path model = dir / ("periodic_" + std::to_string(::getpid()) + ".fem");
  const std::filesystem::path err = dir / ("periodic_" + std::to_string(::getpid()) + ".err");
  std::ofstream(model) << strip(P, 4, 0.9 * Ht).str();
  const std::string command =
      std::string(RHEOMAG_BINARY) + " solve " + model.string() + " >/dev/null 2>" + err.string();
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream in(err);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  EXPECT_THAT(text, HasSubstr("periodic boundary 'air'"));
  std::filesystem::remove(model);
  std::filesystem::remove(err);
}

// FEMM's default block label (flag column bit 2) fills every area without a label, and may lie
// outside the geometry (xfemm's femmcli_antiperiodicBC_flux.fem has one): the strip with its air
// label replaced by a default air label far outside solves to the same energy.
TEST(FemmPeriodic, DefaultLabelFillsUnlabelledAreas) {
  const SolveResult labelled = solve_text(strip(P, 4).str());
  FemText f = strip(P, 4);
  f.labels.back() = "1 1 1 0.0015 0 0 0 1 2";  // air, default, at (1, 1) m: outside
  const SolveResult by_default = solve_text(f.str());
  EXPECT_NEAR(by_default.results.energy, labelled.results.energy, 1e-9 * labelled.results.energy);
  FemText plain = strip(P, 4);
  plain.labels.back() = "1 1 1 0.0015 0 0 0 1 0";  // the same label without the default bit
  EXPECT_THAT(error_of(plain.str()), ::testing::IsEmpty());  // reads, ...
  EXPECT_THROW(solve_text(plain.str()), InputError);         // ... but lies outside every area
}
