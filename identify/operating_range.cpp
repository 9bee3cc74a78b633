// The drive a model was fitted on, and what of another recording's drive lies beyond it (see
// operating_range.hpp).

#include "identify/operating_range.hpp"

#include <algorithm>
#include <cmath>

#include "core/format_text.hpp"
#include "lumped/recording_io.hpp"

namespace rheomag::identify {

namespace {

/// Percentiles of a recording's samples that stand for its extremes: a single spike moves neither.
constexpr double kLowPercentile = 0.5, kHighPercentile = 99.5;

/// The `percent`-th percentile of `v` (nearest rank on the sorted copy); `v` not empty.
double percentile(std::vector<double> v, double percent) {
  const auto k =
      static_cast<std::size_t>(std::lround(percent / 100.0 * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

/// Samples [begin, end) of column `name`, empty if the recording has no such column.
std::vector<double> samples(const lumped::Recording& rec, const std::string& name,
                            std::size_t begin, std::size_t end) {
  const auto it = rec.columns.find(name);
  if (name.empty() || it == rec.columns.end()) return {};
  const std::vector<double>& c = it->second;
  end = std::min(end, c.size());
  begin = std::min(begin, end);
  return {c.begin() + static_cast<std::ptrdiff_t>(begin),
          c.begin() + static_cast<std::ptrdiff_t>(end)};
}

std::optional<DriveExtent> spanned(const std::optional<DriveExtent>& a,
                                   const std::optional<DriveExtent>& b) {
  if (!a) return b;
  if (!b) return a;
  return DriveExtent{a->column, std::min(a->low, b->low), std::max(a->high, b->high)};
}

/// A value and its unit for a sentence: "0.73 A".
std::string with_unit(double value, const std::string& column) {
  return format_text("%.3g %s", value, lumped::column_si_unit(column).c_str());
}

nlohmann::json extent_json(const DriveExtent& e) {
  return {{"column", e.column},
          {"unit", lumped::column_si_unit(e.column)},
          {"low", e.low},
          {"high", e.high}};
}

/// An amplitude (peak speed, stroke) beyond the trained ones by more than kAmplitudeFactor.
void check_amplitude(const char* quantity, const std::optional<DriveExtent>& trained,
                     const std::optional<DriveExtent>& rec, std::vector<RangeExcess>& out) {
  if (!trained || !rec) return;
  if (rec->high > kAmplitudeFactor * trained->high)
    out.push_back({quantity, trained->column, rec->high, trained->low, trained->high});
  else if (rec->low < trained->low / kAmplitudeFactor)
    out.push_back({quantity, trained->column, rec->low, trained->low, trained->high});
}

}  // namespace

OperatingRange operating_range(const lumped::Recording& rec, const DriveColumns& cols,
                               std::size_t begin, std::size_t end) {
  OperatingRange r;
  if (const std::vector<double> b = samples(rec, cols.field, begin, end); !b.empty())
    r.field =
        DriveExtent{cols.field, percentile(b, kLowPercentile), percentile(b, kHighPercentile)};
  if (std::vector<double> v = samples(rec, cols.motion, begin, end); !v.empty()) {
    for (double& x : v) x = std::abs(x);
    const double peak = percentile(v, kHighPercentile);
    r.speed = DriveExtent{cols.motion, peak, peak};
  }
  if (const std::vector<double> x = samples(rec, cols.position, begin, end); !x.empty()) {
    const double amplitude = 0.5 * (percentile(x, kHighPercentile) - percentile(x, kLowPercentile));
    r.stroke = DriveExtent{cols.position, amplitude, amplitude};
  }
  return r;
}

OperatingRange span(const OperatingRange& a, const OperatingRange& b) {
  return {spanned(a.field, b.field), spanned(a.speed, b.speed), spanned(a.stroke, b.stroke)};
}

std::string RangeExcess::text() const {
  const bool above = value > high;
  const std::string trained = low == high
                                  ? with_unit(low, column)
                                  : format_text("%.3g", low) + " ... " + with_unit(high, column);
  if (quantity == "field")
    return format_text(
        "field: %s %s %s, %s the trained %s (the model's field dependence is "
        "extrapolated)",
        column.c_str(), above ? "up to" : "down to", with_unit(value, column).c_str(),
        above ? "above" : "below", trained.c_str());
  const char* what = quantity == "speed" ? "peak" : "amplitude";
  return format_text("%s: %s %s %s, %s the trained %ss %s", quantity.c_str(), column.c_str(), what,
                     with_unit(value, column).c_str(), above ? "above" : "below", what,
                     trained.c_str());
}

std::vector<RangeExcess> beyond_range(const OperatingRange& trained,
                                      const OperatingRange& recording) {
  std::vector<RangeExcess> out;
  if (trained.field && recording.field) {
    const DriveExtent& t = *trained.field;
    const double margin = std::max(
        kFieldMargin * std::max({t.high - t.low, std::abs(t.high), std::abs(t.low)}), kFieldFloor);
    if (recording.field->high > t.high + margin)
      out.push_back({"field", t.column, recording.field->high, t.low, t.high});
    else if (recording.field->low < t.low - margin)
      out.push_back({"field", t.column, recording.field->low, t.low, t.high});
  }
  check_amplitude("speed", trained.speed, recording.speed, out);
  check_amplitude("stroke", trained.stroke, recording.stroke, out);
  return out;
}

nlohmann::json operating_range_json(const OperatingRange& range) {
  nlohmann::json j = nlohmann::json::object();
  if (range.field) j["field"] = extent_json(*range.field);
  if (range.speed) j["speed"] = extent_json(*range.speed);
  if (range.stroke) j["stroke"] = extent_json(*range.stroke);
  return j;
}

nlohmann::json range_excess_json(const std::vector<RangeExcess>& excess) {
  nlohmann::json j = nlohmann::json::array();
  for (const RangeExcess& e : excess)
    j.push_back({{"quantity", e.quantity},
                 {"column", e.column},
                 {"unit", lumped::column_si_unit(e.column)},
                 {"value", e.value},
                 {"trained_low", e.low},
                 {"trained_high", e.high},
                 {"text", e.text()}});
  return j;
}

}  // namespace rheomag::identify
