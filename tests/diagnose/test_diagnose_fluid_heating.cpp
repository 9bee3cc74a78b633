// The fluid_heating candidate (issue 32 point 5) on recordings with a concealed temperature
// history: the valve's dissipation warms the fluid through the recording, its viscosity falls and
// the viscous part of the pressure drifts. The truth's viscosity slope (3 %/K) differs from the
// slope the candidate states (2 %/K, MRF-132DG's Andrade law), so only the viscosity history can
// be recovered, not the temperature itself.
// Acceptance: fluid_heating named (first finding); the fitted viscosity factor at the end of the
// recording within 20 % of the truth's drop (1 - eta_end / eta_0); the final FIT within 2 points
// of the noise ceiling; against coil heating on a voltage-driven coil, coil_heating named and
// fluid_heating not; with no heating, no fluid_heating finding.
// On a real recording (UTFSM 25 mm / 0.5 Hz / 0 A, another lab's damper) given a concealed
// heating differentially (the heated minus the unheated rig model added to the measured force):
// fluid_heating named on the heated recording and not on the original, and the viscous force
// lost by the end within 30 % of the injected (issue 33's real-recording protocol).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "diagnose/candidate.hpp"
#include "diagnose/candidate_registry.hpp"
#include "diagnose/diagnose_model.hpp"
#include "diagnose/diagnose_run.hpp"
#include "lumped/recording_io.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::diagnose::Diagnosis;
using rheomag::diagnose::Finding;
using rheomag::lumped::RigSpec;
using rheomag::test::bypass_rig;
using rheomag::test::drive;
using rheomag::test::make_recording;

constexpr double kTrueSlope = 0.03;  // [1/K] concealed viscosity slope of the truth

/// 40 s of a 1 Hz stroke at 250 Hz with the current stepping between three levels.
rheomag::lumped::Recording long_drive(const std::string& coil_signal) {
  return drive(40.0, 250.0, {"displacement=sine:amplitude=0.025,frequency=1", coil_signal});
}

RigSpec heated_rig() {
  auto truth = bypass_rig();
  rheomag::lumped::FluidHeatingBlock heating;
  heating.thermal_resistance = 0.1;
  heating.thermal_time_constant = 60.0;
  heating.viscosity_slope = kTrueSlope;
  truth.fluid_heating = heating;
  return truth;
}

const Finding* find(const Diagnosis& d, const std::string& name) {
  for (const auto& f : d.findings)
    if (f.effect->name() == name) return &f;
  return nullptr;
}

double param(const Finding& f, const std::string& name) {
  for (std::size_t j = 0; j < f.param_names.size(); ++j)
    if (f.param_names[j] == name) return f.params[j];
  ADD_FAILURE() << "no parameter " << name;
  return 0.0;
}

/// Viscosity over its starting value at the end of `drive_rec` for the heating `block` of `rig`.
double final_viscous_factor(RigSpec rig, const rheomag::lumped::FluidHeatingBlock& block,
                            const rheomag::lumped::Recording& drive_rec) {
  rig.fluid_heating = block;
  rig.sensor_noise.clear();
  const auto rec = rheomag::lumped::simulate_rig(rig, drive_rec);
  return block.viscous_factor(rec.column("fluid_temperature_rise").back());
}

void print(const Diagnosis& d, double ceiling) {
  std::cout << "baseline FIT " << d.baseline_fit_percent << ", final " << d.final_fit_percent
            << ", ceiling " << ceiling << "; knee (slit_fraction) " << d.nuisance.slit_fraction
            << " -> " << d.final_nuisance.slit_fraction << "\n";
  rheomag::test::print_findings(d);
  for (const auto& c : d.candidates)
    std::cout << "  step " << c.step << " " << c.effect->name() << " FIT " << c.fit_percent
              << " dBIC " << c.delta_bic << (c.screened ? " (screened)" : "") << "\n";
  for (const auto& n : d.notes) std::cout << "  note: " << n << "\n";
}

TEST(DiagnoseFluidHeating, ViscosityHistoryOfAConcealedWarmingIsRecovered) {
  const auto in = long_drive("current=steps:levels=0/1/0.5,period=2");
  const auto truth = heated_rig();
  auto v = make_recording(truth, in, 2e4);
  const double true_factor = final_viscous_factor(truth, *truth.fluid_heating, in);
  std::cout << "truth: viscosity at the end " << true_factor << " of its start, rise "
            << v.noisy.column("fluid_temperature_rise").back() << " K\n";
  v.noisy.columns.erase("fluid_temperature_rise");  // the temperature is not recorded
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  ASSERT_FALSE(d.findings.empty());
  EXPECT_EQ(d.findings.front().effect->name(), "fluid_heating");
  const Finding* f = find(d, "fluid_heating");
  ASSERT_TRUE(f);
  rheomag::lumped::FluidHeatingBlock fitted;  // the candidate's stated slope
  fitted.thermal_resistance = param(*f, "thermal_resistance");
  fitted.thermal_time_constant = param(*f, "thermal_time_constant");
  const double fitted_factor = final_viscous_factor(bypass_rig(), fitted, in);
  std::cout << "fitted: viscosity at the end " << fitted_factor << "\n";
  EXPECT_NEAR((1.0 - fitted_factor) / (1.0 - true_factor), 1.0, 0.2);
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
}

