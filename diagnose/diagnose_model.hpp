#pragma once
// The models the diagnosis compares with a recording: the baseline rig of the sidecar (everything
// it states, a calibrated static map from its table or its FE case, and the recording's
// nuisances: a delay between output and drives, the static map's pre-yield smoothness) plus any
// set of candidate physics, each switched on in the lumped rig (lumped/rig_model.hpp) with a few
// named SI parameters.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/enum_names.hpp"
#include "identify/fit_model_json.hpp"
#include "lumped/motion_glitches.hpp"
#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"

namespace rheomag::diagnose {

class Candidate;

/// How the recorder's drive samples act on the rig between samples: a nuisance the baseline
/// calibrates (it picks the convention that fits better), never physics.
enum class DriveSampling {
  linear,  ///< instantaneous samples, linear in between
  held     ///< each sample stands for the interval it begins: the coil drive held (zero-order
           ///< hold), the motion (which cannot step) read at the interval's middle
};

/// "linear" | "held".
inline constexpr EnumNames<DriveSampling, 2> kDriveSamplingNames{
    {{{DriveSampling::linear, "linear"}, {DriveSampling::held, "held"}}}};

/// Largest delay between output and drives the baseline calibrates [samples]: channel skew and
/// a drive recorded as held samples (half a sample) are recording nuisances, not physics.
inline constexpr double kMaxDelaySamples = 2.0;

/// Widest plug switch of the static map the baseline calibrates, as a fraction of the peak flow:
/// a recorder's valve smoother at pre-yield than the Bingham map within this is a nuisance; what
/// lies beyond is left to the pre_yield candidate.
inline constexpr double kMaxPreyieldFraction = 0.03;

/// A drive whose white noise exceeds this fraction of its range is noisy (see kVelocity...).
inline constexpr double kNoisyDrive = 1e-4;

/// Half width [samples] of the cubic Savitzky-Golay filter applied to a noisy velocity
/// (diagnose_noise.hpp); the bandwidth it gives at the recording's rate is reported.
inline constexpr std::size_t kVelocityFilterHalfWidth = 8;

/// Fixed SDIRK2 steps per sample interval in every simulation of the diagnosis
/// (lumped/ode_grid.hpp; 8 in an interval where a drive input steps): the cost is set by the
/// number of samples, not by how often the inputs switch, and the output is a smooth function of
/// the fitted parameters. On the edge-rich dyke1996 record (3 kHz, ~1 100 command edges) this stays
/// within 0.32 % rms of the error-controlled integrator with chamber compliance on, 0.002 % with a
/// field lag (bench_rig_simulation).
inline constexpr int kDiagnosisGridSubsteps = 1;

/// [s] median interval between the sample times `t` (1 for fewer than two samples).
double median_interval(const std::vector<double>& t);

/// One thing the baseline contains, and where it came from (reported as baseline.includes).
struct BaselineItem {
  std::string name;    ///< e.g. "coil_inductance"
  double value = 0.0;  ///< SI (0 for non-numeric items such as the valve case)
  std::string unit;    ///< SI unit of value ("" when dimensionless or not numeric)
  std::string source;  ///< e.g. "sidecar [coil] inductance", with how it is used
};

/// A fitted model (`rheomag fit --json`, read by identify::read_fit_model_json) as the baseline of
/// a diagnosis, and the file it came from (named in messages and in baseline.includes).
struct ModelBaseline {
  identify::FitModel model;
  std::string file;
};

/// One fitted parameter: its SI name, start value and bounds; log-scaled parameters are fitted as
/// log(value / nominal) so that very different magnitudes share one trust region.
struct ParamDef {
  std::string name;
  double nominal = 1.0;
  double lower = 0.0;
  double upper = 1.0;
  bool log_scale = true;
  double typical = 1.0;  ///< linear parameters are fitted as value / typical
  std::string unit;      ///< SI unit of the value ("1" when dimensionless)
};

/// The baseline rig of a recording and the layout of the parameter vector for a set of effects.
class DiagnosisModel {
 public:
  /// Builds the baseline from the sidecar of `rec`, or from `fitted` when given (its simulated
  /// output, parameters held, output scale and offset calibrated; candidates as blocks on its
  /// inputs and output). Throws InputError naming a missing key, or a model of another rig kind
  /// or other drive/output columns than the recording.
  /// With `sampling` held, the coil drive column is a zero-order hold and the motion columns
  /// are read half a sample later (a sidecar rig with a coil drive only; ignored otherwise).
  /// `current_path` false: no path estimate of a noisy current (current_path() stays empty).
  explicit DiagnosisModel(const lumped::Recording& rec, const ModelBaseline* fitted = nullptr,
                          DriveSampling sampling = DriveSampling::linear, bool current_path = true);

