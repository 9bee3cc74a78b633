#pragma once
// The lead of a model's motion drive over its position and output
// (lumped::GreyboxSetup::motion_lead), chosen by the training misfit: a velocity column that lags
// the displacement and the force (a backward difference, a filter, a sensor of its own) shifts
// the model's reversals against the measured ones, and no parameter of the model can undo a
// shift in time. The lead is one number for the device, searched, not fitted through the ODE
// (docs/damper-model.md, "A velocity column that lags").

#include <functional>
#include <string>
#include <vector>

#include "identify/greybox.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// [s] The leads fit_family_searching_motion_lead tries: -5 to 15 ms in 2.5 ms steps (a
/// backward difference at 100 Hz lags 5 ms).
std::vector<double> default_motion_leads();

/// Options of a warm refit of `fit`: one start at its values, at most `iterations`
/// Levenberg-Marquardt iterations, and what it held of its own accord (the inertance) held.
GreyboxOptions warm_refit_options(const GreyboxOptions& options, const GreyboxFit& fit,
                                  int iterations);

/// Gives a warm refit of `before` the decisions `before` made of its own accord (why a parameter
/// was held, the inertance check's gain), which the refit kept without making them again.
void keep_fit_decisions(const GreyboxFit& before, GreyboxFit& refit);

/// A grey-box fit with the given options (a family's or one recording's).
using FitWithOptions = std::function<GreyboxFit(const GreyboxOptions&)>;

/// The search behind both fits below: `fit_at(options)`, then a warm refit from it (`iterations`)
/// at each lead of `leads`, the given one included so that every candidate gets the same refit;
/// the fit of lowest `misfit` is kept (ties keep the earlier one). A refit whose simulation does
/// not converge at its lead is not a candidate.
GreyboxFit search_motion_lead(const GreyboxOptions& options, const std::vector<double>& leads,
                              int iterations, const FitWithOptions& fit_at,
                              const std::function<double(const GreyboxFit&)>& misfit);

/// The family fit of `recs` at `options.motion_lead` (fit_greybox_family), then a warm refit
/// from it (`iterations`) at each lead of `leads`, the given one included so that every candidate
/// gets the same refit: the fit whose training recordings, simulated at full rate, have the
/// lowest sum of (1 - FIT)^2, its lead in fit.setup.motion_lead. Ties keep the earlier fit.
GreyboxFit fit_family_searching_motion_lead(const std::vector<lumped::Recording>& recs,
                                            const std::string& model, const GreyboxOptions& options,
                                            int decimation, const std::vector<double>& leads,
                                            int iterations = 30);

/// One recording's fit (fit_greybox) with the lead searched likewise, the misfit the training
/// samples' (1 - FIT)^2 (fit.train, full rate).
GreyboxFit fit_searching_motion_lead(const lumped::Recording& rec, const std::string& model,
                                     const GreyboxOptions& options,
                                     const std::vector<double>& leads, int iterations = 30);

}  // namespace rheomag::identify
