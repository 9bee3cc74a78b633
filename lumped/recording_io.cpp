// CSV + TOML sidecar reader and atomic writer for recordings.

#include "lumped/recording_io.hpp"

#include <toml++/toml.h>

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "case/toml_section.hpp"
#include "core/atomic_file.hpp"
#include "core/closest_key.hpp"
#include "core/error.hpp"
#include "core/finite_output.hpp"
#include "core/input_file.hpp"
#include "core/output_set.hpp"
#include "core/quantity_domain.hpp"
#include "lumped/motion_glitches.hpp"

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

std::string column_si_unit(const std::string& column) {
  if (column == "t") return "s";
  if (column == "current" || column == "current_cmd") return "A";
  if (column == "voltage" || column == "command") return "V";
  if (column == "flow") return "m^3/s";
  if (column == "velocity") return "m/s";
  if (column == "displacement") return "m";
  if (column == "pressure") return "Pa";
  if (column == "force") return "N";
  if (column == "flux_linkage") return "Wb";
  return "degC";  // temperature
}

namespace {

bool is_known_column(const std::string& name) {
  const auto& k = known_columns();
  return std::find(k.begin(), k.end(), name) != k.end();
}

/// True if `unit` as a header writes it names the SI unit of `column` (m^3/s also as m3/s or m³/s,
/// degC also as °C or C).
bool is_si_unit_of(const std::string& unit, const std::string& column) {
  const std::string si = column_si_unit(column);
  if (unit == si) return true;
  if (si == "m^3/s") return unit == "m3/s" || unit == "m\u00b3/s";
  if (si == "degC") return unit == "\u00b0C" || unit == "C";
  return false;
}

/// A header cell "name [unit]" or "name (unit)": the name and the unit ("" if none).
std::pair<std::string, std::string> split_unit(const std::string& header) {
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const std::size_t at = header.find(open);
    if (at != std::string::npos && at > 0 && header.back() == close) {
      std::string name = header.substr(0, at), unit = header.substr(at + 1);
      unit.pop_back();
      while (!name.empty() && (name.back() == ' ' || name.back() == '_')) name.pop_back();
      return {name, unit};
    }
  }
  return {header, ""};
}

/// The known column a header names: itself, or "name [unit]" with the column's SI unit. Throws at
/// `line` for a known name with another unit (the format is SI: the file must be converted).
/// "" for an unknown column.
std::string column_named(const std::string& header, const std::string& file, std::size_t line);

std::string lower_case(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// A hint for an unknown header cell: the known column it resembles (case, "time"), or "".
std::string column_hint(const std::string& header) {
  const std::string name = lower_case(split_unit(header).first);
  const std::string column = name == "time" ? "t" : name;
  if (is_known_column(column))
    return "; did you mean '" + column +
           "'? (columns are named in lower case, in SI units: " + column + " in " +
           column_si_unit(column) + ")";
  const std::string near = closest_key(name, known_columns());
  return near.empty() ? "" : "; did you mean '" + near + "'?";
}

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return std::string(s.substr(a, b - a));
}

/// The cells of one CSV line: split at commas outside double quotes, each trimmed, a quoted cell
/// ("force", as spreadsheets and some DAQ exports write them) unquoted with "" read as ".
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> raw(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted)
      raw.emplace_back();
    else
      raw.back() += c;
  }
  std::vector<std::string> cells;
  for (const std::string& r : raw) {
    std::string cell = trim(r);
    if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') {
      std::string inner;
      for (std::size_t i = 1; i + 1 < cell.size(); ++i) {
        inner += cell[i];
        if (cell[i] == '"' && cell[i + 1] == '"') ++i;  // "" is one quote
      }
      cell = trim(inner);
    }
    cells.push_back(cell);
  }
  return cells;
}

/// Largest |value| a recording's cell may hold (SI units).
constexpr double kLargestRecordedMagnitude = 1e15;

[[noreturn]] void fail_at(const std::string& file, std::size_t line, const std::string& what) {
  throw InputError(file + ":" + std::to_string(line) + ": " + what);
}

