#pragma once
// Top-level tables of a case file that belong to a later layer ([valve], [optimise], ...): each
// layer registers the names it reads, so the case reader accepts them without naming them.

#include <string>
#include <string_view>
#include <vector>

namespace rheomag::cases {

/// Registers `name` as a top-level table read by a later layer; returns true (so a header can
/// register at static initialisation: `inline const bool kRegistered = register_case_section(..)`).
bool register_case_section(std::string_view name);

/// The registered section names, sorted.
std::vector<std::string> registered_case_sections();

}  // namespace rheomag::cases
