// The damper fit's inertance check (GreyboxOptions::min_inertance_gain; docs/damper-model.md, "An
// inertance the drives must show"): the fitted inertance is kept only where it removes at least
// 10 % of the residual energy the fit leaves with it held at 0.
// References and tolerances:
// - real slow sines (UTFSM 25 mm at 0.1 and 0.25 Hz, M. Quiroz 2022): measured 2026-12-05, the
//   inertance removes 2.3 % and is held; the family then predicts 10 mm / 1 Hz / 0 A at 87.0 %
//   (with it free, 193 kg and 69.0 %); asserted: held, and that prediction >= 85 %;
// - a simulated damper with a 40 kg inertance, driven at 1 and 4 Hz with 1 % output noise (an
//   inertial force of up to 63 N): the check keeps it, and the fit finds it within 10 % (the
//   truth it was simulated from);
// - an inertance the user holds is not checked, and the progress counts against the bound
//   greybox_iteration_bound gives (the check's iterations included only when it runs).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "identify/greybox.hpp"
#include "lumped/phenomenological.hpp"
#include "lumped/recording_io.hpp"

namespace {

using rheomag::ProgressEvent;
using rheomag::identify::FittedParameter;
using rheomag::identify::GreyboxFit;
using rheomag::identify::GreyboxOptions;
using rheomag::lumped::PhenoKind;
using rheomag::lumped::Recording;

constexpr double kTwoPi = 6.283185307179586;
constexpr double kTrueInertance = 40.0;  // [kg] (N s^2/m on the damper's force)

const FittedParameter& inertance_of(const GreyboxFit& fit) {
  return fit.params.at(
      static_cast<std::size_t>(rheomag::lumped::pheno_param_index(PhenoKind::damper, "inertance")));
}

/// A damper at 0.5 A driven by 8 mm at 1 Hz plus 2 mm at 4 Hz (500 Hz, 3 s), its force simulated
/// with kTrueInertance and 1 % white noise (seeded).
Recording shaken_damper() {
  Recording rec;
  rec.csv_path = "shaken.csv";
  rec.meta.drive = {"displacement", "velocity", "current"};
  rec.meta.output = "force";
  const double dt = 2e-3;
  for (int k = 0; k < 1500; ++k) {
    const double t = dt * k, w1 = kTwoPi, w2 = 4.0 * kTwoPi;
    rec.t.push_back(t);
    rec.columns["displacement"].push_back(8e-3 * std::sin(w1 * t) + 2e-3 * std::sin(w2 * t));
    rec.columns["velocity"].push_back(8e-3 * w1 * std::cos(w1 * t) + 2e-3 * w2 * std::cos(w2 * t));
    rec.columns["current"].push_back(0.5);
  }
  std::vector<double> truth(rheomag::lumped::pheno_params(PhenoKind::damper).size(), 0.0);
  const std::vector<std::pair<const char*, double>> set = {
      {"yield", 40.0},          {"yield_per_field", 400.0},   {"consistency", 800.0},
      {"flow_index", 1.0},      {"pre_yield_viscous", 5e4},   {"compliance_stiffness", 2e5},
      {"seal_friction", 10.0},  {"seal_presliding", 2e-4},    {"inertance", kTrueInertance},
      {"gas_stiffness", 500.0}, {"field_time_constant", 0.01}};
  for (const auto& [name, value] : set)
    truth[static_cast<std::size_t>(rheomag::lumped::pheno_param_index(PhenoKind::damper, name))] =
        value;
  rec.columns["force"] = std::vector<double>(rec.t.size(), 0.0);
  auto setup = rheomag::lumped::greybox_setup_for(rec, PhenoKind::damper);
  auto force = rheomag::lumped::simulate_pheno(rec, setup, truth);
  double ss = 0.0;
  for (double f : force) ss += f * f;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01 * std::sqrt(ss / force.size()));
  for (double& f : force) f += noise(rng);
  rec.columns["force"] = force;
  return rec;
}