std::string column_named(const std::string& header, const std::string& file, std::size_t line) {
  if (is_known_column(header)) return header;
  const auto [name, unit] = split_unit(header);
  if (unit.empty() || !is_known_column(name)) return "";
  if (!is_si_unit_of(unit, name))
    fail_at(file, line,
            "column '" + header + "': the recording format's '" + name + "' is in " +
                column_si_unit(name) + "; convert the column to " + column_si_unit(name) +
                " (the format is SI throughout)");
  return name;
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
  // No recorded quantity in SI units comes near 1e15 (31 million years, 1e15 N or Pa); such a
  // value is a corrupt cell, and its square would overflow every norm computed from it.
  if (std::abs(value) > kLargestRecordedMagnitude)
    fail_at(file, line,
            "'" + cell + "' in column '" + column +
                "' is beyond any measured magnitude (|value| > 1e15 in SI units); expected a "
                "measured value");
  return value;
}

std::string format_number(double v) {
  char buffer[64];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  (void)ec;
  return std::string(buffer, ptr);
}

}  // namespace

namespace {

/// Areas and volumes of a rig: positive physical sizes, at most 10 m^2 (a 3.5 m bore) and
/// 10 m^3, so a value off by hundreds of orders of magnitude is refused, not simulated.
constexpr Domain kArea = Domain::between(0.0, 10.0, "m^2").above(0.0);
constexpr Domain kVolume = Domain::between(0.0, 10.0, "m^3").above(0.0);

}  // namespace

RecordingMeta parse_sidecar(std::string_view text, const std::string& toml_path) {
  using cases::TomlSection;
  const toml::table doc = cases::parse_toml(text, toml_path);
  const TomlSection top(doc, "", toml_path);
  // The format is open to extension (other tables and keys are kept or ignored), but a key one
  // or two letters off a known one is a typo that would silently drop a value.
  top.refuse_near_misses({"recording", "rig", "valve", "coil"});
  RecordingMeta meta;
  meta.sidecar_path = toml_path;
  const std::optional<TomlSection> rec = top.table("recording");
  if (!rec) top.fail("recording", "missing; expected a [recording] table with drive and output");
  rec->refuse_near_misses({"description", "drive", "output"});
  meta.description = rec->string("description").value_or("");
  meta.drive = rec->strings("drive");
  if (meta.drive.empty()) rec->fail("drive", "expected a non-empty list of column names");
  meta.output = rec->required_string("output");
  // A drive column listed twice makes the regressors collinear; the output as a drive makes the
  // model explain the signal with itself (an ARX fit of it went unstable, |pole| = 2e13).
  for (auto d = meta.drive.begin(); d != meta.drive.end(); ++d) {
    if (*d == meta.output)
      rec->fail("drive", "column '" + *d +
                             "' is also the output; expected the measured inputs that drive the "
                             "model (e.g. velocity, current), not the signal it explains");
    if (std::find(meta.drive.begin(), d, *d) != d)
      rec->fail("drive", "column '" + *d + "' is listed twice; expected each drive column once");
  }

  if (const std::optional<TomlSection> rig = top.table("rig")) {
    static const std::vector<std::string_view> declared{
        "kind",      "piston_area", "chamber_volume", "rod_area",
        "gas_force", "orientation", "driver_gain"};
    rig->refuse_near_misses(declared);
    if (rig->has("kind"))
      meta.rig.kind = rig->choice_or("kind", kRigKindNames, RigKind::constant_velocity_pump);
    meta.rig.piston_area = rig->optional_quantity("piston_area", kArea);
    meta.rig.chamber_volume = rig->optional_quantity("chamber_volume", kVolume);
    meta.rig.rod_area = rig->optional_quantity("rod_area", Domain::non_negative("m^2"));
    if (meta.rig.rod_area && meta.rig.piston_area && !(*meta.rig.rod_area < *meta.rig.piston_area))
      rig->fail("rod_area",
                "expected less than piston_area = " + cases::format_number(*meta.rig.piston_area) +
                    " m^2, got " + cases::format_number(*meta.rig.rod_area));
    meta.rig.gas_force = rig->optional_quantity("gas_force", Domain::finite("N"));
    if (auto o = rig->optional_quantity("orientation", Domain::between(-1.0, 1.0).whole())) {
      if (*o == 0.0) rig->fail("orientation", "expected 1 or -1, got 0");
      meta.rig.extra["orientation"] = *o;
    }
    if (auto gain = rig->optional_quantity("driver_gain", Domain::finite("A/V")))
      meta.rig.extra["driver_gain"] = *gain;
    for (const auto& [key, node] : rig->raw()) {
      const std::string_view k = key.str();
      if (std::find(declared.begin(), declared.end(), k) != declared.end()) continue;
      if (node.is_number()) meta.rig.extra[std::string(k)] = rig->quantity(k, Domain::finite());
    }
  }
  if (const std::optional<TomlSection> valve = top.table("valve")) {
    valve->refuse_near_misses({"case", "yield_current", "yield_pressure", "viscous_resistance"});
    if (auto c = valve->string("case")) {
      fs::path p(*c);
      if (p.is_relative()) p = fs::path(toml_path).parent_path() / p;
      meta.valve.case_file = p.lexically_normal().string();
    }
    meta.valve.yield_current = valve->quantities("yield_current", Domain::finite("A"));
    meta.valve.yield_pressure = valve->quantities("yield_pressure", Domain::non_negative("Pa"));
    if (meta.valve.yield_current.size() != meta.valve.yield_pressure.size())
      valve->fail("yield_pressure", "has " + std::to_string(meta.valve.yield_pressure.size()) +
                                        " values, yield_current " +
                                        std::to_string(meta.valve.yield_current.size()) +
                                        "; expected one pressure per current");
    for (std::size_t i = 1; i < meta.valve.yield_current.size(); ++i)
      if (!(meta.valve.yield_current[i] > meta.valve.yield_current[i - 1]))
        valve->fail("yield_current", "expected strictly increasing currents");
    meta.valve.viscous_resistance =
        valve->optional_quantity("viscous_resistance", Domain::positive("Pa s/m^3"));
  }
  if (const std::optional<TomlSection> coil = top.table("coil")) {
    coil->refuse_near_misses({"resistance", "inductance"});
    meta.coil.resistance = coil->optional_quantity("resistance", Domain::positive("ohm"));
    meta.coil.inductance = coil->optional_quantity("inductance", Domain::non_negative("H"));
  }
  return meta;
}

