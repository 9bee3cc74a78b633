// The damper and brake quantities of the optimiser (force_on, force_off, force_range, torque_on,
// torque_off, mass, torque_per_mass) against the device chains of `rheomag damper` / `rheomag
// brake` and closed forms, and short optimisation runs of the bundled examples
// (cases/optimise_damper.toml, cases/optimise_brake.toml) on a coarse mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"
#include "optimise/evaluate.hpp"
#include "optimise/spec.hpp"
#include "optimise_fixture.hpp"
#include "valve/brake.hpp"
#include "valve/damper.hpp"

using namespace rheomag;
using design::Quantity;

namespace {

constexpr double kPi = std::numbers::pi;

void replace(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// A bundled example on a coarse P1 mesh (1 element across the gap) with `iterations` Ipopt
// iterations, so a test run takes seconds; `extra` is appended to its text.
cases::Case coarse_example(const std::string& name, int iterations, const std::string& extra = "") {
  const std::string path = std::string(RHEOMAG_SOURCE_DIR) + "/cases/" + name + ".toml";
  std::string text = cases::read_input_file(path);
  replace(text, "order = 2", "order = 1");
  replace(text, "min_gap_elements = 4", "min_gap_elements = 1");
  replace(text, "max_iterations = 15", "max_iterations = " + std::to_string(iterations));
  return cases::parse_case(text + extra, path);
}

design::Quantities start_quantities(const cases::Case& c) {
  optimise::OptimiseEvaluator evaluator(c, optimise::read_optimise_spec(c));
  std::vector<double> x;
  for (const auto& v : evaluator.spec().variables) x.push_back(v.initial);
  return evaluator.evaluate(x);
}

}  // namespace

// Reference: valve::DamperChain (what `rheomag damper` prints) on the same case at 1 A and 0 A,
// 0.1 m/s. force_on: same field, 1e-6 (the evaluator's mesh is the same mesher input);
// force_off: zero field both ways, 1e-9; force_range = (F_on - F_gas) / (F_off - F_gas), 1e-6.
TEST(OptimiseDevices, DamperQuantitiesAreTheDamperChains) {
  const auto c = coarse_example("optimise_damper", 3);
  const auto q = start_quantities(c);
  valve::DamperChain chain(c, valve::read_damper_options(c));
  const auto points = chain.evaluate({1.0, 0.0}, {0.1});
  const auto& on = points[0];
  const auto& off = points[1];
  EXPECT_NEAR(q[design::Quantity::force_on], on.force, 1e-6 * on.force);
  EXPECT_NEAR(q[design::Quantity::force_off], off.force, 1e-9 * off.force);
  const double range = (on.force - on.force_gas) / (off.force - off.force_gas);
  EXPECT_NEAR(q[design::Quantity::force_range], range, 1e-6 * range);
  EXPECT_GT(q[design::Quantity::force_range], 5.0);
  EXPECT_FALSE(q.has(design::Quantity::dp_on));  // no [optimise] flow: no valve quantities
}

// Reference: valve::BrakeChain (what `rheomag brake` prints) at 1 A, 50 rad/s (1e-6); at zero
// field the two disc faces' closed form N 2 pi [tau_y (Ro^3 - Ri^3)/3 + mu w (Ro^4 - Ri^4)/(4 h)]
// with Ri = 8, Ro = 40, h = 1 mm (1e-9); mass: the template's rectangles swept about the axis,
// pi (r2^2 - r1^2) (z2 - z1) x density, summed by hand from the stated dimensions (1e-9: the
// mesh's straight triangles integrate 2 pi r dA exactly).
TEST(OptimiseDevices, BrakeQuantitiesAreTheBrakeChainsAndClosedForms) {
  const auto c = coarse_example("optimise_brake", 3);
  const auto q = start_quantities(c);
  valve::BrakeChain chain(c, valve::read_brake_options(c));
  const auto on = chain.evaluate({1.0}, {50.0}).front();
  EXPECT_NEAR(q[design::Quantity::torque_on], on.torque.torque, 1e-6 * on.torque.torque);
  const double tau = chain.fluid().yield_stress(0.0), mu = chain.fluid().viscosity;
  const double ri = 0.008, ro = 0.040, h = 0.001, w = 50.0;
  const double off = 2.0 * 2.0 * kPi *
                     (tau * (std::pow(ro, 3) - std::pow(ri, 3)) / 3.0 +
                      mu * w * (std::pow(ro, 4) - std::pow(ri, 4)) / (4.0 * h));
  EXPECT_NEAR(q[design::Quantity::torque_off], off, 1e-9 * off);

  // disc_brake of cases/optimise_brake.toml: shaft 8, disc 40 x 3, gaps 1, rim clearance 2,
  // coil depth 12, plates 5.5, ring 6 (mm).
  const double mm = 1e-3, steel = 7870.0, aluminium = 2710.0, copper = 8960.0;
  const double fluid = chain.fluid().density;
  const double rs = 8 * mm, rd = 40 * mm, t2 = 1.5 * mm, zg = 2.5 * mm, zp = 8 * mm;
  const double rci = 42 * mm, rco = 54 * mm, rr = 60 * mm;
  const auto ring = [](double r1, double r2, double dz) { return kPi * (r2 * r2 - r1 * r1) * dz; };
  const double mass = aluminium * ring(0, rs, 2 * zp) + steel * ring(rs, rd, 2 * t2) +
                      fluid * 2.0 * ring(rs, rd, zg - t2) + fluid * ring(rd, rci, 2 * zg) +
                      copper * ring(rci, rco, 2 * zg) + steel * 2.0 * ring(rs, rco, zp - zg) +
                      steel * ring(rco, rr, 2 * zp);
  EXPECT_NEAR(q[design::Quantity::mass], mass, 1e-9 * mass);
  EXPECT_NEAR(q[design::Quantity::torque_per_mass], q[design::Quantity::torque_on] / mass,
              1e-9 * on.torque.torque);
}

// A short run (6 Ipopt iterations, coarse mesh) of each bundled example: the optimum is feasible
// (every constraint within the optimiser's feasibility tolerance, in the written case re-checked
// on a fresh mesh) and better than the (feasible) start design by more than 5 %.
TEST(OptimiseDevices, ShortRunsOfTheExamplesImproveAndStayFeasible) {
  for (const char* name : {"optimise_damper", "optimise_brake"}) {
    const auto c = coarse_example(name, 6);
    optimise_fixture::TempDir dir(name);
    const auto result = optimise_fixture::run(c, dir);
    EXPECT_TRUE(result.initial.feasible) << name;
    EXPECT_TRUE(result.optimal.feasible) << name;
    for (const auto& status : result.optimal.constraints)
      EXPECT_TRUE(status.satisfied) << name << " " << status.constraint.where;
    EXPECT_GT(result.optimal.objective, 1.05 * result.initial.objective) << name;
    std::printf("%s: objective %.6g -> %.6g, %d FE solves\n", name, result.initial.objective,
                result.optimal.objective, result.fe_solves);
    EXPECT_TRUE(std::filesystem::exists(result.case_file)) << name;
  }
}

// Bad input: a device quantity without its operating point names the missing key; mass without
// a density names the material, a density of a material the case does not use (a typo) names it
// and lists the case's materials; a damper velocity on a case without [damper] says so.
TEST(OptimiseDevices, MissingOperatingPointsAndDensitiesAreInputErrors) {
  const auto error = [](const cases::Case& c) -> std::string {
    try {
      optimise::OptimiseEvaluator evaluator(c, optimise::read_optimise_spec(c));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  {
    std::string text =
        cases::read_input_file(std::string(RHEOMAG_SOURCE_DIR) + "/cases/optimise_damper.toml");
    replace(text, "velocity = 0.1 ", "# no velocity ");
    EXPECT_NE(error(cases::parse_case(text, "d.toml")).find("velocity"), std::string::npos);
  }
  {
    std::string text =
        cases::read_input_file(std::string(RHEOMAG_SOURCE_DIR) + "/cases/optimise_brake.toml");
    replace(text, "\"Copper\" = 8960.0", "");
    const std::string message = error(cases::parse_case(text, "b.toml"));
    EXPECT_NE(message.find("Copper"), std::string::npos) << message;
    EXPECT_NE(message.find("optimise.density"), std::string::npos) << message;
  }
  {
    std::string text =
        cases::read_input_file(std::string(RHEOMAG_SOURCE_DIR) + "/cases/optimise_brake.toml");
    replace(text, "\"Copper\" = 8960.0", "\"Coper\" = 8960.0");
    const std::string message = error(cases::parse_case(text, "b.toml"));
    EXPECT_NE(message.find("\"Coper\""), std::string::npos) << message;
    EXPECT_NE(message.find("\"Copper\""), std::string::npos) << message;
  }
  {
    const auto c = optimise_fixture::make_case(R"(
[optimise]
objective = "force_on"
velocity = 0.1
[[optimise.variable]]
key = "geometry.pole_length"
lower = 3.0
upper = 8.0
)");
    EXPECT_NE(error(c).find("[damper]"), std::string::npos);
  }
}
