#pragma once
// HTML report of a family fit: measured vs model force-displacement and force-velocity loops of
// every recording (inline SVG, no external resources), the parameter table with standard errors,
// the field-dependent parameters at each field level, and the metrics per recording.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// A parameter whose value depends on the field u: base + linear u (+ quadratic u^2), indices
/// into the fit's parameters.
struct FieldDependence {
  std::string name;  ///< "yield" (base + yield_per_field ...), "alpha" (alpha_a + alpha_b u)
  std::size_t base = 0, linear = 0;
  std::optional<std::size_t> quadratic;  ///< NAME_per_field2
};

/// The field-dependent parameters of a grey-box model: X with X_per_field (and X_per_field2),
/// and the Bouc-Wen pairs X_a + X_b u (alpha, c0, c1).
std::vector<FieldDependence> field_dependent_parameters(const std::vector<FittedParameter>& params);

/// The report of `fit` (fitted on `training`, predicting `prediction`, in the order of
/// fit.training / fit.predicted) as one self-contained HTML page.
std::string family_report_html(const FamilyFit& fit, const std::vector<lumped::Recording>& training,
                               const std::vector<lumped::Recording>& prediction);

/// Writes family_report_html(...) to `dir`/report.html (the folder is created if needed).
void write_family_report(const std::filesystem::path& dir, const FamilyFit& fit,
                         const std::vector<lumped::Recording>& training,
                         const std::vector<lumped::Recording>& prediction);

}  // namespace rheomag::identify
