#pragma once
// The results table of a sweep: its columns and the CSV text of one design's row.

#include <functional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "sweep/designs.hpp"

namespace rheomag::sweep {

/// A solved design, as offered to output columns.
struct SolvedDesign {
  const cases::Case& design_case;
  const magnetostatics::MagnetostaticSolver& solver;
  const magnetostatics::Solution& solution;
  const magnetostatics::Results& results;
};

/// A group of extra output columns computed from a solved design (the plug-in point for later
/// links, e.g. the valve chain's pressure drop, coil resistance, L/R and power). `evaluate`
/// returns one value per name (SI; NaN leaves the cell empty) and may throw InputError or
/// ConvergenceError, which turns the design into an error row.
struct ColumnGroup {
  std::vector<std::string> names;
  std::function<std::vector<double>(const SolvedDesign&)> evaluate;
};

/// Longest error text kept in a row (longer messages are cut and end in "...").
inline constexpr std::size_t kMaxErrorText = 400;

/// The columns of a sweep's CSV: design_id, one per axis key (as written), per fluid gap of the
/// base case <gap>.B_avg_T, <gap>.B_max_midline_T and <gap>.B_max_area_T (docs/quantities.md), per
/// circuit <circuit>.flux_linkage_Wb, .inductance_H (secant) and .incremental_inductance_H,
/// newton_iterations, elements, the extra groups' columns, status (ok|error) and error.
class RowLayout {
 public:
  RowLayout(const SweepSpec& spec, std::vector<ColumnGroup> extra = {});
  /// The header line (with its newline).
  std::string header() const;
  /// "id,<inputs>," : how every row of this design starts (used to match rows on resume).
  std::string prefix(const Design& design) const;
  /// A complete row (with newline) for a solved design; throws what the extra groups throw.
  std::string ok_row(const Design& design, const SolvedDesign& solved) const;
  /// A complete row (with newline) for a failed design.
  std::string error_row(const Design& design, const std::string& message) const;
  /// Number of columns.
  std::size_t columns() const { return names_.size(); }

 private:
  std::vector<std::string> names_;
  std::vector<std::string> gaps_;
  std::vector<std::string> circuits_;
  std::vector<ColumnGroup> extra_;
  std::size_t output_columns_ = 0;  ///< between the inputs and status
};

/// A CSV field: quoted (with doubled quotes) when it holds a comma, quote or line break.
std::string csv_field(const std::string& text);

/// A number for the CSV: 9 significant digits; NaN gives an empty cell.
std::string csv_number(double value);

}  // namespace rheomag::sweep
