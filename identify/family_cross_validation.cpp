// Leave-one-recording-out refits of a family, each predicting the recording it left out.

#include "identify/family_cross_validation.hpp"

#include <algorithm>
#include <chrono>

#include "core/error.hpp"

namespace rheomag::identify {

namespace {

/// `training` without its k-th recording.
std::vector<lumped::Recording> without(const std::vector<lumped::Recording>& training,
                                       std::size_t k) {
  std::vector<lumped::Recording> rest;
  for (std::size_t i = 0; i < training.size(); ++i)
    if (i != k) rest.push_back(training[i]);
  return rest;
}

}  // namespace

void check_cross_validation(const std::vector<lumped::Recording>& training,
                            const std::string& model) {
  const std::size_t n = training.size();
  if (n < 3)
    throw InputError("fit-family --cross-validate: needs at least 3 training recordings (got " +
                     std::to_string(n) + "): each refit leaves one out and keeps a family");
  for (std::size_t k = 0; k < n; ++k) {
    try {
      check_family(without(training, k), {training[k]}, model);
    } catch (const InputError& e) {
      throw InputError("fit-family --cross-validate: without " + training[k].csv_path +
                       " the family no longer fits: " + e.what());
    }
  }
}

std::vector<FamilyMember> cross_validate_family(const std::vector<lumped::Recording>& training,
                                                const std::string& model,
                                                const FamilyFitOptions& options) {
  check_cross_validation(training, model);
  const std::size_t n = training.size();
  const auto start = std::chrono::steady_clock::now();
  std::vector<FamilyMember> held_out;
  for (std::size_t k = 0; k < n; ++k) {
    GreyboxOptions greybox = options.greybox;
    if (options.greybox.progress) {
      // Each refit's iterations, offset by the refits before it, of the bound of all n refits.
      const double bound = std::max(1, greybox.starts) * greybox.max_iterations;
      const std::string stage = "cross-validation, refit " + std::to_string(k + 1) + " of " +
                                std::to_string(n) + " (without " + training[k].csv_path + ")";
      greybox.progress = [&, bound, stage, k](const ProgressEvent& inner) {
        ProgressEvent e = inner;
        e.stage = stage;
        e.done = static_cast<double>(k) * bound + std::min(inner.done, bound);
        e.total = static_cast<double>(n) * bound;
        e.total_is_bound = true;
        e.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        options.greybox.progress(e);
      };
    }
    const GreyboxFit fit =
        fit_greybox_family(without(training, k), model, greybox, options.decimation);
    held_out.push_back(evaluate_family_member(training[k], fit));
    held_out.back().band = prediction_band(training[k], fit);
  }
  return held_out;
}

}  // namespace rheomag::identify