  /// True when the stated chambers' oil compliance is not negligible (its viscous lag or the
  /// plug's swing between yields at a flow reversal is a tenth of a sample or more), so that the
  /// baseline is calibrated with and without it.
  bool oil_compliance_optional() const { return oil_compliance_optional_; }
  /// True when the baseline simulates the stated chambers' oil compliance.
  bool oil_compliance() const { return base_.compressibility.has_value(); }
  /// This model with the stated chambers' oil compliance simulated (a copy; unchanged on a coil
  /// bench or a fitted baseline); `fit_gain` [FIT points over the stiff fluid] goes in the report.
  DiagnosisModel with_oil_compliance(double fit_gain) const;

  /// This model under the held convention (a copy: the static map, e.g. a tabulated FE chain,
  /// is not built again); unchanged when the convention cannot apply (can_hold()).
  DiagnosisModel held() const;

  /// The drive sampling convention this model applies.
  DriveSampling sampling() const { return sampling_; }
  /// [samples] shift of the delay's range: -1/2 under the held convention (its reading of the
  /// motion is already half a sample later), 0 otherwise.
  double held_delay_shift() const { return sampling_ == DriveSampling::held ? -0.5 : 0.0; }
  /// True when the held convention can show (a sidecar rig whose recorded coil drive steps:
  /// on a coil drive without steps it would only be half a sample more delay of the motion).
  bool can_hold() const { return !fitted_ && !constant_field_ && coil_drive_steps_; }

  /// Static (calibrated) parameters of the baseline: yield_scale, viscous_resistance (or
  /// viscous_scale of an FE-chain map), force_offset, and the nuisances delay, preyield_flow and
  /// slit_fraction (the table map's knee).
  std::vector<ParamDef> static_params() const;

  /// Number of static parameters that are nuisances (the last ones of static_params()).
  std::size_t nuisance_count() const;

  /// Index of the output delay nuisance in static_params() (and every layout).
  std::size_t delay_index() const { return static_params().size() - nuisance_count(); }

  /// The output delay within its bounds that fits `undelayed` (the model output before its
  /// delay, at the recording's times) best: a scan in tenths of a sample, then the parabola
  /// through the best and its neighbours. Returns the delay [s]; its squared error in `sse`.
  double best_delay(const std::vector<double>& undelayed, std::vector<double> values,
                    double& sse) const;

  /// The full layout: static parameters, then each effect's parameters (Candidate::params).
  std::vector<ParamDef> layout(const std::vector<const Candidate*>& effects) const;

  /// The rig spec for parameter values `values` (in the order of layout(effects)).
  lumped::RigSpec spec(const std::vector<const Candidate*>& effects,
                       const std::vector<double>& values) const;

  /// Shifts `y` (at the recording's times) by the delay in `values`: y(t - delay).
  std::vector<double> delayed(std::vector<double> y, const std::vector<double>& values) const;

  /// Free-run model output at the recording's sample times, shifted by the delay nuisance.
  std::vector<double> predict(const std::vector<const Candidate*>& effects,
                              const std::vector<double>& values) const;

