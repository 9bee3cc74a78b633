#pragma once
// The models the diagnosis compares with a recording: the baseline rig of the sidecar (stiff fluid,
// ideal coil, calibrated static map) plus any set of candidate physics, each switched on in the
// lumped rig (lumped/rig_model.hpp) with a few named SI parameters.

#include <string>
#include <vector>

#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"

namespace rheomag::diagnose {

/// Candidate physics, named exactly as in the diagnosis output format.
enum class Effect {
  compressibility,
  fluid_inertia,
  magnetic_hysteresis,
  eddy_currents,
  coil_inductance,
  coil_heating,
  mr_response_time,
  friction
};

/// Name of an effect in the diagnosis output ("compressibility", ...).
std::string effect_name(Effect effect);

/// b2 [1/A] of the diagnosis's Duhem candidate: small, so f(i) = tanh(b2 i) / b2 is the current
/// itself and the saturation stays in the calibrated valve map.
inline constexpr double kDuhemFieldB2 = 0.01;

/// Fixed SDIRK2 steps per sample interval in every simulation of the diagnosis
/// (lumped/ode_grid.hpp; 8 in an interval where a drive input steps): the cost is set by the
/// number of samples, not by how often the inputs switch, and the output is a smooth function of
/// the fitted parameters. On the edge-rich dyke1996 record (3 kHz, ~1 100 command edges) this stays
/// within 0.32 % rms of the error-controlled integrator with chamber compliance on, 0.002 % with a
/// field lag (bench_rig_simulation).
inline constexpr int kDiagnosisGridSubsteps = 1;

/// The Duhem block of the magnetic_hysteresis candidate: field-equivalent current h with
/// dh/dt = a |di/dt| (i - h) + d di/dt (paper 004 eqs. 2-3 with b1 b2 = 1, b2 -> 0).
lumped::DuhemBlock duhem_field(double a, double d);

/// One fitted parameter: its SI name, start value and bounds; log-scaled parameters are fitted as
/// log(value / nominal) so that very different magnitudes share one trust region.
struct ParamDef {
  std::string name;
  double nominal = 1.0;
  double lower = 0.0;
  double upper = 1.0;
  bool log_scale = true;
  double typical = 1.0;  ///< linear parameters are fitted as value / typical
};

/// The baseline rig of a recording and the layout of the parameter vector for a set of effects.
class DiagnosisModel {
 public:
  /// Builds the baseline from the sidecar of `rec`; throws InputError naming a missing key.
  explicit DiagnosisModel(const lumped::Recording& rec);

  /// Effects that can show in this recording (e.g. friction only on a damper's force, coil
  /// effects only when the coil is voltage driven).
  std::vector<Effect> applicable_effects() const;

  /// Static (calibrated) parameters of the baseline: yield_scale, viscous_resistance, ...
  std::vector<ParamDef> static_params() const;

  /// Parameters an effect adds, with starting values scaled to this recording.
  std::vector<ParamDef> effect_params(Effect effect) const;

  /// The full layout: static parameters, then each effect's parameters in order.
  std::vector<ParamDef> layout(const std::vector<Effect>& effects) const;

  /// The rig spec for parameter values `values` (in the order of layout(effects)).
  lumped::RigSpec spec(const std::vector<Effect>& effects, const std::vector<double>& values) const;

  /// Free-run model output at the recording's sample times.
  std::vector<double> predict(const std::vector<Effect>& effects,
                              const std::vector<double>& values) const;

  /// Free-run model value of another column (e.g. the coil current of a voltage-driven rig).
  std::vector<double> predict_column(const std::vector<Effect>& effects,
                                     const std::vector<double>& values,
                                     const std::string& column) const;

  /// The measured output the model explains.
  const std::vector<double>& measured() const { return measured_; }
  /// The recording.
  const lumped::Recording& recording() const { return rec_; }
  /// The baseline spec read from the sidecar (before calibration).
  const lumped::RigSpec& baseline() const { return base_; }
  /// Name of the output column.
  const std::string& output_column() const { return output_; }
  /// Chamber oil volume used by the compressibility candidate [m^3] and whether the sidecar gave
  /// it.
  double chamber_volume() const { return chamber_volume_; }
  bool chamber_volume_given() const { return chamber_volume_given_; }
  /// True when the recording has no coil input and the field is taken as constant.
  bool constant_field() const { return constant_field_; }

 private:
  lumped::Recording rec_;
  lumped::RigSpec base_;
  std::string output_;
  std::vector<double> measured_;
  double chamber_volume_ = 2e-5;
  bool chamber_volume_given_ = false;
  bool constant_field_ = false;
  double output_rms_ = 1.0;
};

}  // namespace rheomag::diagnose
