#pragma once
// HTML report of a family fit: measured vs model force-displacement and force-velocity loops of
// every recording (inline SVG, no external resources), the parameter table with standard errors,
// the field-dependent parameters at each field level, and the metrics per recording.

#include <filesystem>
#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// The report of `fit` (fitted on `training`, predicting `prediction`, in the order of
/// fit.training / fit.predicted) as one self-contained HTML page.
std::string family_report_html(const FamilyFit& fit, const std::vector<lumped::Recording>& training,
                               const std::vector<lumped::Recording>& prediction);

/// Writes family_report_html(...) to `dir`/report.html (the folder is created if needed).
void write_family_report(const std::filesystem::path& dir, const FamilyFit& fit,
                         const std::vector<lumped::Recording>& training,
                         const std::vector<lumped::Recording>& prediction);

}  // namespace rheomag::identify
