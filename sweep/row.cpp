#include "sweep/row.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace rheomag::sweep {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string csv_number(double value) {
  if (std::isnan(value)) return "";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

RowLayout::RowLayout(const SweepSpec& spec, std::vector<ColumnGroup> extra)
    : extra_(std::move(extra)) {
  names_.push_back("design_id");
  for (const SweepAxis& axis : spec.axes) names_.push_back(axis.key.written);
  const auto& problem = spec.base.problem;
  for (const auto& region : problem.geometry.regions) {
    if (region.gap != mesh::GapKind::none) gaps_.push_back(region.name);
  }
  for (const auto& circuit : problem.circuits) circuits_.push_back(circuit.name);
  const std::size_t before = names_.size();
  for (const std::string& g : gaps_) {
    // The names of docs/quantities.md, as solve's text and JSON print them.
    names_.push_back(g + ".B_avg_T");
    names_.push_back(g + ".B_max_midline_T");
    names_.push_back(g + ".B_max_area_T");
  }
  for (const std::string& c : circuits_) {
    names_.push_back(c + ".flux_linkage_Wb");
    names_.push_back(c + ".inductance_H");
    names_.push_back(c + ".incremental_inductance_H");
  }
  names_.push_back("newton_iterations");
  names_.push_back("elements");
  for (const ColumnGroup& group : extra_) {
    names_.insert(names_.end(), group.names.begin(), group.names.end());
  }
  output_columns_ = names_.size() - before;
  names_.push_back("status");
  names_.push_back("error");
}

std::string RowLayout::header() const {
  std::string line;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (i > 0) line += ',';
    line += csv_field(names_[i]);
  }
  line += '\n';
  return line;
}

std::string RowLayout::prefix(const Design& design) const {
  std::string line = std::to_string(design.id) + ",";
  for (const cases::KeyValue& v : design.values) line += csv_field(cases::format_value(v)) + ",";
  return line;
}

std::string RowLayout::ok_row(const Design& design, const SolvedDesign& solved) const {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> values;
  const auto& results = solved.results;
  for (const std::string& g : gaps_) {
    double average = none, midline = none, area = none;
    for (const auto& gap : results.gaps) {
      if (gap.name == g) {
        average = gap.b.average;
        midline = gap.line_b.maximum;
        area = gap.b.maximum;
      }
    }
    values.push_back(average);
    values.push_back(midline);
    values.push_back(area);
  }
  for (const std::string& c : circuits_) {
    double lambda = none, secant = none, incremental = none;
    for (const auto& circuit : results.circuits) {
      if (circuit.name == c) {
        lambda = circuit.flux_linkage;
        secant = circuit.inductance;
        incremental = circuit.incremental_inductance;
      }
    }
    values.push_back(lambda);
    values.push_back(secant);
    values.push_back(incremental);
  }
  values.push_back(results.newton_iterations);
  values.push_back(results.elements);
  for (const ColumnGroup& group : extra_) {
    std::vector<double> extra = group.evaluate(solved);
    extra.resize(group.names.size(), none);
    values.insert(values.end(), extra.begin(), extra.end());
  }
  std::string line = prefix(design);
  for (double v : values) line += csv_number(v) + ",";
  return line + "ok,\n";
}

std::string RowLayout::error_row(const Design& design, const std::string& message) const {
  std::string text;
  for (char c : message) text += (c == '\n' || c == '\r') ? ' ' : c;
  if (text.size() > kMaxErrorText) {
    std::size_t cut = kMaxErrorText - 3;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
    text = text.substr(0, cut) + "...";
  }
  std::string line = prefix(design);
  line.append(output_columns_, ',');
  return line + "error," + csv_field(text) + "\n";
}

}  // namespace rheomag::sweep
