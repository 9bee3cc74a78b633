#pragma once
// A viscous damper carrying a moving mass on a 5 Hz sinusoid, diagnosed against a user's fitted
// model of it without the mass: the bypass rig's valve as a damper at 0 A (F = R A^2 v,
// c = R A^2 = 3070 N s/m), the baseline a Bingham model fitted on a 2 Hz drive of it and read
// back from its JSON, as `rheomag diagnose --baseline` reads it.

#include <string>

#include "diagnose/diagnose_run.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/greybox.hpp"
#include "test_diagnose_fixture.hpp"

namespace rheomag::test {

/// The bypass rig's valve as a damper at 0 A, with `mass` [kg] moving with the piston.
inline lumped::RigSpec viscous_damper(double mass) {
  auto rig = bypass_rig();
  rig.kind = lumped::RigKind::damper;
  if (mass > 0.0) rig.inertance = mass / (rig.piston_area * rig.piston_area);
  return rig;
}

/// The damper's force coefficient c = R A^2 [N s/m].
inline double viscous_coefficient() {
  const auto rig = viscous_damper(0.0);
  return rig.valve.viscous_resistance * rig.piston_area * rig.piston_area;
}

/// Diagnosis options whose baseline is the Bingham model fitted to the damper without the mass
/// on a 3 s, 2 Hz, 10 mm sinusoid at 500 Hz (seed 3), through its fitted-model JSON.
inline diagnose::DiagnoseOptions viscous_damper_baseline() {
  const auto last_month = make_recording(
      viscous_damper(0.0),
      drive(3.0, 500.0,
            {"displacement=sine:amplitude=0.01,frequency=2", "current=constant:value=0"}),
      2.0, 3);
  const auto fit = identify::fit_greybox(last_month.noisy, "bingham");
  const std::string text = identify::fit_model_json(fit, last_month.noisy.meta).dump();
  diagnose::DiagnoseOptions options;
  options.baseline_model =
      diagnose::ModelBaseline{identify::parse_fit_model_json(text, "model.json"), "model.json"};
  return options;
}

/// Today's recording: the damper with `mass` [kg] on a 2 s, 5 Hz, 5 mm sinusoid at 1 kHz
/// (seed 5).
inline VirtualRecording viscous_damper_at_five_hertz(double mass) {
  return make_recording(
      viscous_damper(mass),
      drive(2.0, 1000.0,
            {"displacement=sine:amplitude=0.005,frequency=5", "current=constant:value=0"}),
      2.0, 5);
}

}  // namespace rheomag::test
