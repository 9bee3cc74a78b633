// Yield-stress models and the [rheology] reader of materials TOML files.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "fluid/fluid.hpp"
#include "fluid/yield_stress.hpp"

using namespace rheomag::fluid;

// Reference: interpolation conditions (exact at the nodes, 1e-12), monotonicity (Fritsch-Carlson:
// a monotone table gives a monotone interpolant, checked on 2001 samples) and the stated
// constant extrapolation beyond the table.
TEST(YieldStressTable, InterpolatesMonotonically) {
  const std::vector<double> b{0.0, 0.1, 0.2, 0.4, 0.6, 0.8, 1.0};
  const std::vector<double> tau{0.0, 2e3, 8e3, 25e3, 40e3, 41e3, 41.5e3};
  const YieldStressTable table(b, tau);
  for (std::size_t i = 0; i < b.size(); ++i) EXPECT_NEAR(table(b[i]), tau[i], 1e-12 * 4e4);
  double previous = -1.0;
  for (int i = 0; i <= 2000; ++i) {
    const double value = table(1.2 * i / 2000.0);
    EXPECT_GE(value, previous);
    previous = value;
  }
  EXPECT_EQ(table(1.5), 41.5e3);
  EXPECT_EQ(table(-0.4), table(0.4));  // |B|
  // Three points: linear interpolation.
  const YieldStressTable three({0.0, 0.5, 1.0}, {0.0, 10.0, 30.0});
  EXPECT_NEAR(three(0.75), 20.0, 1e-12);
}

TEST(YieldStressTable, RejectsBadTables) {
  EXPECT_THROW(YieldStressTable({0.0, 0.2, 0.1, 0.3}, {0, 1, 2, 3}), rheomag::InputError);
  EXPECT_THROW(YieldStressTable({0.0, 0.1, 0.2, 0.3}, {0, 5, 2, 3}), rheomag::InputError);
  EXPECT_THROW(YieldStressTable({0.0, 0.1}, {0.0}), rheomag::InputError);
  EXPECT_THROW(YieldStressTable({0.0}, {0.0}), rheomag::InputError);
  EXPECT_THROW(YieldStressTable({0.0, 0.1, 0.2}, {0.0, -1.0, 2.0}), rheomag::InputError);
  try {
    YieldStressTable({0.0, 0.1, 0.2, 0.3}, {0, 5, 2, 3});
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("monotone"), std::string::npos) << e.what();
  }
}

// Reference: the MRF-132DG polynomial (issue 3; 52.962B^4 - 176.51B^3 + 158.79B^2 + 13.708B +
// 0.1442 kPa). The clamp point must be a zero of the derivative (|p'| < 1e-6 of its scale) with
// p'' < 0, near 1.16 T (issue), and values beyond it are held.
TEST(YieldStressPolynomial, Mrf132dgClampedAtItsMaximum) {
  const auto fit = YieldStressPolynomial::mrf132dg();
  const double b = fit.clamp_point();
  auto p = [](double x) {
    return 1e3 * ((((52.962 * x - 176.51) * x + 158.79) * x + 13.708) * x + 0.1442);
  };
  const double dp = 1e3 * (4 * 52.962 * b * b * b - 3 * 176.51 * b * b + 2 * 158.79 * b + 13.708);
  const double d2p = 1e3 * (12 * 52.962 * b * b - 6 * 176.51 * b + 2 * 158.79);
  EXPECT_LT(std::abs(dp), 1e-6 * 1e3 * 158.79);
  EXPECT_LT(d2p, 0.0);
  EXPECT_NEAR(b, 1.16, 0.01);
  EXPECT_NEAR(fit(0.5), p(0.5), 1e-9);
  EXPECT_NEAR(fit(1.0), p(1.0), 1e-9);
  EXPECT_NEAR(fit(1.4), p(b), 1e-9 * p(b));
  EXPECT_NEAR(fit(1.8), p(b), 1e-9 * p(b));
  EXPECT_LT(p(1.4), p(b));  // the raw polynomial drops past its maximum (and rises again later)
  // A user limit below the maximum wins.
  EXPECT_EQ(YieldStressPolynomial({0.0, 1e3}, 0.7)(2.0), 700.0);
  EXPECT_THROW(YieldStressPolynomial({0.0, -5.0, 1.0}), rheomag::InputError);
}

// Reference: Carlson's formulas written out (tau_y = 271700 C phi^1.5239 tanh(6.33e-3 H[kA/m]),
// B = 1.91 phi^1.133 (1 - exp(-10.97 mu0 H)) + mu0 H); round trip H -> B -> H within 1e-9.
TEST(CarlsonYieldStress, FormulasAndInverse) {
  const CarlsonYieldStress model(0.32, 1.0);
  const double h = 100e3;
  EXPECT_NEAR(model.of_field_strength(h),
              271700.0 * std::pow(0.32, 1.5239) * std::tanh(6.33e-3 * 100.0), 1e-9);
  const double mu0 = rheomag::kMu0;
  EXPECT_NEAR(model.flux_density(h),
              1.91 * std::pow(0.32, 1.133) * (1 - std::exp(-10.97 * mu0 * h)) + mu0 * h, 1e-14);
  for (double hh : {1e3, 5e4, 3e5}) {
    EXPECT_NEAR(model.field_strength(model.flux_density(hh)) / hh, 1.0, 1e-9);
  }
  EXPECT_NEAR(model(model.flux_density(h)), model.of_field_strength(h), 1e-6);
  EXPECT_EQ(model(0.0), 0.0);
  EXPECT_THROW(CarlsonYieldStress(0.0), rheomag::InputError);
}

