#pragma once
// Why a candidate that lowered BIC is still not accepted (practical significance, noise, timing,
// the candidate's own plausibility, identifiability), and the findings that fade in the joint
// re-fit.

#include <string>
#include <vector>

#include "diagnose/diagnose_evidence.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// Why a candidate fit that lowered BIC is still not accepted ("" if nothing speaks against it
/// before the held-out check): it removes too small a share of the residual energy above the
/// noise floor (`share` returns the share), its time constant is shorter than a sample, or its
/// size parameter is not identified. Measured on every sample, or (`away`) on the samples away
/// from steps only (Evidence).
std::string rejection(const DiagnosisModel& model, const ModelFit& current, const ModelFit& fit,
                      const Candidate* effect, double delta_bic, const Evidence& evidence,
                      bool away, const DiagnoseOptions& options, double& share);

/// Drops from `d` (and from `fit`, the final joint re-fit) each finding that no longer passes the
/// practical-significance and noise bars inside the joint model: switched off there with every
/// other parameter as fitted, the error rises by less than `min_share` of the residual above the
/// noise floor or less than `min_noise_multiple` noise deviations in rms. A finding accepted
/// beside another can fade in the joint re-fit (a Coulomb force that ends at a few newtons
/// once a compliance and the static map are re-fitted with it); it is then not reported. So is a
/// finding whose re-fitted parameters its candidate finds implausible (Candidate::implausible),
/// or whose lag the re-fitted output delay takes back (the timing rules of `rejection`).
void drop_faded_findings(const DiagnosisModel& model, ModelFit& fit, const Evidence& evidence,
                         const DiagnoseOptions& options, Diagnosis& d);

/// `fit` with its effect i moved to the end of the layout (Candidate::implausible reads the
/// effect it judges as the last one).
ModelFit with_effect_last(const DiagnosisModel& model, const ModelFit& fit, std::size_t i);

/// Relative standard error of the size parameter (the first) of the last effect of `fit`, on the
/// samples of `mask` (all when empty).
double size_relative_se(const DiagnosisModel& model, const ModelFit& fit, int threads,
                        const std::vector<bool>& mask);

}  // namespace rheomag::diagnose
