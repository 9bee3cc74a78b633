#pragma once
// Grey-box (physical) identification: Bingham, LuGre, modified Bouc-Wen, Maxwell, Dahl,
// bi-viscous, hyperbolic tangent and the physically based damper model fitted to a recording (or
// jointly to several recordings of one device) with Ceres (bounded trust region, automatic
// differentiation through a fixed-step RK4 simulation), multi-start, and standard errors from the
// Jacobian.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/progress.hpp"
#include "lumped/metrics.hpp"
#include "lumped/pheno_simulation.hpp"
#include "lumped/phenomenological.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// Share of the residual energy a damper's fitted inertance must remove to be kept (see
/// GreyboxOptions::min_inertance_gain).
inline constexpr double kMinInertanceGain = 0.1;

/// Options of a grey-box fit.
struct GreyboxOptions {
  std::optional<lumped::SampleRange> train;  ///< samples to fit on; whole recording if empty
  int starts = 4;  ///< multi-start: number of starting points (first = nominal)
  /// Parameters held at a value instead of fitted (name, SI value; e.g. an inertance known from
  /// the device's geometry): reported as held, used by every start. InputError for a name the
  /// model does not have or a value outside the parameter's bounds.
  std::vector<std::pair<std::string, double>> held;
  /// The first start's parameter values (SI, in the model's parameter order, clamped into the
  /// bounds; held parameters keep their nominal value) instead of the nominal guess, e.g. a fit of
  /// other recordings of the device; empty: the nominal guess. The other starts are unchanged.
  std::vector<double> start;
  unsigned seed = 1;        ///< seed of the perturbed starting points
  int max_iterations = 60;  ///< Levenberg-Marquardt iterations per start
  int threads = 0;          ///< threads (0: one per core); same fit if starts >= it
  double max_substep = lumped::kPhenoMaxSubstep;  ///< [s] largest RK4 substep in the fit
  double exponential_step = 5e-3;  ///< [s] largest step of the damper model's integrator
  double bouc_wen_step = 1e-3;     ///< [s] largest step of the Bouc-Wen model's integrator
  double eps_fraction = 1e-3;      ///< sign/|.| regularisation width as a fraction of rms motion
  /// [s] The motion drives are read this much later (lumped::GreyboxSetup::motion_lead).
  double motion_lead = 0.0;
  /// Family fits: each recording's factor on the viscosity-scaled parameters
  /// (scales_with_viscosity), held during the fit; empty: 1 for every recording.
  std::vector<double> viscous_factors;
  /// Damper model: the inertance is held at 0 when, fitted, it removes less than this share of
  /// the residual energy the fit leaves with it held (a moving mass the training drives do not
  /// show; the diagnosis' 10 % rule for an effect); 0: always fitted. Not checked when held.
  double min_inertance_gain = kMinInertanceGain;
  /// Levenberg-Marquardt iterations of that check's refit (inertance at 0, from the fit).
  int inertance_check_iterations = 20;
  /// Reports the fit's Levenberg-Marquardt iterations (summed over the starts, out of the bound
  /// starts x max_iterations); may be called from several threads at once.
  ProgressCallback progress;
};

/// One fitted parameter in SI units (units spelled out for this recording's columns).
struct FittedParameter {
  std::string name;
  std::string unit;
  double value = 0.0;
  std::optional<double> standard_error;  ///< empty when held fixed or not identifiable
  /// Cluster-robust standard error, each training recording one cluster (family fits of two or
  /// more recordings; cluster_standard_errors): how far the recordings disagree on the value.
  std::optional<double> standard_error_between_recordings;
  bool fixed = false;     ///< held constant (e.g. field terms without a field input)
  bool at_bound = false;  ///< ended on a bound
  /// Why the fit held it where the user did not (e.g. an inertance too small to be seen); empty
  /// otherwise.
  std::string held_because{};
};

/// A standard error above this multiple of |value| calls a parameter poorly identified: the data
/// do not tell its value from zero or from ten times it.
inline constexpr double kPoorlyIdentifiedRelativeError = 1.0;

/// How to read a fitted parameter, one rule for `fit` and `fit-family` (text and report):
/// "held" (fixed), "at bound", "not identified" (no standard error), "poorly identified (s.e.
/// 1.4e+04 x |value|)" (relative error above kPoorlyIdentifiedRelativeError) or "".
std::string parameter_remark(const FittedParameter& p);

/// Result of fit_greybox.
struct GreyboxFit {
  std::string model;
  lumped::GreyboxSetup setup;
  std::vector<FittedParameter> params;  ///< in the order of pheno_params(kind)
  std::vector<double> simulated;        ///< free-run model output over the whole recording
  lumped::Metrics train;                ///< simulation-mode metrics on the training samples
  lumped::SampleRange train_range;
  /// [s] the recording's leading rest over which the model's output is tared to its level
  /// (lumped::tared_rest); 0 where it is not tared (no rest, or training that starts after it)
  double tared_rest_seconds = 0.0;
  double residual_sigma = 0.0;  ///< [output unit] rms residual on the training samples
  int starts_run = 0;
  int best_start = 0;
  bool converged = false;  ///< Ceres reported convergence for the best start
  double cost = 0.0;       ///< the best start's final least-squares cost (1/2 sum residual^2)
  /// Damper model: the share of the residual energy its fitted inertance removed, when checked
  /// (GreyboxOptions::min_inertance_gain); below the bound the inertance is held at 0.
  std::optional<double> inertance_gain;
  /// Family fits of two or more recordings: the parameters' cluster-robust covariance between
  /// recordings (N x N in the model's parameter order, SI units), zero for held and unidentifiable
  /// parameters; empty otherwise.
  Eigen::MatrixXd covariance_between_recordings;
};

/// Tared training recordings: the model's level in motion above the level at rest, in the output's
/// unit, orientation x (offset - PhenoSettings::rest_reference); empty where none was tared.
std::optional<double> level_in_motion_above_rest(const GreyboxFit& fit);

/// Names accepted by fit_greybox: bingham, lugre, bouc-wen, maxwell, dahl, bi-viscous, tanh,
/// damper.
const std::vector<std::string>& greybox_model_names();

/// True if `model` is a grey-box model name.
bool is_greybox_model(const std::string& model);

/// Fits `model` to `rec` (output column vs motion, position and field drive columns). Throws
/// InputError for an unknown model, a recording without a velocity/flow drive, or too few samples.
GreyboxFit fit_greybox(const lumped::Recording& rec, const std::string& model,
                       const GreyboxOptions& options = {});

/// Fits `model` jointly to `recs` (same drive and output columns), keeping every `decimation`-th
/// sample: each recording is simulated from its own initial state and its residuals are divided
/// by its own spread ||y - mean(y)||, so every recording weighs the same whatever its force
/// level (the cost is sum (1 - FIT_r)^2 / 2). `options.train` is ignored; fit.simulated is empty.
GreyboxFit fit_greybox_family(const std::vector<lumped::Recording>& recs, const std::string& model,
                              const GreyboxOptions& options, int decimation);

/// Levenberg-Marquardt iterations a fit of `model` with `options` runs at most (its starts and the
/// damper's inertance check), the bound its progress counts against.
int greybox_iteration_bound(const std::string& model, const GreyboxOptions& options);

/// Free-run output of a fitted model on another recording of the same device (stiff integrator).
std::vector<double> simulate_greybox(const lumped::Recording& rec, const GreyboxFit& fit);

}  // namespace rheomag::identify
