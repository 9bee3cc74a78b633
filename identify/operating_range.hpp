#pragma once
// The drive a model was fitted on (its field levels, peak speeds and strokes), carried in the
// fitted model, so that a recording the model later runs on can be told where it lies beyond
// what the fit saw: there the model extrapolates, and its prediction is a guess of its structure.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "lumped/recording.hpp"

namespace rheomag::identify {

/// The extent of one drive quantity: its smallest and largest value [SI, the column's unit].
struct DriveExtent {
  std::string column;  ///< the recording column it is measured on ("current", "velocity", ...)
  double low = 0.0;    ///< smallest value
  double high = 0.0;   ///< largest value
};

/// The drive of one or more recordings, quantity by quantity (each absent where the model has no
/// such column).
struct OperatingRange {
  /// The field column's samples from their 0.5th to their 99.5th percentile (a noise spike does
  /// not widen it).
  std::optional<DriveExtent> field;
  /// Each recording's peak |motion| (the 99.5th percentile of |motion|), smallest to largest.
  std::optional<DriveExtent> speed;
  /// Each recording's stroke amplitude (half its position's 0.5th-to-99.5th percentile range),
  /// smallest to largest.
  std::optional<DriveExtent> stroke;
};

/// The drive columns a model reads; an empty name is a column the model does not have.
struct DriveColumns {
  std::string field;     ///< e.g. "current"
  std::string motion;    ///< e.g. "velocity"
  std::string position;  ///< e.g. "displacement"
};

/// The drive of `rec` on its samples [begin, end) (clamped to the data). Columns named in `cols`
/// but absent from the recording are left out.
OperatingRange operating_range(const lumped::Recording& rec, const DriveColumns& cols,
                               std::size_t begin = 0,
                               std::size_t end = static_cast<std::size_t>(-1));

/// The range that spans both `a` and `b` (the drive of a family of recordings).
OperatingRange span(const OperatingRange& a, const OperatingRange& b);

/// One drive quantity of a recording beyond the range a model was fitted on.
struct RangeExcess {
  std::string quantity;  ///< "field", "speed" or "stroke"
  std::string column;    ///< the recording column
  double value = 0.0;    ///< the recording's value beyond the range [SI]
  double low = 0.0;      ///< the trained range's smallest value
  double high = 0.0;     ///< the trained range's largest value
  /// One sentence, e.g. "field: current up to 0.73 A, above the trained 0 ... 0.495 A (the
  /// model's field dependence is extrapolated)".
  std::string text() const;
};

/// Margins of beyond_range: a field beyond the trained levels by more than this share of their
/// span (or of their largest magnitude when they are one level); a peak speed or stroke more
/// than this factor above the largest or below the smallest trained one.
inline constexpr double kFieldMargin = 0.05;
/// The least field margin [A or V]: a recording at 0 A is not beyond a fit at 0 A for its noise.
inline constexpr double kFieldFloor = 0.01;
inline constexpr double kAmplitudeFactor = 1.25;

/// What of `recording`'s drive lies beyond `trained` (empty: within it); quantities missing on
/// either side are not compared.
std::vector<RangeExcess> beyond_range(const OperatingRange& trained,
                                      const OperatingRange& recording);

/// `range` as the fitted-model JSON carries it: {"field": {"column", "unit", "low", "high"},
/// "speed": ..., "stroke": ...}, absent quantities left out.
nlohmann::json operating_range_json(const OperatingRange& range);

/// `excess` as a JSON array of {quantity, column, unit, value, trained_low, trained_high, text}.
nlohmann::json range_excess_json(const std::vector<RangeExcess>& excess);

}  // namespace rheomag::identify
