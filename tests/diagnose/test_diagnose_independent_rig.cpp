// Diagnosis of a recording made by a simulator that shares no code with rheomag
// (scripts/independent-rig.py, Python standard library only: the exact Bingham slit valve, an
// isothermal air pocket, a noisy recorder with channel skew; docs/diagnosis.md, "Recordings from
// an independent simulator"). Reference: the concealed effect the script writes to truth.toml.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "diagnose/diagnose_run.hpp"
#include "lumped/recording_io.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

namespace fs = std::filesystem;

/// Writes the independent simulator's recording `name` into a fresh folder and returns its CSV
/// (`options`: more of the script's options, e.g. a random draw's "--random 40 --seed 7").
fs::path independent_recording(const std::string& name, const std::string& options = "") {
  const fs::path dir =
      fs::temp_directory_path() / ("rheomag_independent_rig_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string command = "python3 '" + std::string(RHEOMAG_SOURCE_DIR) +
                              "/scripts/independent-rig.py' '" + dir.string() + "' --only " + name +
                              " " + options + " > /dev/null";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return dir / (name + ".csv");
}

/// Diagnoses the independent simulator's recording `name` (`options` as for
/// independent_recording) and expects nothing named.
void expect_nothing_named(const std::string& name, const std::string& options) {
  const fs::path csv = independent_recording(name, options);
  const auto d = rheomag::test::run_diagnosis(rheomag::lumped::read_recording(csv.string()));
  rheomag::test::print_findings(d);
  EXPECT_TRUE(d.findings.empty());
  fs::remove_all(csv.parent_path());
}

/// The parameter `param` of the finding named `effect` in `d`, or NaN (with a test failure) if
/// `effect` is not named.
double named_param(const rheomag::diagnose::Diagnosis& d, const std::string& effect,
                   const std::string& param) {
  for (const auto& f : d.findings)
    if (f.effect->name() == effect)
      for (std::size_t j = 0; j < f.param_names.size(); ++j)
        if (f.param_names[j] == param) return f.params[j];
  ADD_FAILURE() << effect << " (" << param << ") not named";
  return std::nan("");
}

/// The derived quantity `name` of the finding named `effect` in `d`, or NaN (with a test failure)
/// if `effect` is not named.
double named_derived(const rheomag::diagnose::Diagnosis& d, const std::string& effect,
                     const std::string& name) {
  for (const auto& f : d.findings)
    if (f.effect->name() == effect)
      for (const auto& q : f.derived)
        if (q.name == name) return q.value;
  ADD_FAILURE() << effect << " (" << name << ") not named";
  return std::nan("");
}

// An air pocket of 4e-7 m^3 (2e-7 per chamber) behind a slit valve whose shape the baseline's
// Bingham line cannot follow (97 % of the final residual is that shape). A first-order field lag
// of 1.4 ms with the output delay moved to 2 samples ahead of the drives (one sample = 1 ms) fits
// part of that shape as a zero-delay smoothing: it lowered BIC and was named before the lag was
// measured net of the delay. The air pocket alone is to be named, within 10 % of the truth
// (measured 2.01e-7 m^3 per chamber, +0.7 %).
TEST(DiagnoseIndependentRig, AirPocketBehindASlitValveIsOnlyCompressibility) {
  const fs::path csv = independent_recording("bypass_air");
  const auto d = rheomag::test::run_diagnosis(rheomag::lumped::read_recording(csv.string()));
  rheomag::test::print_findings(d);
  for (const std::string& note : d.notes) std::cout << "  note: " << note << "\n";
  ASSERT_EQ(d.findings.size(), 1u);
  const auto& f = d.findings.front();
  EXPECT_EQ(f.effect->name(), "compressibility");
  ASSERT_FALSE(f.params.empty());
  EXPECT_EQ(f.param_names.front(), "air_volume");
  EXPECT_NEAR(f.params.front() / 2e-7, 1.0, 0.10);
  fs::remove_all(csv.parent_path());
}

// A random draw (seed 7, draw 13): a 10.6 ms MR response time on the constant-velocity pump,
// 1 kHz, behind a slit valve (the exact Buckingham law, the sidecar's Bingham line 10 % off).
// The Bingham line's missing knee showed as a nearly closed Duhem loop (d = 0.971) beside the
// right lag. With the knee calibrated (nuisance slit_fraction; the truth is a full slit, 1) the
// lag alone is to be named, within 20 % (measured 10.6 ms, final FIT 99.3 %, nothing above the
// noise left; the tolerance covers the lag's trade with the delay nuisance).
TEST(DiagnoseIndependentRig, SlitValveKneeLeavesTheFieldLagAlone) {
  const fs::path csv = independent_recording("random13_mr_response_time", "--random 40 --seed 7");
  const auto d = rheomag::test::run_diagnosis(rheomag::lumped::read_recording(csv.string()));
  rheomag::test::print_findings(d);
  EXPECT_GT(d.nuisance.slit_fraction, 0.8);
  ASSERT_EQ(d.findings.size(), 1u);
  const auto& f = d.findings.front();
  EXPECT_TRUE(f.effect->name() == "mr_response_time" || f.effect->name() == "eddy_currents");
  ASSERT_FALSE(f.params.empty());
  EXPECT_NEAR(f.params.front() / 0.0106, 1.0, 0.20);
  fs::remove_all(csv.parent_path());
}

// A random draw with nothing concealed (seed 7, draw 30): the bypass behind a slit valve.
// Without the knee the baseline named a 2.3e7 Pa s^2/m^3 fluid inertia; nothing is to be named.
TEST(DiagnoseIndependentRig, SlitValveWithNothingConcealedNamesNothing) {
  expect_nothing_named("random30_none", "--random 40 --seed 7");
}

// A random draw with nothing concealed (seed 6, draw 30): a clean bypass whose current levels
// are each reached from one direction (0.26 and 0.34 A from below, 0.10 A from above) through
// steps that rise within about a sample. The previous build named a Duhem loop of half width 0.013
// A whose offset depended on the direction of approach for 5 % of its rms; nothing is to be named.
TEST(DiagnoseIndependentRig, LevelsReachedFromOneDirectionShowNoLoop) {
  expect_nothing_named("random30_none", "--random 40 --seed 6");
}

// A random pair (seed 5, draw 19): a voltage-driven damper whose sidecar states a 0.05 H coil
// (L/R = 10 ms) while the coil has 0.5206 H more, beside a 180 N Coulomb friction. The previous
// build could only name the extra inductance as a field lag behind the stated coil's (105 ms).
// Both are to be named: the inductance beyond the stated one within 10 % (measured 0.531 H,
// +2 %), the friction within 30 % (161 N, -11 %), and nothing else.
TEST(DiagnoseIndependentRig, InductanceBeyondTheStatedCoilBesideFriction) {
  const fs::path csv = independent_recording("random19_pair", "--random 40 --seed 5");
  const auto d = rheomag::test::run_diagnosis(rheomag::lumped::read_recording(csv.string()));
  rheomag::test::print_findings(d);
  EXPECT_EQ(d.findings.size(), 2u);
  EXPECT_NEAR(named_param(d, "coil_inductance", "inductance") / 0.5206, 1.0, 0.10);
  EXPECT_NEAR(named_param(d, "friction", "coulomb_force") / 180.217, 1.0, 0.30);
  fs::remove_all(csv.parent_path());
}

// A random pair (seed 8, draw 39): a damper with 1.72e-6 m^3 of air (8.62e-7 per chamber) and a
// 182 N Coulomb friction. At the first selection step, without the friction, the air and a
// linear pre-yield compliance tie (BIC 3418 against 3434) and the compliance was named: final
// FIT 90.7 %, every bit of the residual above the noise. With the friction in the joint model
// the air fits far better (BIC 1.4e4 lower; final FIT 97.8 %). Both are to be named, the air
// within 15 % per chamber (measured 8.41e-7 m^3, -2 %) and as the derived total over both chambers
// against the simulator's stated total (1.68e-6 m^3), the friction within 30 % (169 N, -7 %).
TEST(DiagnoseIndependentRig, TieBetweenAirAndPreYieldDecidedWithTheFrictionIn) {
  const fs::path csv = independent_recording("random39_pair", "--random 40 --seed 8");
  const auto d = rheomag::test::run_diagnosis(rheomag::lumped::read_recording(csv.string()));
  rheomag::test::print_findings(d);
  for (const std::string& note : d.notes) std::cout << "  note: " << note << "\n";
  EXPECT_EQ(d.findings.size(), 2u);
  EXPECT_NEAR(named_param(d, "compressibility", "air_volume") / (1.72366e-6 / 2), 1.0, 0.15);
  // The simulator states the air of both chambers: the finding's derived total is that one.
  EXPECT_NEAR(named_derived(d, "compressibility", "total_air_volume") / 1.72366e-6, 1.0, 0.15);
  EXPECT_NEAR(named_param(d, "friction", "coulomb_force") / 181.935, 1.0, 0.30);
  fs::remove_all(csv.parent_path());
}

// A random air pocket (seed 6, draw 31): a bypass cylinder at 500 Hz with 7.31e-7 m^3 of air and
// nothing else. A field lag was accepted beside the air at the second selection step; in the
// joint re-fit its time constant fell to 1.89 ms, under one sample interval (2 ms), so the timing
// rules of the acceptance, checked again there, drop it (it was named before). The air alone is
// named, its total over both chambers within 15 % of the simulator's (measured 7.31e-7, +0.0 %).
TEST(DiagnoseIndependentRig, ALagTheJointRefitShrinksBelowASampleIsNotNamed) {
  const fs::path csv = independent_recording("random31_compressibility", "--random 40 --seed 6");
  const auto d = rheomag::test::run_diagnosis(rheomag::lumped::read_recording(csv.string()));
  rheomag::test::print_findings(d);
  ASSERT_EQ(d.findings.size(), 1u);
  EXPECT_NEAR(named_derived(d, "compressibility", "total_air_volume") / 7.30968e-7, 1.0, 0.15);
  bool dropped = false;
  for (const std::string& note : d.notes)
    dropped = dropped || (note.find("accepted in forward selection but in the joint re-fit with a "
                                    "time constant") != std::string::npos);
  EXPECT_TRUE(dropped) << "no note that a lag was dropped in the joint re-fit";
  fs::remove_all(csv.parent_path());
}

}  // namespace
