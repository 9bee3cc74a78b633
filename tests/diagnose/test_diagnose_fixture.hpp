#pragma once
// Virtual-rig recordings with concealed effects for the diagnosis tests: simulated in-process by
// lumped::simulate_rig (truth with noise), plus the noiseless truth for the noise ceiling. The
// sidecar's static map is deliberately 10 % off, as a datasheet map would be.

#include <cstdlib>
#include <iostream>
#include <string>

#include "coupling/rig_chain_map.hpp"
#include "diagnose/diagnose_run.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"
#include "lumped/signals.hpp"

namespace rheomag::test {

/// A concealed-effect recording: noisy data the diagnosis sees, and the noise ceiling.
struct VirtualRecording {
  lumped::Recording noisy;
  double noise_ceiling = 0.0;  ///< FIT% of the noiseless truth against the noisy data
};

/// The bypass rig of paper 001 (piston 4.524e-4 m^2, Bingham map up to 5.8 MPa at 1 A).
inline lumped::RigSpec bypass_rig() {
  lumped::RigSpec s;
  s.kind = lumped::RigKind::bypass_cylinder;
  s.piston_area = 4.524e-4;
  s.valve.yield_current = {0.0, 0.25, 0.5, 0.75, 1.0};
  s.valve.yield_pressure = {0.0, 1.9e6, 3.6e6, 4.9e6, 5.8e6};
  s.valve.viscous_resistance = 1.5e10;
  s.coil.resistance_20c = 8.9;
  return s;
}

/// Drive of `duration` s at `rate` Hz built from `rheomag simulate --signal` texts.
inline lumped::Recording drive(double duration, double rate,
                               std::initializer_list<std::string> signals) {
  lumped::Recording rec;
  rec.t = lumped::uniform_times(duration, rate);
  for (const auto& s : signals) lumped::add_signal(rec, s);
  return rec;
}

/// Simulates `truth` with noise of `sigma` on its output and returns what the diagnosis sees:
/// the noisy recording with a sidecar whose map is 10 % off (yield +10 %, viscous -10 %).
inline VirtualRecording make_recording(lumped::RigSpec truth, const lumped::Recording& in,
                                       double sigma, unsigned seed = 7) {
  const std::string out = lumped::rig_output_column(truth);
  truth = coupling::with_chain_map(truth, in);  // a [valve] case's FE map, tabulated once
  auto clean_spec = truth;
  clean_spec.sensor_noise.clear();
  const auto clean = lumped::simulate_rig(clean_spec, in);
  truth.sensor_noise = {{out, sigma}};
  truth.noise_seed = seed;
  VirtualRecording v;
  v.noisy = lumped::simulate_rig(truth, in);
  v.noise_ceiling = lumped::fit_percent(v.noisy.column(out), clean.column(out));
  for (double& p : v.noisy.meta.valve.yield_pressure) p *= 1.1;
  if (v.noisy.meta.valve.viscous_resistance) *v.noisy.meta.valve.viscous_resistance *= 0.9;
  // A concealed coil inductance is not stated (a stated one is part of the baseline).
  v.noisy.meta.coil.inductance.reset();
  // The sidecar names the chamber volume whether or not the truth had compliance.
  if (truth.kind != lumped::RigKind::coil_bench) v.noisy.meta.rig.chamber_volume = 2e-5;
  v.noisy.meta.sidecar_path = "virtual.toml";
  v.noisy.csv_path = "virtual.csv";
  return v;
}

/// Prints each finding of `d` with its parameters (SI), one line each.
inline void print_findings(const diagnose::Diagnosis& d) {
  for (const auto& f : d.findings) {
    std::cout << "  " << f.effect->name();
    for (std::size_t j = 0; j < f.params.size(); ++j)
      std::cout << " " << f.param_names[j] << "=" << f.params[j];
    std::cout << "\n";
  }
}

/// Prints the diagnosis's FIT against the noise ceiling, its findings and every candidate it
/// scored, one line per forward-selection step (ΔBIC, screened or fitted).
inline void print_selection(const diagnose::Diagnosis& d, double noise_ceiling) {
  std::cout << "baseline FIT " << d.baseline_fit_percent << ", final " << d.final_fit_percent
            << ", ceiling " << noise_ceiling << "\n";
  print_findings(d);
  for (const auto& s : d.candidates)
    std::cout << "  step " << s.step + 1 << " " << s.effect->name() << " dBIC " << s.delta_bic
              << (s.screened ? " screened" : "") << "\n";
}

/// The diagnosis with default options (candidate timings on stderr if RHEOMAG_DIAGNOSE_TRACE set).
inline diagnose::Diagnosis run_diagnosis(const lumped::Recording& rec) {
  diagnose::DiagnoseOptions options;
  if (std::getenv("RHEOMAG_DIAGNOSE_TRACE"))
    options.progress = [](const rheomag::ProgressEvent& e) {
      std::cerr << "diagnose: " << e.stage << " " << e.detail << "\n";
    };
  return diagnose::diagnose(rec, options);
}

}  // namespace rheomag::test
