// CSV + TOML sidecar reader and atomic writer for recordings.

#include "lumped/recording_io.hpp"

#include <toml++/toml.h>

#include <unistd.h>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace rheomag::lumped {

namespace fs = std::filesystem;

const std::vector<std::string>& known_columns() {
  static const std::vector<std::string> names = {
      "t",        "current",      "current_cmd", "voltage", "command",      "flow",
      "velocity", "displacement", "pressure",    "force",   "flux_linkage", "temperature"};
  return names;
}

std::string sidecar_path_for(const std::string& csv_path) {
  fs::path p(csv_path);
  p.replace_extension(".toml");
  return p.string();
}

namespace {

bool is_known_column(const std::string& name) {
  const auto& k = known_columns();
  return std::find(k.begin(), k.end(), name) != k.end();
}

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return std::string(s.substr(a, b - a));
}

std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = line.find(',', start);
    cells.push_back(trim(std::string_view(line).substr(
        start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

[[noreturn]] void fail_at(const std::string& file, std::size_t line, const std::string& what) {
  throw InputError(file + ":" + std::to_string(line) + ": " + what);
}

double parse_cell(const std::string& cell, const std::string& file, std::size_t line,
                  const std::string& column) {
  if (cell.empty()) fail_at(file, line, "empty cell in column '" + column + "'");
  double value = 0.0;
  const char* begin = cell.data();
  const char* end = cell.data() + cell.size();
  if (*begin == '+') ++begin;
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec == std::errc::result_out_of_range)
    fail_at(file, line, "value '" + cell + "' in column '" + column + "' is out of range");
  if (ec != std::errc() || ptr != end)
    fail_at(file, line, "'" + cell + "' in column '" + column + "' is not a number");
  if (!std::isfinite(value))
    fail_at(file, line, "'" + cell + "' in column '" + column + "' is NaN or infinite");
  return value;
}

std::optional<double> optional_number(const toml::table& table, const std::string& key,
                                      const std::string& file, const std::string& section) {
  const toml::node* node = table.get(key);
  if (!node) return std::nullopt;
  auto value = node->value<double>();
  if (!value || !std::isfinite(*value))
    throw InputError(file + ": [" + section + "] " + key + " must be a finite number");
  return *value;
}

std::vector<double> number_array(const toml::table& table, const std::string& key,
                                 const std::string& file, const std::string& section) {
  std::vector<double> out;
  const toml::node* node = table.get(key);
  if (!node) return out;
  const toml::array* arr = node->as_array();
  if (!arr) throw InputError(file + ": [" + section + "] " + key + " must be an array of numbers");
  for (const auto& element : *arr) {
    auto value = element.value<double>();
    if (!value || !std::isfinite(*value))
      throw InputError(file + ": [" + section + "] " + key + " must contain only finite numbers");
    out.push_back(*value);
  }
  return out;
}

std::string format_number(double v) {
  char buffer[64];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  (void)ec;
  return std::string(buffer, ptr);
}

}  // namespace

RecordingMeta read_sidecar(const std::string& toml_path) {
  if (!fs::exists(toml_path))
    throw InputError(toml_path +
                     ": sidecar not found (every recording CSV needs a TOML sidecar "
                     "with the same stem; see shared/docs/recording-format.md)");
  toml::table doc;
  try {
    doc = toml::parse_file(toml_path);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << toml_path << ":" << e.source().begin.line << ": " << e.description();
    throw InputError(msg.str());
  }
  RecordingMeta meta;
  meta.sidecar_path = toml_path;
  const toml::table* rec = doc["recording"].as_table();
  if (!rec) throw InputError(toml_path + ": missing [recording] table");
  meta.description = (*rec)["description"].value_or(std::string());
  const toml::array* drive = (*rec)["drive"].as_array();
  if (!drive || drive->empty())
    throw InputError(toml_path + ": [recording] drive must be a non-empty array of column names");
  for (const auto& d : *drive) {
    auto name = d.value<std::string>();
    if (!name) throw InputError(toml_path + ": [recording] drive must contain strings");
    meta.drive.push_back(*name);
  }
  auto output = (*rec)["output"].value<std::string>();
  if (!output || output->empty())
    throw InputError(toml_path + ": [recording] output must be a column name");
  meta.output = *output;

  if (const toml::table* rig = doc["rig"].as_table()) {
    const std::string kind = (*rig)["kind"].value_or(std::string());
    if (!kind.empty()) {
      meta.rig.kind = kRigKindNames.find(kind);
      if (!meta.rig.kind)
        throw InputError(toml_path + ": [rig] kind '" + kind +
                         "' is not one of constant_velocity_pump, bypass_cylinder, damper, "
                         "coil_bench");
    }
    meta.rig.piston_area = optional_number(*rig, "piston_area", toml_path, "rig");
    meta.rig.chamber_volume = optional_number(*rig, "chamber_volume", toml_path, "rig");
    meta.rig.rod_area = optional_number(*rig, "rod_area", toml_path, "rig");
    meta.rig.gas_force = optional_number(*rig, "gas_force", toml_path, "rig");
    for (const auto& [key, node] : *rig) {
      std::string k(key.str());
      if (k == "kind" || k == "piston_area" || k == "chamber_volume" || k == "rod_area" ||
          k == "gas_force")
        continue;
      if (auto v = node.value<double>()) meta.rig.extra[k] = *v;
    }
  }
  if (const toml::table* valve = doc["valve"].as_table()) {
    if (auto c = (*valve)["case"].value<std::string>()) {
      fs::path p(*c);
      if (p.is_relative()) p = fs::path(toml_path).parent_path() / p;
      meta.valve.case_file = p.lexically_normal().string();
    }
    meta.valve.yield_current = number_array(*valve, "yield_current", toml_path, "valve");
    meta.valve.yield_pressure = number_array(*valve, "yield_pressure", toml_path, "valve");
    if (meta.valve.yield_current.size() != meta.valve.yield_pressure.size())
      throw InputError(toml_path + ": [valve] yield_current and yield_pressure differ in length");
    for (std::size_t i = 1; i < meta.valve.yield_current.size(); ++i)
      if (!(meta.valve.yield_current[i] > meta.valve.yield_current[i - 1]))
        throw InputError(toml_path + ": [valve] yield_current must be strictly increasing");
    meta.valve.viscous_resistance =
        optional_number(*valve, "viscous_resistance", toml_path, "valve");
  }
  if (const toml::table* coil = doc["coil"].as_table()) {
    meta.coil.resistance = optional_number(*coil, "resistance", toml_path, "coil");
    meta.coil.inductance = optional_number(*coil, "inductance", toml_path, "coil");
    if (meta.coil.resistance && *meta.coil.resistance <= 0)
      throw InputError(toml_path + ": [coil] resistance must be > 0 ohm");
    if (meta.coil.inductance && *meta.coil.inductance < 0)
      throw InputError(toml_path + ": [coil] inductance must be >= 0 H");
  }
  return meta;
}

Recording read_csv_samples(const std::string& csv_path) {
  std::vector<std::string> warnings;
  std::ifstream in(csv_path);
  if (!in) throw InputError(csv_path + ": cannot open recording");
  Recording rec;
  rec.csv_path = csv_path;
  std::string line;
  std::size_t line_no = 0;
  std::vector<std::string> header;
  // Skip leading comments and blank lines; the first other line is the header.
  while (std::getline(in, line)) {
    ++line_no;
    std::string stripped = trim(line);
    if (stripped.empty() || stripped[0] == '#') continue;
    header = split_cells(stripped);
    break;
  }
  if (header.empty()) throw InputError(csv_path + ": no header row");
  std::vector<int> slot(header.size(), -1);  // index into `kept`, -1 for ignored columns
  std::vector<std::string> kept;
  std::set<std::string> seen;
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (header[c].empty())
      fail_at(csv_path, line_no,
              "empty column name in header (column " + std::to_string(c + 1) + ")");
    if (!seen.insert(header[c]).second)
      fail_at(csv_path, line_no, "column '" + header[c] + "' appears twice");
    if (is_known_column(header[c])) {
      slot[c] = static_cast<int>(kept.size());
      kept.push_back(header[c]);
    } else {
      warnings.push_back(csv_path + ": ignoring unknown column '" + header[c] + "'");
    }
  }
  if (!seen.count("t")) fail_at(csv_path, line_no, "no 't' column (time in s is required)");
  std::vector<std::vector<double>> data(kept.size());
  const int t_slot = static_cast<int>(std::find(kept.begin(), kept.end(), "t") - kept.begin());
  while (std::getline(in, line)) {
    ++line_no;
    std::string stripped = trim(line);
    if (stripped.empty()) continue;
    if (stripped[0] == '#')
      fail_at(csv_path, line_no, "comment lines are only allowed before the header");
    auto cells = split_cells(stripped);
    if (cells.size() != header.size())
      fail_at(csv_path, line_no,
              "expected " + std::to_string(header.size()) + " cells, found " +
                  std::to_string(cells.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (slot[c] < 0) continue;
      double v = parse_cell(cells[c], csv_path, line_no, header[c]);
      if (slot[c] == t_slot && !data[t_slot].empty() && !(v > data[t_slot].back()))
        fail_at(csv_path, line_no,
                "time column 't' is not strictly increasing (" + cells[c] + " after " +
                    format_number(data[t_slot].back()) + ")");
      data[slot[c]].push_back(v);
    }
  }
  if (data[t_slot].size() < 2)
    throw InputError(csv_path + ": needs at least 2 samples, found " +
                     std::to_string(data[t_slot].size()));
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (static_cast<int>(k) == t_slot)
      rec.t = std::move(data[k]);
    else
      rec.columns[kept[k]] = std::move(data[k]);
  }
  rec.warnings = std::move(warnings);
  return rec;
}