  /// Free-run model value of another column (e.g. the coil current of a voltage-driven rig).
  std::vector<double> predict_column(const std::vector<const Candidate*>& effects,
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
  /// What the baseline contains from the sidecar (or the model it was given).
  const std::vector<BaselineItem>& includes() const { return includes_; }
  /// True when the baseline is a fitted model (ModelBaseline) rather than the sidecar's rig.
  bool fitted_baseline() const { return fitted_ != nullptr; }
  /// Fitted-model baseline: the model's field drive column ("" if none).
  const std::string& field_column() const { return field_column_; }
  /// True when the static map's pre-yield smoothness is calibrated (the flow reverses).
  bool preyield_calibrated() const { return smoothing_nuisance_; }
  /// True when the table map's knee (slit_fraction, lumped/slit_law.hpp) is calibrated.
  bool knee_calibrated() const { return knee_nuisance_; }
  /// Standard deviation of the measured output about its mean (floored at 1e-300).
  double output_spread() const { return output_rms_; }
  /// [s] median sample interval.
  double sample_interval() const { return sample_interval_; }
  /// [m^3/s] largest |piston flow| of the recording (0 on a coil bench).
  double peak_flow() const { return peak_flow_; }
  /// Standard deviation of the white noise on each drive column (SI).
  const std::map<std::string, double>& drive_noise() const { return drive_noise_; }
  /// [Hz] -3 dB bandwidth of the filter applied to a noisy velocity (0: used as recorded).
  double velocity_filter_bandwidth() const { return velocity_filter_bandwidth_; }
  /// The noisy measured coil current's path (current_path.hpp) that drives the states which
  /// remember it (Candidate::follows_current_path); empty when the current is clean.
  const std::vector<double>& current_path() const { return current_path_; }
  /// True unless the model was built without the path estimate (DiagnoseOptions::current_path).
  bool current_path_wanted() const { return current_path_wanted_; }
  /// [A] Smallest swing of the measured current taken as a reversal (0: clean current).
  double current_reversal_band() const { return current_reversal_band_; }
  /// Motion drives whose single-sample acquisition glitches were repaired before the model saw
  /// them (lumped/motion_glitches.hpp): column -> the glitches found.
  const std::map<std::string, lumped::MotionGlitches>& motion_glitches() const {
    return motion_glitches_;
  }
  /// One line per repaired motion drive, for the diagnosis' notes.
  const std::vector<std::string>& motion_glitch_notes() const { return motion_glitch_notes_; }

 private:
  lumped::Recording rec_;
  lumped::RigSpec base_;
  std::string output_;
  std::vector<double> measured_;
  double chamber_volume_ = 2e-5;
  bool chamber_volume_given_ = false;
  bool oil_compliance_optional_ = false;  ///< the oil's compliance may show: calibrated
  std::string oil_compliance_lags_;       ///< its lag and reversal swing, in words
  bool constant_field_ = false;
  double output_rms_ = 1.0;
  double sample_interval_ = 1.0;
  double peak_flow_ = 0.0;
  double velocity_filter_bandwidth_ = 0.0;
  bool smoothing_nuisance_ = false;  ///< the flow reverses: the pre-yield smoothness is calibrated
  bool fe_chain_ = false;            ///< the static map is the FE chain of [valve] case
  bool knee_nuisance_ = false;       ///< a table map with a yield: its knee's shape is calibrated
  DriveSampling sampling_ = DriveSampling::linear;
  bool coil_drive_steps_ = false;  ///< the coil drive moves by a step within one interval
  /// Applies the held convention to the drives (RigSpec::held_drives, motion read later).
  void hold_drives();
  std::shared_ptr<const identify::FitModel> fitted_;  ///< the fitted-model baseline, if any
  std::string field_column_;  ///< fitted baseline: the model's field drive column ("" if none)
  double model_sign_ = 1.0;   ///< fitted baseline: sign of its output's correlation with velocity
  std::vector<BaselineItem> includes_;
  std::map<std::string, double> drive_noise_;
  bool current_path_wanted_ = true;                                ///< see current_path_wanted()
  std::vector<double> current_path_;                               ///< see current_path()
  double current_reversal_band_ = 0.0;                             ///< see current_reversal_band()
  std::map<std::string, lumped::MotionGlitches> motion_glitches_;  ///< see motion_glitches()
  std::vector<std::string> motion_glitch_notes_;                   ///< see motion_glitch_notes()
  /// Replaces the motion drives' single-sample glitches by their neighbours' path.
  void repair_motion_glitches(const std::vector<std::string>& drives);
  /// Estimates the path of a noisy coil current (current_path.hpp) for current_path().
  void noisy_current_path();
  /// The rig of `effects` with `values` simulated on the recording, its current replaced by the
  /// current's path when one of them follows it and the current is noisy.
  lumped::Recording simulate(const std::vector<const Candidate*>& effects,
                             const std::vector<double>& values) const;
  /// Standard deviation of `y` about its mean (floored at 1e-300).
  static double spread(const std::vector<double>& y);
  /// Builds the baseline from a fitted model (diagnose_fitted_baseline.cpp).
  void from_fitted_model(const ModelBaseline& fitted);
  /// Estimates the drives' white noise and smooths a noisy velocity (errors in variables).
  void drive_noise_and_filter();
  /// Output of the fitted-model baseline with `effects` as blocks on its inputs and output.
  std::vector<double> predict_fitted(const std::vector<const Candidate*>& effects,
                                     const std::vector<double>& values) const;
  /// Tabulates the FE chain of [valve] case as the static map (InputError naming it if it fails).
  void chain_map(const std::string& where);
  /// Puts the stated chambers' oil compliance in the baseline when it is not negligible.
  void stiff_or_compliant_chambers();
};

}  // namespace rheomag::diagnose
