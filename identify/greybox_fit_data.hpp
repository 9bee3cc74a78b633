#pragma once
// What a grey-box fit hands to its Ceres solve (identify/greybox_run_fit.hpp): the training data,
// the parameters' starting point and bounds, and the solve itself, declared here and compiled once
// per parameter count N (greybox_fit_*.cpp) so that no file instantiates every model's Jets.

#include <string>
#include <vector>

#include "identify/greybox.hpp"
#include "lumped/pheno_simulation.hpp"

namespace rheomag::identify::greybox_detail {

/// Nominal value, scale and bounds of each parameter, from the data's magnitudes.
struct ParamGuess {
  std::vector<double> nominal, scale, lower, upper;
  std::vector<bool> fixed;
  /// Held parameters that take a slot of the fit's free-parameter vector, held constant there
  /// (a held count the fit has no instantiation of runs in the next larger one); empty: none.
  std::vector<bool> pinned;
};

/// The training data of a fit: one or more drive series, each simulated from its own initial
/// state on its own sample range, its residuals divided by its own scale.
struct FitData {
  std::vector<lumped::DriveSeries> series;
  std::vector<lumped::SampleRange> ranges;
  std::vector<double> y_scales;
  std::vector<double> viscous_factors;  ///< per series (GreyboxOptions); empty: 1
};

/// The unit of a parameter: its pattern with Y (output), M (motion), X (position) and U (field)
/// spelled out for the recording's columns.
std::string unit_string(const std::string& pattern, const lumped::GreyboxSetup& s);

/// Longest integration step inside a fit: the damper and Bouc-Wen models' exponential steps are
/// not limited by their stiff modes (only by accuracy), the other models' RK4 substeps are.
double fit_step(lumped::PhenoKind kind, const GreyboxOptions& options);

/// One multi-start fit of a model with N parameters of which NF are free; fills `fit`. Defined in
/// identify/greybox_run_fit.hpp, instantiated in greybox_fit_*.cpp.
template <int N, int NF>
void run_fit(const FitData& data, const lumped::GreyboxSetup& setup, const ParamGuess& guess,
             const GreyboxOptions& options, GreyboxFit& fit);

}  // namespace rheomag::identify::greybox_detail
