#pragma once
// The design report of a solved case: one self-contained HTML page with its key numbers and its
// pictures as inline SVG.

#include <filesystem>
#include <string>

#include "figures/device_sections.hpp"
#include "figures/field_map.hpp"
#include "figures/solve_pictures.hpp"

namespace rheomag::figures {

/// The HTML page: the mesh and solve, each gap's flux density, each circuit's flux linkage and
/// inductances, the energies, then the field map, B along each gap, lambda(I), L(I) and the
/// device `sections` (inline SVG, their ids prefixed per picture so that they do not clash).
std::string solve_report_html(const SolvedCase& solved, const FieldMapOptions& options,
                              const std::vector<ReportSection>& sections = {});

/// Writes the page as DIR/report.html (DIR created if absent; nothing else written).
std::filesystem::path write_solve_report(const std::filesystem::path& dir, const SolvedCase& solved,
                                         const FieldMapOptions& options,
                                         const std::vector<ReportSection>& sections = {});

/// Cairo's SVG document made fit to sit inside HTML: the XML declaration dropped and every id
/// (and every reference to one) prefixed with `prefix`.
std::string inline_svg(const std::string& svg, const std::string& prefix);

}  // namespace rheomag::figures
