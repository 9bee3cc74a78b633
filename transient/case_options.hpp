#pragma once
// The [transient] table of a case file: eddy-current remedies per region and the coil
// resistance (docs/case-format.md, "[transient]").

#include <optional>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "transient/eddy.hpp"

namespace rheomag::transient {

/// What a case says about its transient behaviour.
struct TransientCaseOptions {
  std::vector<RegionEddy> remedies;  ///< [[transient.region]] entries
  std::optional<double> resistance;  ///< [transient] resistance [Ohm] (else from the wire)
};

/// [transient] is a section of the case file read here.
inline const bool kTransientSectionRegistered = cases::register_case_section("transient");

/// Reads [transient] (absent: no remedy, no resistance). Sizes are in the case's length unit.
/// InputError naming the key for unknown keys, an unknown model, a factor outside [0, 1], a size
/// <= 0 or a model without the parameter it needs.
TransientCaseOptions read_transient_case(const cases::Case& c);

}  // namespace rheomag::transient
