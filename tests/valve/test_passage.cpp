// Unmagnetised passages and minor losses in the valve chain ([[valve.passage]], [[valve.loss]]).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "fluid/passage.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "valve/solved_valve.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag;

namespace {

const std::string kCase = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

/// The annular valve solved once at its 1 A (shared by the tests).
const magnetostatics::SolveResult& solved() {
  static const magnetostatics::SolveResult result =
      magnetostatics::solve_problem(cases::load_case(kCase).problem);
  return result;
}

valve::ValvePoint point(const valve::ValveOptions& options, double flow) {
  const auto& s = solved();
  const fluid::Fluid fluid = valve::case_fluid(cases::load_case(kCase));
  return valve::SolvedValve(*s.solver, s.solution, s.results, fluid, options).point(flow);
}

fluid::Passage passage(fluid::PassageShape shape) {
  fluid::Passage p;
  p.name = "p";
  p.shape = shape;
  return p;
}

}  // namespace

// Reference: Hagen-Poiseuille dp = 128 mu Q L / (pi D^4) for a 6 mm x 40 mm pipe, evaluated
// here by hand; the chain adds exactly it (1e-12) to dp_total and dp_viscous and lists it as a
// "passage" segment; dp_yield is unchanged.
TEST(Passage, PipeAddsHagenPoiseuille) {
  const double q = 2e-6, mu = valve::case_fluid(cases::load_case(kCase)).viscosity;
  const valve::ValveOptions none;
  valve::ValveOptions with;
  auto pipe = passage(fluid::PassageShape::pipe);
  pipe.diameter = 6e-3;
  pipe.length = 40e-3;
  with.passages = {pipe};
  const auto a = point(none, q), b = point(with, q);
  const double hagen_poiseuille = 128.0 * mu * q * 40e-3 / (std::numbers::pi * std::pow(6e-3, 4));
  EXPECT_NEAR(b.dp_total - a.dp_total, hagen_poiseuille, 1e-12 * a.dp_total);
  EXPECT_NEAR(b.dp_viscous - a.dp_viscous, hagen_poiseuille, 1e-12 * a.dp_total);
  EXPECT_NEAR(b.dp_yield, a.dp_yield, 1e-12 * a.dp_total);
  ASSERT_EQ(b.segments.size(), a.segments.size() + 1);
  EXPECT_EQ(b.segments.back().kind, valve::SegmentKind::passage);
  EXPECT_NEAR(b.segments.back().drop.integrated.dp, hagen_poiseuille, 1e-15);
  // Re = rho V D / mu, V = Q / (pi D^2 / 4): 11.4 here (laminar).
  const double rho = valve::case_fluid(cases::load_case(kCase)).density;
  const double re = rho * q / (std::numbers::pi * 9e-6) * 6e-3 / mu;
  EXPECT_NEAR(b.segments.back().reynolds_number / re, 1.0, 1e-12);
}

// Reference: exact laminar annulus (Bird, Stewart & Lightfoot eq. 2.4-16/17):
// Q = pi G R^4 / (8 mu) [(1 - k^4) - (1 - k^2)^2 / ln(1/k)], R outer radius, k = R_in / R,
// written out here for a thick annulus 3..12 mm (no thin-gap approximation): passage_dp must
// give G L within 1e-10. The same formula for the annular_valve's "channel" region (r 19..20 mm,
// z -17..17 mm: the fluid facing the sleeve between the poles) taken from the mesh.
TEST(Passage, AnnulusExactFormulaAlsoFromARegion) {
  const double mu = 0.1, q = 1e-5;
  auto exact_dp = [&](double r_in, double r_out, double length) {
    const double k = r_in / r_out;
    const double bracket = (1 - std::pow(k, 4)) - std::pow(1 - k * k, 2) / std::log(1 / k);
    const double gradient = q * 8.0 * mu / (std::numbers::pi * std::pow(r_out, 4) * bracket);
    return gradient * length;
  };
  auto annulus = passage(fluid::PassageShape::annulus);
  annulus.inner_radius = 3e-3;
  annulus.outer_radius = 12e-3;
  annulus.length = 0.05;
  EXPECT_NEAR(fluid::passage_dp(annulus, mu, q) / exact_dp(3e-3, 12e-3, 0.05), 1.0, 1e-10);

  const double flow = 2e-6;
  const double viscosity = valve::case_fluid(cases::load_case(kCase)).viscosity;
  valve::ValveOptions with;
  auto channel = passage(fluid::PassageShape::annulus);
  channel.region = "channel";
  with.passages = {channel};
  const auto b = point(with, flow), a = point(valve::ValveOptions{}, flow);
  const double k = 19e-3 / 20e-3;
  const double bracket = (1 - std::pow(k, 4)) - std::pow(1 - k * k, 2) / std::log(1 / k);
  const double channel_dp =
      flow * 8.0 * viscosity / (std::numbers::pi * std::pow(20e-3, 4) * bracket) * 34e-3;
  // The thin annulus makes the bracket a difference of nearly equal terms: 1e-7.
  EXPECT_NEAR((b.dp_total - a.dp_total) / channel_dp, 1.0, 1e-7);
}

