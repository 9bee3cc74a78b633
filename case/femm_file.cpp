// A FEMM 4.2 .fem text read into its raw sections (see femm_file.hpp). Format facts from the
// FEMM 4.2 manual and the .fem reader of xfemm (cfemm/libfemm); no code taken from either.

#include "case/femm_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <tuple>

#include "case/toml_section.hpp"
#include "core/error.hpp"

namespace rheomag::cases::femm {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

/// Splits "[Key] = value" or "<Key> = value" into lower-case key and trimmed value.
std::pair<std::string, std::string_view> key_value(std::string_view line, char close) {
  const std::size_t end = line.find(close);
  const std::string key = lower(line.substr(1, end == std::string_view::npos ? 0 : end - 1));
  std::string_view value;
  const std::size_t equals = line.find('=');
  if (equals != std::string_view::npos) value = trim(line.substr(equals + 1));
  return {key, value};
}

std::string unquote(std::string_view value) {
  value = trim(value);
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
    value = value.substr(1, value.size() - 2);
  return std::string(value);
}

double length_unit(std::string_view value, FemReader& reader) {
  const std::string unit = lower(unquote(value));
  if (unit == "inches") return 0.0254;
  if (unit == "millimeters") return 1e-3;
  if (unit == "centimeters") return 1e-2;
  if (unit == "meters") return 1.0;
  if (unit == "mils") return 2.54e-5;
  if (unit == "micrometers") return 1e-6;
  reader.fail(reader.line_number(),
              "[LengthUnits]: expected inches, millimeters, centimeters, meters, mils or "
              "micrometers, got '" +
                  unit + "'");
}

/// The two point numbers (columns 1 and 2) of the segment or arc line just read; they must be
/// whole numbers.
std::pair<int, int> edge_ends(const std::vector<double>& c, const FemReader& reader,
                              const std::string& what) {
  if (c[0] != std::floor(c[0]) || c[1] != std::floor(c[1]) || std::abs(c[0]) > 1e9 ||
      std::abs(c[1]) > 1e9)
    reader.fail(reader.line_number(), what + " point numbers must be integers");
  return {static_cast<int>(c[0]), static_cast<int>(c[1])};
}

int count_value(std::string_view value, FemReader& reader, const std::string& key) {
  const int n = reader.integer(value, "[" + key + "]");
  if (n < 0 || n > 10000000)
    reader.fail(reader.line_number(),
                "[" + key + "]: expected a count in [0, 10000000], got " + std::to_string(n));
  return n;
}

void read_property_block(FemReader& reader, FemFile& file, const std::string& begin) {
  const int start = reader.line_number();
  const std::string end = "end" + begin.substr(5);
  FemBoundary boundary;
  FemBlock block;
  FemCircuit circuit;
  FemPointProp point;
  boundary.line = block.line = circuit.line = point.line = start;
  while (true) {
    const std::string_view line =
        reader.require("<" + end + "> closing the block opened at line " + std::to_string(start));
    if (line.front() != '<')
      reader.fail(reader.line_number(), "expected a <Key> = value line inside <" + begin + ">");
    const auto [key, value] = key_value(line, '>');
    const std::string what = "<" + key + ">";
    if (key == end) break;
    if (key.rfind("begin", 0) == 0)
      reader.fail(reader.line_number(), "<" + key + "> inside <" + begin + "> opened at line " +
                                            std::to_string(start) + " (missing <" + end + ">)");
    if (begin == "beginbdry") {
      if (key == "bdryname")
        boundary.name = unquote(value);
      else if (key == "bdrytype")
        boundary.type = reader.integer(value, what);
      else if (key == "a_0")
        boundary.a0 = reader.number(value, what);
      else if (key == "a_1")
        boundary.a1 = reader.number(value, what);
      else if (key == "a_2")
        boundary.a2 = reader.number(value, what);
      else if (key == "phi")
        boundary.phi = reader.number(value, what);
      else if (key == "c0")
        boundary.c0 = reader.number(value, what);
      else if (key == "c1")
        boundary.c1 = reader.number(value, what);
    } else if (begin == "beginblock") {
      if (key == "blockname")
        block.name = unquote(value);
      else if (key == "mu_x")
        block.mu_x = reader.number(value, what);
      else if (key == "mu_y")
        block.mu_y = reader.number(value, what);
      else if (key == "h_c")
        block.h_c = reader.number(value, what);
      else if (key == "h_cangle")
        block.h_c_angle = reader.number(value, what);
      else if (key == "j_re")
        block.j = reader.number(value, what);
      else if (key == "sigma")
        block.sigma = reader.number(value, what);
      else if (key == "lamtype")
        block.lam_type = reader.integer(value, what);
      else if (key == "lamfill")
        block.lam_fill = reader.number(value, what);
      else if (key == "bhpoints") {
        const int n = count_value(value, reader, "BHPoints");
        for (int i = 0; i < n; ++i) {
          const std::vector<double> bh = reader.columns(
              reader.require("B-H point " + std::to_string(i + 1) + " of " + std::to_string(n)), 2,
              "B-H point");
          block.bh.emplace_back(bh[0], bh[1]);
        }
      }
    } else if (begin == "begincircuit") {
      if (key == "circuitname")
        circuit.name = unquote(value);
      else if (key == "totalamps_re")
        circuit.amps = reader.number(value, what);
      else if (key == "circuittype")
        circuit.type = reader.integer(value, what);
    } else if (begin == "beginpoint") {
      if (key == "pointname")
        point.name = unquote(value);
      else if (key == "i_re")
        point.i_re = reader.number(value, what);
      else if (key == "i_im")
        point.i_im = reader.number(value, what);
      else if (key == "a_re")
        point.a_re = reader.number(value, what);
      else if (key == "a_im")
        point.a_im = reader.number(value, what);
    }
    // Other keys (complex parts, wire and hysteresis data, ...) do not affect magnetostatics.
  }
  if (begin == "beginbdry")
    file.boundaries.push_back(boundary);
  else if (begin == "beginblock")
    file.blocks.push_back(block);
  else if (begin == "begincircuit")
    file.circuits.push_back(circuit);
  else
    file.point_props.push_back(point);
}

}  // namespace