RecordingMeta read_sidecar(const std::string& toml_path) {
  if (!fs::exists(toml_path))
    throw InputError(toml_path +
                     ": sidecar not found (every recording CSV needs a TOML sidecar "
                     "with the same stem; see shared/docs/recording-format.md)");
  return parse_sidecar(cases::read_input_file(toml_path), toml_path);
}

Recording parse_csv_samples(std::string_view text, const std::string& csv_path) {
  std::vector<std::string> warnings;
  // A UTF-8 byte-order mark (what many Windows tools write first) is not part of the header.
  text = cases::without_byte_order_mark(text);
  std::istringstream in{std::string(text)};
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
  if (header.size() == 1)
    for (const char separator : {';', '\t', ' '})
      if (header[0].find(separator) != std::string::npos)
        fail_at(
            csv_path, line_no,
            "the header '" + header[0] +
                "' has no comma; expected comma-separated columns "
                "(',' between cells, '.' as the decimal point), this file seems to use " +
                (separator == '\t' ? std::string("tabs") : "'" + std::string(1, separator) + "'"));
  std::vector<int> slot(header.size(), -1);  // index into `kept`, -1 for ignored columns
  std::vector<std::string> kept;
  std::set<std::string> seen;
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (header[c].empty()) {  // spreadsheet exports end rows with a comma
      warnings.push_back(csv_path + ": ignoring unnamed column " + std::to_string(c + 1) +
                         " (an empty header cell)");
      continue;
    }
    const std::string name = column_named(header[c], csv_path, line_no);
    if (!seen.insert(name.empty() ? header[c] : name).second)
      fail_at(csv_path, line_no,
              "column '" + header[c] + "' appears twice" +
                  (name.empty() || name == header[c] ? "" : " (as '" + name + "')"));
    if (!name.empty()) {
      slot[c] = static_cast<int>(kept.size());
      kept.push_back(name);
    } else {
      warnings.push_back(csv_path + ": ignoring unknown column '" + header[c] + "'" +
                         column_hint(header[c]));
    }
  }
  if (!seen.count("t")) {
    std::string hint;
    for (const std::string& h : header)
      if (hint.empty() && column_hint(h).find("'t'") != std::string::npos)
        hint = "; the header has '" + h + "': name it 't'";
    fail_at(csv_path, line_no, "no 't' column (time in s is required)" + hint);
  }
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

