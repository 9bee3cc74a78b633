#pragma once
// The outputs of a current-dependent family fit (identify/current_dependent_fit.hpp) as `rheomag
// fit-family` prints them: its JSON document and its text report.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "identify/current_dependent_fit.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// The fitted model (readable by read_fit_model_json, `meta` the first training recording's
/// sidecar), then each recording's metrics; held_out only when the fit was cross-validated.
nlohmann::json family_fit_json(const FamilyFit& r, const lumped::RecordingMeta& meta,
                               int decimation, bool cross_validate);

/// The sample rule of a joint fit in words: which samples the fit uses (every `decimation`-th of
/// each training recording, the --decimation option) and that the metrics use them all.
std::string decimation_text(int decimation);

/// The text report: the sample rule, parameters with both standard errors, then FIT%, RE and
/// repeatability of the training, predicted and held-out recordings (`recordings` training
/// recordings, every `decimation`-th sample).
void write_family_fit_text(const FamilyFit& r, std::size_t recordings, int decimation,
                           std::ostream& out);

}  // namespace rheomag::identify