FemReader::FemReader(std::string_view text, std::string source) : source_(std::move(source)) {
  // FEMM writes none, but a .fem saved by a Windows editor may start with a byte-order mark.
  text = without_byte_order_mark(text);
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    lines_.emplace_back(text.substr(start, end - start));
    if (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n')
      ++end;
    start = end + 1;
  }
}

std::string FemReader::where(int line) const {
  return source_ + ":" + std::to_string(line);
}

void FemReader::fail(int line, const std::string& message) const {
  throw InputError(where(line) + ": " + message);
}

bool FemReader::next(std::string_view& line) {
  while (index_ < lines_.size()) {
    line = trim(lines_[index_++]);
    if (!line.empty()) return true;
  }
  return false;
}

std::string_view FemReader::require(const std::string& what) {
  std::string_view line;
  if (!next(line)) fail(line_number(), "file ends early: expected " + what);
  return line;
}

std::string_view FemReader::current_line() const {
  return index_ > 0 ? trim(lines_[index_ - 1]) : std::string_view();
}

double FemReader::number(std::string_view token, const std::string& what) const {
  const std::string text(trim(token));
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    fail(line_number(), "expected a number for " + what + ", got '" + text + "'");
  if (!std::isfinite(value))
    fail(line_number(), "expected a finite number for " + what + ", got '" + text + "'");
  return value;
}

int FemReader::integer(std::string_view token, const std::string& what) const {
  const double value = number(token, what);
  if (value != std::floor(value) || std::abs(value) > 1e9)
    fail(line_number(), "expected an integer for " + what + ", got '" + std::string(token) + "'");
  return static_cast<int>(value);
}

std::vector<double> FemReader::columns(std::string_view line, std::size_t minimum,
                                       const std::string& what) {
  std::vector<double> values;
  std::istringstream in{std::string(line)};
  std::string token;
  while (in >> token) {
    if (token.front() == '"') break;
    values.push_back(number(token, what));
  }
  if (values.size() < minimum)
    fail(line_number(), what + ": expected at least " + std::to_string(minimum) + " numbers, got " +
                            std::to_string(values.size()));
  return values;
}