TEST(DiagnoseFluidHeating, CoilHeatingIsNotTakenForFluidHeating) {
  // A voltage-driven coil that warms: its current sags and the yield part with it.
  auto truth = bypass_rig();
  truth.driver_mode = rheomag::lumped::DriverMode::voltage;
  truth.voltage_column = "voltage";
  rheomag::lumped::ThermalBlock coil;
  coil.thermal_resistance = 5.0;
  coil.thermal_time_constant = 20.0;
  truth.coil_heating = coil;
  auto v = make_recording(truth, long_drive("voltage=steps:levels=0/8.9/4.45,period=2"), 2e4);
  v.noisy.columns.erase("temperature");
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  ASSERT_FALSE(d.findings.empty());
  EXPECT_EQ(d.findings.front().effect->name(), "coil_heating");
  EXPECT_FALSE(find(d, "fluid_heating"));
}

TEST(DiagnoseFluidHeating, NoFindingWithoutHeating) {
  const auto v =
      make_recording(bypass_rig(), long_drive("current=steps:levels=0/1/0.5,period=2"), 2e4);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  EXPECT_FALSE(find(d, "fluid_heating"));
}

/// [Pa s/m^3] Viscous resistance lost by the end of `drive_rec` in `rig` (its heating block on):
/// the resistance times one minus the viscosity factor reached.
double viscous_loss(const RigSpec& rig, const rheomag::lumped::Recording& drive_rec) {
  return rig.valve.viscous_resistance *
         (1.0 - final_viscous_factor(rig, *rig.fluid_heating, drive_rec));
}

TEST(DiagnoseFluidHeating, RealRecordingWithAConcealedWarming) {
  const std::string csv = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/25mm0x5Hz0A.csv";
  if (!std::filesystem::exists(csv)) GTEST_SKIP() << csv << " not present";
  auto rec = rheomag::lumped::read_csv_samples(csv);
  rec.meta = rheomag::lumped::read_sidecar(std::string(RHEOMAG_SOURCE_DIR) +
                                           "/tests/data/diagnosis/utfsm_damper.toml");
  const auto original = rheomag::test::run_diagnosis(rec);
  print(original, 100.0);
  EXPECT_FALSE(find(original, "fluid_heating"));
  // The concealed warming on top of the original's final model, as that model predicts it
  // (its filtered velocity, delay and calibration): a steady rise of 30 K at the recording's mean
  // |F v|, tau 20 s, viscosity slope 3 %/K: about 20 K and a viscous part
  // about 40 % thinner by the end. A
  // smaller warming (20 K steady) removes only 8 % of this recording's residual energy (its own
  // misfit is 17 %) and is rightly not accepted (the 10 % practical-significance bar).
  const rheomag::diagnose::DiagnosisModel model(rec);
  const auto& force = rec.column("force");
  const auto& v = rec.column("velocity");
  double power = 0.0;  // [W]
  for (std::size_t k = 0; k < v.size(); ++k) power += std::abs(force[k] * v[k]) / v.size();
  auto effects = original.final_fit.effects;
  auto values = original.final_fit.values;
  const auto cold = model.predict(effects, values);
  effects.push_back(&rheomag::diagnose::candidate_named("fluid_heating"));
  values.push_back(30.0 / power * kTrueSlope / rheomag::lumped::kFluidViscosityTemperatureSlope);
  values.push_back(20.0);
  const auto hot = model.predict(effects, values);
  auto heated = rec;
  for (std::size_t k = 0; k < v.size(); ++k) heated.columns["force"][k] += hot[k] - cold[k];
  const auto d = rheomag::test::run_diagnosis(heated);
  print(d, 100.0);
  const Finding* f = find(d, "fluid_heating");
  ASSERT_TRUE(f);
  const RigSpec truth = model.spec(effects, values);
  const RigSpec fitted = model.spec(d.final_fit.effects, d.final_fit.values);
  ASSERT_TRUE(fitted.fluid_heating);
  const double injected = viscous_loss(truth, rec), found = viscous_loss(fitted, rec);
  std::cout << "viscous resistance lost: injected " << injected << ", found " << found
            << "; viscous resistance " << truth.valve.viscous_resistance << " / "
            << fitted.valve.viscous_resistance << "\n";
  EXPECT_NEAR(found / injected, 1.0, 0.3);
}

}  // namespace
