#pragma once
// Leave-one-recording-out cross-validation of a family fit: each training recording predicted
// by the same model fitted on all the others, so that its FIT is that of a test the fit has not
// seen (what a prediction of another test of the device can be expected to reach).

#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// InputError unless every leave-one-out family of `training` holds (check_family): at least 3
/// recordings, and no recording the only one at a field level that the family needs.
void check_cross_validation(const std::vector<lumped::Recording>& training,
                            const std::string& model);

/// The two halves whose fits start the refits: the training recordings in order of their mean
/// field (ties in training order), the k-th recording of the l-th field level into half
/// (k + l) mod 2 (levels closer than 1e-3 of the largest |field| are one).
std::vector<std::vector<lumped::Recording>> cross_validation_halves(
    const std::vector<lumped::Recording>& training, const std::string& model);

/// For each training recording k (in order), `model` fitted on the others and evaluated on k
/// (predict_family_member: band and calibrated level too; `beyond`: what of k's drive lies
/// beyond the other recordings', where the refit extrapolates). With options.refit_iterations > 0,
/// each refit runs that many iterations from one start: the fit (from nominal, with
/// options.greybox) of the half (cross_validation_halves) that does not hold k, so no fit that saw
/// k starts it; a half that is no family for the model (check_family) leaves its tests the cold
/// refit. With 0, every refit is cold: from nominal with options.greybox. The fits run one per
/// thread, options.greybox.threads of them at once (0: one per core), so the result does not
/// depend on that count. Progress, if options.greybox.progress is set, counts every fit's
/// iterations against their bound. InputError as check_cross_validation.
std::vector<FamilyMember> cross_validate_family(const std::vector<lumped::Recording>& training,
                                                const std::string& model,
                                                const FamilyFitOptions& options);

}  // namespace rheomag::identify