// Reference: the scale factor multiplies the curve (definition).
TEST(YieldStressCurve, ScaleMultiplies) {
  const YieldStressCurve curve(YieldStressPolynomial::mrf132dg());
  EXPECT_NEAR(curve.scaled(1.3)(0.6), 1.3 * curve(0.6), 1e-9);
  EXPECT_EQ(YieldStressCurve()(1.0), 0.0);
  EXPECT_THROW(curve.scaled(0.0), rheomag::InputError);
}

TEST(FluidToml, ParsesTheThreeModels) {
  const auto table = parse_fluid(R"(
name = "test fluid"
[rheology]
viscosity = 0.106
density = 2850
[rheology.yield_stress]
model = "table"
b = [0.0, 0.2, 0.4, 0.57, 0.8]
tau = [0.0, 15e3, 45e3, 68e3, 80e3]
)",
                                 "a.toml");
  EXPECT_EQ(table.name, "test fluid");
  EXPECT_EQ(table.viscosity, 0.106);
  EXPECT_EQ(table.density, 2850.0);
  EXPECT_EQ(table.flow_index, 1.0);
  EXPECT_NEAR(table.yield_stress(0.57), 68e3, 1e-6);
  const auto poly = parse_fluid(R"(
[rheology]
viscosity = 0.112
density = 3090
yield_stress_scale = 0.9
[rheology.yield_stress]
model = "polynomial"
coefficients = [144.2, 13708.0, 158790.0, -176510.0, 52962.0]
)",
                                "b.toml");
  EXPECT_NEAR(poly.yield_stress(0.5), 0.9 * YieldStressPolynomial::mrf132dg()(0.5), 1e-6);
  const auto carlson = parse_fluid(R"(
[rheology]
viscosity = 0.09
density = 3000
flow_index = 0.8
[rheology.yield_stress]
model = "carlson"
volume_fraction = 0.3
)",
                                   "c.toml");
  EXPECT_EQ(carlson.flow_index, 0.8);
  EXPECT_NEAR(carlson.yield_stress(0.5), CarlsonYieldStress(0.3)(0.5), 1e-9);
  // The pair form used by cases/materials: yield_stress = [[B, tau], ...], name in [material].
  const auto pairs = parse_fluid(R"(
[material]
name = "pairs"
[rheology]
viscosity = 0.1
density = 3000
yield_stress = [[0.0, 0], [0.5, 30e3], [1.0, 50e3]]
)",
                                 "d.toml");
  EXPECT_EQ(pairs.name, "pairs");
  EXPECT_NEAR(pairs.yield_stress(0.75), 40e3, 1e-9);
}

// Errors must name the file and the key (or line).
TEST(FluidToml, ErrorsNameFileAndKey) {
  auto message = [](const char* text) {
    try {
      parse_fluid(text, "bad.toml");
    } catch (const rheomag::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("[rheology]\ndensity = 3000\n").find("viscosity"), std::string::npos);
  EXPECT_NE(message("[rheology]\nviscosity = -1\ndensity = 3000\n").find("line 2"),
            std::string::npos);
  EXPECT_NE(message("[other]\n").find("[rheology]"), std::string::npos);
  EXPECT_NE(message("[rheology\n").find("bad.toml"), std::string::npos);
  const std::string unmonotone = message(
      "[rheology]\nviscosity = 0.1\ndensity = 3000\n[rheology.yield_stress]\nmodel = "
      "\"table\"\nb = [0, 0.1, 0.2, 0.3]\ntau = [0, 5, 2, 3]\n");
  EXPECT_NE(unmonotone.find("monotone"), std::string::npos) << unmonotone;
  EXPECT_NE(unmonotone.find("bad.toml"), std::string::npos);
  const std::string pairs = message(
      "[rheology]\nviscosity = 0.1\ndensity = 3000\nyield_stress = [[0, 0], [0.5, 9], [1, 3]]\n");
  EXPECT_NE(pairs.find("line 4"), std::string::npos) << pairs;
  EXPECT_NE(pairs.find("monotone"), std::string::npos) << pairs;
  EXPECT_NE(message("[rheology]\nviscosity = 0.1\ndensity = 3000\n[rheology.yield_stress]\n"
                    "model = \"magic\"\n")
                .find("magic"),
            std::string::npos);
  EXPECT_THROW(read_fluid("/nonexistent/fluid.toml"), rheomag::InputError);
}

// Every bundled materials file that has a [rheology] table must parse and give a yield stress
// that does not decrease with B (0 to 1.5 T).
TEST(FluidToml, BundledMaterialsParse) {
  const std::filesystem::path dir = std::filesystem::path(RHEOMAG_SOURCE_DIR) / "cases/materials";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no cases/materials yet";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".toml") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    if (text.str().find("[rheology") == std::string::npos) continue;
    const Fluid fluid = read_fluid(entry.path());
    ++count;
    double previous = -1.0;
    for (int i = 0; i <= 150; ++i) {
      const double tau = fluid.yield_stress(0.01 * i);
      EXPECT_GE(tau, previous) << entry.path();
      previous = tau;
    }
  }
  if (count == 0) GTEST_SKIP() << "no materials file with [rheology] yet";
}