// Reference: minor loss K rho V^2 / 2 with V = Q / (2 pi R h) the mean velocity in gap_top
// (R = 19.5 mm, h = 1 mm, paper 000), by hand; and with an explicit area.
TEST(Passage, MinorLossAtTheNamedSection) {
  const double q = 5e-6, k = 1.5;
  const double rho = valve::case_fluid(cases::load_case(kCase)).density;
  valve::ValveOptions with;
  with.losses = {{"entrance", k, "gap_top", 0.0, 0.0}, {"exit", 1.0, "", 1e-5, 0.0}};
  const auto a = point(valve::ValveOptions{}, q), b = point(with, q);
  const double v = q / (2.0 * std::numbers::pi * 19.5e-3 * 1e-3);
  const double v_exit = q / 1e-5;
  const double expected = k * rho * v * v / 2.0 + rho * v_exit * v_exit / 2.0;
  EXPECT_NEAR(b.dp_total - a.dp_total, expected, 1e-9 * expected);
  EXPECT_EQ(b.segments.back().kind, valve::SegmentKind::loss);
}

// The TOML format and its errors (names the key / the missing region or section).
TEST(Passage, TomlFormatAndBadInput) {
  std::ifstream in(kCase);
  std::stringstream text;
  text << in.rdbuf();
  const std::string base = text.str().substr(0, text.str().find("\n[valve]"));
  auto options_of = [&](const std::string& valve) {
    return valve::read_valve_options(cases::parse_case(base + "\n[valve]\n" + valve, "valve.toml"));
  };
  const auto options = options_of(
      "[[valve.passage]]\nname = \"port\"\nshape = \"pipe\"\ndiameter = 6e-3\nlength = 0.02\n"
      "[[valve.passage]]\nname = \"channel\"\nshape = \"annulus\"\nregion = \"channel\"\n"
      "[[valve.loss]]\nname = \"in\"\nk = 0.5\nsection = \"port\"\n");
  ASSERT_EQ(options.passages.size(), 2u);
  EXPECT_EQ(options.passages[1].region, "channel");
  ASSERT_EQ(options.losses.size(), 1u);
  EXPECT_EQ(options.losses[0].k, 0.5);
  EXPECT_THROW(options_of("[[valve.passage]]\nname = \"p\"\nshape = \"tube\"\n"), InputError);
  EXPECT_THROW(options_of("[[valve.passage]]\nname = \"p\"\nshape = \"pipe\"\ndiameter = 1e-3\n"),
               InputError);  // no length
  EXPECT_THROW(options_of("[[valve.loss]]\nname = \"l\"\nsection = \"gap_top\"\n"),
               InputError);  // no k
  valve::ValveOptions bad_region;
  auto missing = passage(fluid::PassageShape::annulus);
  missing.region = "no_such_region";
  bad_region.passages = {missing};
  EXPECT_THROW(point(bad_region, 1e-6), InputError);
  valve::ValveOptions off_axis;
  auto pipe = passage(fluid::PassageShape::pipe);
  pipe.region = "channel";  // r 19..20 mm: not a pipe
  off_axis.passages = {pipe};
  EXPECT_THROW(point(off_axis, 1e-6), InputError);
  valve::ValveOptions bad_section;
  bad_section.losses = {{"l", 1.0, "nowhere", 0.0, 0.0}};
  EXPECT_THROW(point(bad_section, 1e-6), InputError);
}
