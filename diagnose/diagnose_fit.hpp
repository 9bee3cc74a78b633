#pragma once
// Bounded least-squares fit (Ceres, Levenberg-Marquardt) of a DiagnosisModel's parameters to the
// measured output, on all samples or on a mask (for held-out validation).

#include <vector>

#include "diagnose/diagnose_model.hpp"

namespace rheomag::diagnose {

/// A fitted model: the effects, the parameter values in SI and their standard errors.
struct ModelFit {
  std::vector<const Candidate*> effects;
  std::vector<ParamDef> layout;
  std::vector<double> values;           ///< SI, in the order of layout
  std::vector<double> standard_errors;  ///< SI; NaN where the Jacobian does not identify it
  std::vector<double> prediction;       ///< free-run output over the whole recording
  double sse = 0.0;                     ///< sum of squared residuals on the fitted samples
  std::size_t samples = 0;              ///< number of fitted samples
  bool converged = false;
};

/// Options of fit_model.
struct FitSettings {
  int max_iterations = 25;      ///< 0: only evaluate (and give standard errors) at the start
  std::vector<bool> mask;       ///< samples to fit; all when empty
  int threads = 1;              ///< threads sharing the Jacobian's columns (one simulation each)
  bool standard_errors = true;  ///< compute them (one more Jacobian) or leave them NaN
  /// Parameters held at their start value (e.g. the baseline's calibrated nuisances while a
  /// candidate is screened); empty: all free.
  std::vector<bool> fixed;
  /// Follow each clamped step with Ceres' projected line search (a Jacobian per trial point:
  /// costly once a parameter sits at a bound, but it keeps the short fits on half the data of
  /// the held-out check from jumping to another optimum).
  bool projected_line_search = false;
  /// Fit the last effect's size (its first parameter) on a linear scale within +-its upper
  /// bound: its sign free (Candidate::linear_in_size).
  bool signed_last_size = false;
  /// The same for every effect linear in its size (a reference comparison's joint fit).
  bool signed_linear_sizes = false;
};

/// Fits `effects` on top of the baseline, starting from `start` (SI values in the order of
/// model.layout(effects); clamped into the bounds). Throws ConvergenceError if the model cannot
/// be simulated even at the start.
ModelFit fit_model(const DiagnosisModel& model, const std::vector<const Candidate*>& effects,
                   const std::vector<double>& start, const FitSettings& settings = {});

/// Sum of squared residuals of `prediction` on the samples of `mask` (all when empty).
double masked_sse(const std::vector<double>& measured, const std::vector<double>& prediction,
                  const std::vector<bool>& mask);

/// `start` with parameter j set to the value of `grid` where the model's squared error is least
/// (returned in `best_sse` when given; models that cannot be simulated are skipped). The grid
/// points share `threads` threads. With `scan_delay` each grid point gets its own best output
/// delay (DiagnosisModel::best_delay: no extra simulation), returned with the best point.
std::vector<double> grid_search(const DiagnosisModel& model,
                                const std::vector<const Candidate*>& effects,
                                std::vector<double> start, std::size_t j,
                                const std::vector<double>& grid, double* best_sse = nullptr,
                                int threads = 1, bool scan_delay = false);

/// Best start for `effects.back()`'s first parameter: a decade grid over its bounds with the
/// other values held at `start`; returns `start` with that parameter replaced and, in
/// `best_sse` when given, the squared error there. The grid points share `threads` threads;
/// `scan_delay` as in grid_search. `extra` values of that parameter (e.g. starts measured on the
/// recording) are scored beside the grid's.
std::vector<double> grid_start(const DiagnosisModel& model,
                               const std::vector<const Candidate*>& effects,
                               std::vector<double> start, double* best_sse = nullptr,
                               int threads = 1, bool scan_delay = false,
                               const std::vector<double>& extra = {});

}  // namespace rheomag::diagnose