Recording read_recording(const std::string& csv_path) {
  if (!fs::exists(csv_path)) throw InputError(csv_path + ": recording not found");
  const std::string sidecar = sidecar_path_for(csv_path);
  RecordingMeta meta = read_sidecar(sidecar);
  Recording rec = read_csv_samples(csv_path);
  rec.meta = std::move(meta);
  for (const auto& d : rec.meta.drive)
    if (!rec.columns.count(d))
      throw InputError(sidecar + ": [recording] drive column '" + d + "' is not in " + csv_path);
  if (!rec.columns.count(rec.meta.output))
    throw InputError(sidecar + ": [recording] output column '" + rec.meta.output + "' is not in " +
                     csv_path);
  return rec;
}

void write_recording(const Recording& rec, const std::string& csv_path) {
  for (const auto& [name, values] : rec.columns) {
    if (!is_known_column(name) || name == "t")
      throw InputError(csv_path + ": cannot write column '" + name +
                       "' (not a column of the recording format)");
    if (values.size() != rec.t.size())
      throw InputError(csv_path + ": column '" + name + "' has " + std::to_string(values.size()) +
                       " samples, t has " + std::to_string(rec.t.size()));
  }
  for (std::size_t i = 0; i < rec.t.size(); ++i)
    if (!std::isfinite(rec.t[i]) || (i > 0 && !(rec.t[i] > rec.t[i - 1])))
      throw InputError(csv_path + ": time is not finite and strictly increasing at sample " +
                       std::to_string(i));
  std::vector<const std::vector<double>*> cols;
  std::ostringstream csv;
  csv << "# written by rheomag";
  if (!rec.meta.description.empty()) csv << ": " << rec.meta.description;
  csv << "\n";
  csv << "t";
  for (const auto& name : known_columns()) {
    auto it = rec.columns.find(name);
    if (it == rec.columns.end()) continue;
    csv << "," << name;
    cols.push_back(&it->second);
  }
  csv << "\n";
  for (std::size_t i = 0; i < rec.t.size(); ++i) {
    csv << format_number(rec.t[i]);
    for (const auto* c : cols) {
      if (!std::isfinite((*c)[i]))
        throw InputError(csv_path + ": non-finite value at sample " + std::to_string(i));
      csv << "," << format_number((*c)[i]);
    }
    csv << "\n";
  }

  toml::table doc;
  toml::array drive;
  for (const auto& d : rec.meta.drive) drive.push_back(d);
  doc.insert("recording", toml::table{{"description", rec.meta.description},
                                      {"drive", drive},
                                      {"output", rec.meta.output}});
  toml::table rig;
  if (rec.meta.rig.kind) rig.insert("kind", std::string(kRigKindNames.name(*rec.meta.rig.kind)));
  if (rec.meta.rig.piston_area) rig.insert("piston_area", *rec.meta.rig.piston_area);
  if (rec.meta.rig.chamber_volume) rig.insert("chamber_volume", *rec.meta.rig.chamber_volume);
  if (rec.meta.rig.rod_area) rig.insert("rod_area", *rec.meta.rig.rod_area);
  if (rec.meta.rig.gas_force) rig.insert("gas_force", *rec.meta.rig.gas_force);
  for (const auto& [k, v] : rec.meta.rig.extra) rig.insert(k, v);
  if (!rig.empty()) doc.insert("rig", rig);
  toml::table valve;
  if (!rec.meta.valve.case_file.empty()) {
    // Stored relative to the sidecar's folder when possible, as the format says.
    fs::path base = fs::absolute(fs::path(csv_path)).parent_path();
    fs::path rel = fs::absolute(rec.meta.valve.case_file).lexically_relative(base);
    valve.insert("case", rel.empty() ? rec.meta.valve.case_file : rel.string());
  }
  if (!rec.meta.valve.yield_current.empty()) {
    toml::array ic, py;
    for (double v : rec.meta.valve.yield_current) ic.push_back(v);
    for (double v : rec.meta.valve.yield_pressure) py.push_back(v);
    valve.insert("yield_current", ic);
    valve.insert("yield_pressure", py);
  }
  if (rec.meta.valve.viscous_resistance)
    valve.insert("viscous_resistance", *rec.meta.valve.viscous_resistance);
  if (!valve.empty()) doc.insert("valve", valve);
  toml::table coil;
  if (rec.meta.coil.resistance) coil.insert("resistance", *rec.meta.coil.resistance);
  if (rec.meta.coil.inductance) coil.insert("inductance", *rec.meta.coil.inductance);
  if (!coil.empty()) doc.insert("coil", coil);
  std::ostringstream side;
  side << "# sidecar of " << fs::path(csv_path).filename().string()
       << " (shared/docs/recording-format.md)\n"
       << doc << "\n";

  write_file_atomically(csv_path, csv.str());
  write_file_atomically(sidecar_path_for(csv_path), side.str());
}

}  // namespace rheomag::lumped