FemFile read_fem_text(std::string_view text, FemReader& reader) {
  FemFile file;
  bool frequency_seen = false;
  std::string_view line;
  static const std::vector<std::string> ignored{
      "format",   "precision", "minangle", "dosmartmesh", "smartmesh",
      "acsolver", "prevtype",  "prevsoln", "comment",     "forcemaxmesh"};
  (void)text;
  while (reader.next(line)) {
    const int at = reader.line_number();
    if (line.front() == '<') {
      const auto [key, value] = key_value(line, '>');
      if (key == "beginbdry" || key == "beginblock" || key == "begincircuit" ||
          key == "beginpoint") {
        read_property_block(reader, file, key);
        continue;
      }
      reader.fail(at, "unexpected '" + std::string(line) + "' outside a property block");
    }
    if (line.front() != '[' || line.find(']') == std::string_view::npos)
      reader.fail(at,
                  "expected a [Key] = value line, got '" + std::string(line.substr(0, 60)) + "'");
    const auto [key, value] = key_value(line, ']');
    if (key == "solution") break;
    if (line.find('=') == std::string_view::npos) reader.fail(at, "[" + key + "] has no '= value'");
    if (key == "frequency") {
      frequency_seen = true;
      if (reader.number(value, "[Frequency]") != 0.0)
        reader.fail(at,
                    "[Frequency] is not 0: time-harmonic problems are not supported (rheomag "
                    "solves magnetostatics; set the frequency to 0)");
    } else if (key == "depth") {
      file.depth = reader.number(value, "[Depth]");
      file.depth_line = at;
    } else if (key == "extzo" || key == "extro" || key == "extri") {
      const double v = reader.number(value, "[" + key + "]");
      (key == "extzo" ? file.ext_zo : key == "extro" ? file.ext_ro : file.ext_ri) = v;
      file.ext_line = at;
    } else if (key == "coordinates") {
      const std::string type = lower(unquote(value));
      if (type != "cartesian" && type != "polar")
        reader.fail(at, "[Coordinates]: expected cartesian or polar, got '" + type + "'");
      file.polar = type == "polar";
      file.coordinates_line = at;
    } else if (key == "lengthunits") {
      file.unit = length_unit(value, reader);
    } else if (key == "problemtype") {
      const std::string type = lower(unquote(value));
      if (type == "axisymmetric")
        file.axisymmetric = true;
      else if (type == "planar")
        file.axisymmetric = false;
      else
        reader.fail(at, "[ProblemType]: expected planar or axisymmetric, got '" + type + "'");
    } else if (key == "bdryprops" || key == "blockprops" || key == "circuitprops" ||
               key == "pointprops") {
      file.declared[key] = count_value(value, reader, key);
      file.declared_line[key] = at;
    } else if (key == "numpoints") {
      const int n = count_value(value, reader, "NumPoints");
      for (int i = 0; i < n; ++i) {
        const std::vector<double> c = reader.columns(
            reader.require("point " + std::to_string(i + 1) + " of " + std::to_string(n) +
                           " after [NumPoints] (line " + std::to_string(at) + ")"),
            2, "point");
        if (c.size() > 2 && (c[2] != std::floor(c[2]) || std::abs(c[2]) > 1e9))
          reader.fail(reader.line_number(), "point property number must be an integer");
        file.points.push_back({{c[0], c[1]}, c.size() > 2 ? static_cast<int>(c[2]) : 0});
        file.point_lines.push_back(reader.line_number());
      }
    } else if (key == "numsegments") {
      const int n = count_value(value, reader, "NumSegments");
      for (int i = 0; i < n; ++i) {
        const std::vector<double> c = reader.columns(
            reader.require("segment " + std::to_string(i + 1) + " of " + std::to_string(n) +
                           " after [NumSegments] (line " + std::to_string(at) + ")"),
            2, "segment");
        FemSegment s;
        s.line = reader.line_number();
        std::tie(s.n0, s.n1) = edge_ends(c, reader, "segment");
        s.max_length = c.size() > 2 ? c[2] : -1;
        s.marker = c.size() > 3 && std::abs(c[3]) < 1e9 ? static_cast<int>(c[3]) : 0;
        file.segments.push_back(s);
      }
    } else if (key == "numarcsegments") {
      const int n = count_value(value, reader, "NumArcSegments");
      for (int i = 0; i < n; ++i) {
        const std::vector<double> c = reader.columns(
            reader.require("arc segment " + std::to_string(i + 1) + " of " + std::to_string(n) +
                           " after [NumArcSegments] (line " + std::to_string(at) + ")"),
            3, "arc segment");
        FemArc a;
        a.line = reader.line_number();
        std::tie(a.n0, a.n1) = edge_ends(c, reader, "arc segment");
        a.degrees = c[2];
        a.max_side_degrees = c.size() > 3 ? c[3] : 10.0;
        a.marker = c.size() > 4 && std::abs(c[4]) < 1e9 ? static_cast<int>(c[4]) : 0;
        file.arcs.push_back(a);
      }
    } else if (key == "numholes") {
      const int n = count_value(value, reader, "NumHoles");
      for (int i = 0; i < n; ++i) {
        const std::vector<double> c = reader.columns(
            reader.require("hole " + std::to_string(i + 1) + " of " + std::to_string(n)), 2,
            "hole");
        FemLabel hole;
        hole.x = c[0];
        hole.y = c[1];
        hole.line = reader.line_number();
        file.holes.push_back(hole);
      }
    } else if (key == "numblocklabels") {
      const int n = count_value(value, reader, "NumBlockLabels");
      for (int i = 0; i < n; ++i) {
        const std::vector<double> c = reader.columns(
            reader.require("block label " + std::to_string(i + 1) + " of " + std::to_string(n) +
                           " after [NumBlockLabels] (line " + std::to_string(at) + ")"),
            3, "block label");
        FemLabel label;
        label.line = reader.line_number();
        const std::string_view row = reader.current_line();
        if (const std::size_t open = row.find('"'); open != std::string_view::npos) {
          const std::size_t close = row.find('"', open + 1);
          if (close == std::string_view::npos)
            reader.fail(label.line, "unterminated quoted magnetisation direction expression");
          label.magdir_expression = std::string(trim(row.substr(open + 1, close - open - 1)));
        }
        label.x = c[0];
        label.y = c[1];
        for (const auto& [k, name] : {std::pair<std::size_t, const char*>{2, "block type"},
                                      {4, "circuit"},
                                      {6, "group"},
                                      {7, "turns"},
                                      {8, "isexternal"}})
          if (k < c.size() && (c[k] != std::floor(c[k]) || std::abs(c[k]) > 1e9))
            reader.fail(label.line, "block label column " + std::to_string(k + 1) + " (" + name +
                                        "): expected a whole number within +-1e9, got " +
                                        format_number(c[k]));
        label.block = static_cast<int>(c[2]);
        label.size = c.size() > 3 ? c[3] : -1;
        label.circuit = c.size() > 4 ? static_cast<int>(c[4]) : 0;
        label.magdir = c.size() > 5 ? c[5] : 0;
        label.group = c.size() > 6 ? static_cast<int>(c[6]) : 0;
        label.turns = c.size() > 7 ? static_cast<int>(c[7]) : 1;
        label.external = c.size() > 8 ? static_cast<int>(c[8]) : 0;
        file.labels.push_back(label);
      }
    } else if (std::find(ignored.begin(), ignored.end(), key) == ignored.end()) {
      reader.fail(at, "unknown .fem key [" + key + "]");
    }
  }
  if (!frequency_seen)
    reader.fail(reader.line_number(),
                "not a FEMM magnetics file: no [Frequency] key (is this a .fem from FEMM 4.2?)");
  const std::pair<const char*, std::size_t> counts[] = {{"bdryprops", file.boundaries.size()},
                                                        {"blockprops", file.blocks.size()},
                                                        {"circuitprops", file.circuits.size()},
                                                        {"pointprops", file.point_props.size()}};
  for (const auto& [key, found] : counts) {
    auto it = file.declared.find(key);
    const std::size_t declared = it == file.declared.end() ? 0 : it->second;
    if (declared != found)
      reader.fail(it == file.declared.end() ? reader.line_number() : file.declared_line[key],
                  "[" + std::string(key) + "] declares " + std::to_string(declared) +
                      " properties but the file has " + std::to_string(found) +
                      " (truncated or malformed)");
  }
  return file;
}

}  // namespace rheomag::cases::femm