Recording read_csv_samples(const std::string& csv_path) {
  require_regular_input_file(csv_path, "recording CSV");
  return parse_csv_samples(cases::read_input_file(csv_path), csv_path);
}

Recording read_recording(const std::string& csv_path) {
  if (!fs::exists(csv_path)) throw InputError(csv_path + ": recording not found");
  require_regular_input_file(csv_path, "recording CSV");
  std::string sidecar = sidecar_path_for(csv_path);
  // A recording exported on Windows may come as REC.CSV + REC.TOML: the same stem, the
  // extension in capitals.
  if (fs::path upper(csv_path);
      !fs::exists(sidecar) && fs::exists(upper.replace_extension(".TOML")))
    sidecar = upper.string();
  RecordingMeta meta = read_sidecar(sidecar);
  Recording rec = read_csv_samples(csv_path);
  rec.meta = std::move(meta);
  const auto missing = [&](const std::string& role, const std::string& name) {
    std::string present;
    for (const auto& column : rec.columns) present += ", " + column.first;
    throw InputError(sidecar + ": [recording] " + role + " column '" + name + "' is not in " +
                     csv_path + " (its columns: t" + present + ")" +
                     (is_known_column(name) ? "" : column_hint(name)));
  };
  for (const auto& d : rec.meta.drive)
    if (!rec.columns.count(d)) missing("drive", d);
  if (!rec.columns.count(rec.meta.output)) missing("output", rec.meta.output);
  for (const auto& d : rec.meta.drive) {
    const MotionGlitches glitches = find_motion_glitches(rec, d);
    if (!glitches.samples.empty())
      rec.warnings.push_back(csv_path + ": " + describe_glitches(d, glitches, rec.t) +
                             "; diagnose and the grey-box models (fit, fit-family, simulate) "
                             "replace each by its neighbours' path, the other models read "
                             "them as recorded");
  }
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
  std::vector<std::string> names;
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
    names.push_back(name);
  }
  csv << "\n";
  for (std::size_t i = 0; i < rec.t.size(); ++i) {
    csv << format_number(rec.t[i]);
    for (std::size_t k = 0; k < cols.size(); ++k) {
      // A simulated output that overflowed (a model with absurd parameters) is a result, not a
      // bad input: exit 3 naming the column and time, as every other non-finite output.
      if (!std::isfinite((*cols[k])[i]))
        throw NonFiniteOutputError(csv_path + ": column '" + names[k] + "' at sample " +
                                   std::to_string(i) + " (t = " + format_number(rec.t[i]) +
                                   " s) is not a finite number; the recording was not written");
      csv << "," << format_number((*cols[k])[i]);
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

  // The CSV and its sidecar replace the old pair together: a failure keeps both old files.
  const fs::path csv_file(csv_path), sidecar_file(sidecar_path_for(csv_path));
  OutputSet pair(csv_file.parent_path(), csv_path, OutputSet::Folder::must_exist);
  pair.write(csv_file.filename().string(),
             [&](const fs::path& to) { write_file_atomically(to, csv.str()); });
  pair.write(sidecar_file.filename().string(),
             [&](const fs::path& to) { write_file_atomically(to, side.str()); });
  pair.commit();
}

}  // namespace rheomag::lumped
