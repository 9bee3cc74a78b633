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

/// For each training recording k (in order), `model` fitted with `options` on the others and
/// evaluated on k, with k's prediction band. Progress, if options.greybox.progress is set, counts
/// every refit's iterations against their bound. InputError as check_cross_validation.
std::vector<FamilyMember> cross_validate_family(const std::vector<lumped::Recording>& training,
                                                const std::string& model,
                                                const FamilyFitOptions& options);

}  // namespace rheomag::identify