TEST(InertanceCheck, AMassTheDrivesShowIsKeptAndFound) {
  GreyboxOptions options;
  options.starts = 2;
  std::vector<ProgressEvent> events;
  options.progress = [&](const ProgressEvent& e) { events.push_back(e); };
  const GreyboxFit fit = rheomag::identify::fit_greybox(shaken_damper(), "damper", options);
  ASSERT_TRUE(fit.inertance_gain.has_value());
  std::cout << "inertance " << inertance_of(fit).value << " kg, gain " << *fit.inertance_gain
            << ", FIT " << fit.train.fit_percent << " %\n";
  EXPECT_GE(*fit.inertance_gain, 0.1);
  EXPECT_FALSE(inertance_of(fit).fixed);
  EXPECT_TRUE(inertance_of(fit).held_because.empty());
  EXPECT_NEAR(inertance_of(fit).value / kTrueInertance, 1.0, 0.1);
  // The check's iterations are counted after the fit's, against one bound.
  const int bound = rheomag::identify::greybox_iteration_bound("damper", options);
  EXPECT_EQ(bound, 2 * options.max_iterations + options.inertance_check_iterations);
  ASSERT_FALSE(events.empty());
  double done = 0.0;
  for (const ProgressEvent& e : events) {
    EXPECT_EQ(e.total, bound);
    EXPECT_LE(e.done, bound);
    if (e.stage.find("inertance") != std::string::npos) {
      EXPECT_GE(e.done, done);  // after every iteration of the fit
      done = e.done;
    } else {
      done = std::max(done, e.done);
    }
  }
  EXPECT_TRUE(events.back().stage.find("inertance") != std::string::npos) << events.back().stage;
}

TEST(InertanceCheck, AnInertanceTheUserHoldsIsNotChecked) {
  GreyboxOptions options;
  options.starts = 1;
  options.max_iterations = 5;
  options.held = {{"inertance", 20.0}};
  double total = 0.0;
  options.progress = [&](const ProgressEvent& e) { total = e.total; };
  const GreyboxFit fit = rheomag::identify::fit_greybox(shaken_damper(), "damper", options);
  EXPECT_FALSE(fit.inertance_gain.has_value());
  EXPECT_TRUE(inertance_of(fit).fixed);
  EXPECT_EQ(inertance_of(fit).value, 20.0);
  EXPECT_TRUE(inertance_of(fit).held_because.empty());
  EXPECT_EQ(rheomag::identify::greybox_iteration_bound("damper", options), 5);
  EXPECT_EQ(total, 5.0);
}

TEST(InertanceCheck, SlowSinesOfARealDamperHoldItAtZero) {
  const std::string dir = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/";
  if (!std::filesystem::exists(dir + "10mm1Hz0A.csv")) GTEST_SKIP() << "shared data absent";
  std::vector<Recording> slow;
  for (const char* f : {"0x1", "0x25"})
    for (const char* a : {"0", "0x25", "0x5", "0x75", "1"})
      slow.push_back(rheomag::lumped::read_recording(dir + "25mm" + f + "Hz" + a + "A.csv"));
  const std::vector<Recording> faster = {rheomag::lumped::read_recording(dir + "10mm1Hz0A.csv")};
  rheomag::identify::FamilyFitOptions options;
  options.greybox.starts = 2;  // fit-family's default
  const auto family = rheomag::identify::fit_current_dependent(slow, "damper", faster, options);
  ASSERT_TRUE(family.fit.inertance_gain.has_value());
  const FittedParameter& inertance = inertance_of(family.fit);
  std::cout << "inertance gain " << *family.fit.inertance_gain << "; 10 mm / 1 Hz / 0 A predicted "
            << family.predicted.at(0).metrics.fit_percent << " %\n";
  EXPECT_LT(*family.fit.inertance_gain, 0.1);
  EXPECT_TRUE(inertance.fixed);
  EXPECT_EQ(inertance.value, 0.0);
  EXPECT_NE(inertance.held_because.find("residual energy"), std::string::npos);
  EXPECT_GE(family.predicted.at(0).metrics.fit_percent, 85.0);
}

}  // namespace
