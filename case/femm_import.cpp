// FEMM 4.2 .fem (magnetostatic) reader. Format facts from the FEMM 4.2 manual and the .fem
// reader of xfemm (cfemm/libfemm); no code taken from either.

#include "case/femm_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

#include "case/femm_bh_smoothing.hpp"
#include "case/femm_hole_areas.hpp"
#include "case/magnet_direction.hpp"
#include "case/material_library.hpp"
#include "case/region_outline.hpp"
#include "case/toml_section.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::cases {

double femm_mesh_size_to_edge(double femm_size) {
  return femm_size * std::sqrt(std::numbers::pi / std::sqrt(3.0));
}

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

/// The raw .fem data of one boundary property.
struct FemBoundary {
  std::string name;
  int type = 0;
  double a0 = 0, a1 = 0, a2 = 0, phi = 0, c0 = 0, c1 = 0;
  int line = 0;
};

/// The raw .fem data of one block (material) property.
struct FemBlock {
  std::string name;
  double mu_x = 1, mu_y = 1, h_c = 0, h_c_angle = 0, j = 0, sigma = 0, lam_fill = 1;
  int lam_type = 0;
  std::vector<std::pair<double, double>> bh;
  int line = 0;
};

/// The raw .fem data of one point property.
struct FemPointProp {
  std::string name;
  double i_re = 0, i_im = 0, a_re = 0, a_im = 0;
  int line = 0;
};

/// The raw .fem data of one circuit.
struct FemCircuit {
  std::string name;
  double amps = 0;
  int type = 0;
  int line = 0;
};

struct FemLabel {
  double x = 0, y = 0, size = -1, magdir = 0;
  std::string magdir_expression;  // FEMM's direction expression (quoted last column)
  int block = 0, circuit = 0, group = 0, turns = 1, external = 0;
  int line = 0;
};

struct FemArc {
  int n0 = 0, n1 = 0, marker = 0, line = 0;
  double degrees = 0, max_side_degrees = 0;
};

struct FemSegment {
  int n0 = 0, n1 = 0, marker = 0, line = 0;
  double max_length = -1;
};

/// Line-by-line reader with file:line error messages.
class FemReader {
 public:
  FemReader(std::string_view text, std::string source) : source_(std::move(source)) {
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

  /// "file:line", the prefix of every message about that line.
  std::string where(int line) const { return source_ + ":" + std::to_string(line); }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(where(line) + ": " + message);
  }

  bool next(std::string_view& line) {
    while (index_ < lines_.size()) {
      line = trim(lines_[index_++]);
      if (!line.empty()) return true;
    }
    return false;
  }

  /// The next non-empty line, which must exist (`what` says what was expected).
  std::string_view require(const std::string& what) {
    std::string_view line;
    if (!next(line)) fail(line_number(), "file ends early: expected " + what);
    return line;
  }

  int line_number() const { return static_cast<int>(index_); }
  /// The line last returned by next() or require(), trimmed.
  std::string_view current_line() const {
    return index_ > 0 ? trim(lines_[index_ - 1]) : std::string_view();
  }
  const std::string& source() const { return source_; }

  double number(std::string_view token, const std::string& what) const {
    const std::string text(trim(token));
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
      fail(line_number(), "expected a number for " + what + ", got '" + text + "'");
    if (!std::isfinite(value))
      fail(line_number(), "expected a finite number for " + what + ", got '" + text + "'");
    return value;
  }

  int integer(std::string_view token, const std::string& what) const {
    const double value = number(token, what);
    if (value != std::floor(value) || std::abs(value) > 1e9)
      fail(line_number(), "expected an integer for " + what + ", got '" + std::string(token) + "'");
    return static_cast<int>(value);
  }

  /// Whitespace-separated numeric columns of a data line (quoted strings end the columns).
  std::vector<double> columns(std::string_view line, std::size_t minimum, const std::string& what) {
    std::vector<double> values;
    std::istringstream in{std::string(line)};
    std::string token;
    while (in >> token) {
      if (token.front() == '"') break;
      values.push_back(number(token, what));
    }
    if (values.size() < minimum)
      fail(line_number(), what + ": expected at least " + std::to_string(minimum) +
                              " numbers, got " + std::to_string(values.size()));
    return values;
  }

 private:
  std::vector<std::string_view> lines_;
  std::size_t index_ = 0;
  std::string source_;
};

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

/// Everything read from the file before conversion.
struct FemFile {
  double unit = 0.0254;  // FEMM's default length unit is inches
  double depth = 1.0;
  int depth_line = 0;
  bool axisymmetric = false;
  double ext_zo = 0.0, ext_ro = 0.0, ext_ri = 0.0;  // Kelvin exterior, file units
  int ext_line = 0;
  std::vector<FemBoundary> boundaries;
  std::vector<FemBlock> blocks;
  std::vector<FemCircuit> circuits;
  std::vector<FemPointProp> point_props;
  std::vector<std::pair<mesh::Point, int>> points;  // point, point-property marker
  std::vector<int> point_lines;
  std::vector<FemSegment> segments;
  std::vector<FemArc> arcs;
  std::vector<FemLabel> holes;
  std::vector<FemLabel> labels;
  std::map<std::string, int> declared;  // [BdryProps] etc. counts
  std::map<std::string, int> declared_line;
};

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

FemFile read_file(std::string_view text, FemReader& reader) {
  FemFile file;
  bool frequency_seen = false;
  std::string_view line;
  static const std::vector<std::string> ignored{
      "format",   "precision", "minangle", "dosmartmesh", "smartmesh",   "coordinates",
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
        if (c[0] != std::floor(c[0]) || c[1] != std::floor(c[1]) || std::abs(c[0]) > 1e9 ||
            std::abs(c[1]) > 1e9)
          reader.fail(s.line, "segment point numbers must be integers");
        s.n0 = static_cast<int>(c[0]);
        s.n1 = static_cast<int>(c[1]);
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
        if (c[0] != std::floor(c[0]) || c[1] != std::floor(c[1]) || std::abs(c[0]) > 1e9 ||
            std::abs(c[1]) > 1e9)
          reader.fail(a.line, "arc segment point numbers must be integers");
        a.n0 = static_cast<int>(c[0]);
        a.n1 = static_cast<int>(c[1]);
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

/// The material of one FEMM block as FEMM's magnetostatic solver uses it: lamination fill of
/// in-plane laminations folded into mu_r or the B-H curve (smoothed as FEMM does where its spline
/// turns back; a note is added to `warnings`), wire types (LamType >= 3) as mu_r = 1, linear and
/// nonlinear magnets with H_c; every other combination refused by name.
Material femm_material(const FemBlock& block, const std::string& source, const FemReader& reader,
                       std::vector<std::string>& warnings) {
  const std::string name = "block '" + block.name + "'";
  auto fail = [&](const std::string& message) { reader.fail(block.line, name + ": " + message); };
  Material m;
  m.name = block.name;
  m.source = "FEMM file " + source + ", block '" + block.name + "'";
  // A negative conductivity would make the transient solver's eddy currents grow without bound.
  if (!(block.sigma >= 0.0))
    fail("Sigma = " + format_number(block.sigma) + " MS/m; expected a conductivity >= 0");
  m.conductivity = block.sigma * 1e6;  // MS/m -> S/m (kept for eddy-current work)
  const double fill = block.lam_fill;
  if (!(fill > 0.0 && fill <= 1.0))
    fail("LamFill = " + format_number(fill) + "; expected a fill factor in (0, 1]");
  if (block.lam_type < 0 || block.lam_type > 6)
    fail("unknown LamType " + std::to_string(block.lam_type));
  if (block.h_c_angle != 0.0)
    fail("H_cAngle = " + format_number(block.h_c_angle) +
         " is not supported; give the magnetisation direction in the block label");
  if (block.lam_type >= 3) {
    // Wire (magnet, stranded, litz, square): FEMM's magnetostatic solver sets mu_r = 1 and
    // ignores the B-H curve; the winding's fill matters only at a frequency > 0.
    if (block.h_c != 0.0) fail("a wire block (LamType >= 3) cannot be a magnet (H_c not 0)");
    m.mu_r = 1.0;
    m.source += " (wire, LamType " + std::to_string(block.lam_type) + ": mu_r = 1 as in FEMM)";
    return m;
  }
  if ((block.lam_type == 1 || block.lam_type == 2) && fill != 1.0)
    fail("laminations parallel to x or y (LamType " + std::to_string(block.lam_type) +
         ") with LamFill < 1 make the material anisotropic, which is not supported");
  if (!block.bh.empty()) {
    // FEMM smooths a table whose spline turns back (femm_bh_smoothing.hpp), then applies the
    // fill of in-plane laminations (LamType 0), B' = f B(H) + (1 - f) mu0 H at the table's H
    // (FEMM's apparent curve), and checks the result again.
    const std::string where = source + ":" + std::to_string(block.line) + ": " + name;
    FemmSmoothedTable smoothed = femm_smoothed_bh_table(block.bh);
    int passes = smoothed.passes;
    if (fill != 1.0) {
      for (auto& [b, h] : smoothed.points) b = fill * b + (1.0 - fill) * kMu0 * h;
      smoothed = femm_smoothed_bh_table(std::move(smoothed.points));
      passes += smoothed.passes;
    }
    if (passes > 0) {
      std::string what = "the spline FEMM fits through the B-H table turns back (dH/dB < 0)";
      for (std::size_t i = 1; i < block.bh.size(); ++i)
        if (!(block.bh[i].first > block.bh[i - 1].first &&
              block.bh[i].second > block.bh[i - 1].second)) {
          what = "the B-H table does not increase at point " + std::to_string(i + 1) + " [" +
                 format_number(block.bh[i].first) + ", " + format_number(block.bh[i].second) + "]";
          break;
        }
      const std::string count = std::to_string(passes) + (passes == 1 ? " pass" : " passes");
      warnings.push_back(where + ": " + what +
                         "; smoothed as FEMM does: every interior point averaged with its two "
                         "neighbours, " +
                         count + ", until FEMM's spline rises throughout");
      m.source += " (B-H table smoothed as FEMM does, " + count + ")";
    }
    m.bh = checked_bh_table(smoothed.points, where);
    // A nonlinear magnet: FEMM's table is the magnet's curve shifted by H_c to start at (0, 0),
    // H = H_curve(|B|) B/|B| - H_c m; the magnet's load is the linear magnet's.
    m.coercivity = block.h_c;
    return m;
  }
  if (block.mu_x != block.mu_y) fail("anisotropic permeability (Mu_x != Mu_y) is not supported");
  if (!(block.mu_x > 0.0)) fail("Mu_x must be positive");
  m.mu_r = block.mu_x * fill + (1.0 - fill);
  m.coercivity = block.h_c;
  return m;
}

}  // namespace

/// Edge conditions of (anti)periodic properties: FEMM pairs the two edges (two segments or two
/// arcs, never more) that carry one periodic (BdryType 4) or antiperiodic (5) property (the
/// orientation is the solver's: BoundaryCondition::partner); both edges get the finer of their two
/// subdivisions. The first edge keeps the property's condition, the second gets its own,
/// partnered with it. Entries for edges without such a property stay -1.
struct PeriodicEdges {
  std::vector<int> segment_condition, arc_condition;  // problem.boundaries index or -1
  std::vector<double> segment_max_length;             // FEMM units, <= 0 = none
  std::vector<double> arc_max_degrees;
};

PeriodicEdges pair_periodic_edges(const FemFile& file, Problem& problem, FemReader& reader) {
  PeriodicEdges out;
  out.segment_condition.assign(file.segments.size(), -1);
  out.arc_condition.assign(file.arcs.size(), -1);
  for (const FemSegment& s : file.segments) out.segment_max_length.push_back(s.max_length);
  for (const FemArc& a : file.arcs) out.arc_max_degrees.push_back(a.max_side_degrees);
  const int count = static_cast<int>(file.boundaries.size());
  auto periodic = [&](int marker) {
    return marker >= 1 && marker <= count &&
           (file.boundaries[marker - 1].type == 4 || file.boundaries[marker - 1].type == 5);
  };
  struct Use {
    bool arc;
    int index, line;
  };
  std::vector<std::vector<Use>> uses(file.boundaries.size());
  for (std::size_t i = 0; i < file.segments.size(); ++i)
    if (periodic(file.segments[i].marker))
      uses[file.segments[i].marker - 1].push_back(
          {false, static_cast<int>(i), file.segments[i].line});
  for (std::size_t i = 0; i < file.arcs.size(); ++i)
    if (periodic(file.arcs[i].marker))
      uses[file.arcs[i].marker - 1].push_back({true, static_cast<int>(i), file.arcs[i].line});
  const auto& points = file.points;
  auto valid_point = [&](int n) { return n >= 0 && n < static_cast<int>(points.size()); };
  for (int b = 0; b < count; ++b) {
    const std::vector<Use>& use = uses[b];
    if (use.empty()) continue;  // an unused property is harmless
    const FemBoundary& bdry = file.boundaries[b];
    const std::string name = std::string(bdry.type == 4 ? "periodic" : "antiperiodic") +
                             " boundary '" + bdry.name + "' (BdryType " +
                             std::to_string(bdry.type) + ", defined at line " +
                             std::to_string(bdry.line) + ")";
    if (use.size() == 1) {
      // FEMM's mesher drops a property that pairs nothing; the edge gets no condition.
      problem.warnings.push_back(reader.where(use[0].line) + ": " + name +
                                 " is used by this edge only; it pairs nothing, so the edge gets "
                                 "no condition, as in FEMM (which drops such a property)");
      continue;
    }
    if (use.size() != 2) {
      std::string lines;
      for (const Use& u : use) lines += (lines.empty() ? "" : ", ") + std::to_string(u.line);
      reader.fail(use.back().line, name + " is used by " + std::to_string(use.size()) +
                                       " edge(s) (lines " + lines +
                                       "); it must pair exactly two edges, two segments or two "
                                       "arcs, as in FEMM: give each pair its own property");
    }
    if (use[0].arc != use[1].arc)
      reader.fail(use[1].line, name +
                                   " pairs a segment with an arc; it must pair two segments "
                                   "or two arcs, as in FEMM");
    if (!use[0].arc) {
      const FemSegment& s0 = file.segments[use[0].index];
      const FemSegment& s1 = file.segments[use[1].index];
      if (!valid_point(s0.n0) || !valid_point(s0.n1) || !valid_point(s1.n0) || !valid_point(s1.n1))
        continue;  // the segment loop names the bad point
      auto length = [&](const FemSegment& s) {
        return std::hypot(points[s.n1].first.r - points[s.n0].first.r,
                          points[s.n1].first.z - points[s.n0].first.z);
      };
      const double l0 = length(s0), l1 = length(s1);
      if (std::abs(l0 - l1) > 1e-6 * std::max(l0, l1))
        reader.fail(use[1].line, name + " pairs segments of different lengths (" +
                                     format_number(l0) + " at line " + std::to_string(s0.line) +
                                     ", " + format_number(l1) +
                                     " in the file's length unit); the paired edges must have "
                                     "the same length");
      double size = std::min(s0.max_length > 0 ? s0.max_length : s1.max_length,
                             s1.max_length > 0 ? s1.max_length : s0.max_length);
      out.segment_max_length[use[0].index] = out.segment_max_length[use[1].index] = size;
    } else {
      const FemArc& a0 = file.arcs[use[0].index];
      const FemArc& a1 = file.arcs[use[1].index];
      if (!valid_point(a0.n0) || !valid_point(a0.n1) || !valid_point(a1.n0) || !valid_point(a1.n1))
        continue;
      if (std::abs(a0.degrees - a1.degrees) > 1e-6)
        reader.fail(use[1].line, name + " pairs arcs of different angles (" +
                                     format_number(a0.degrees) + " deg at line " +
                                     std::to_string(a0.line) + ", " + format_number(a1.degrees) +
                                     " deg); the paired arcs must span the same angle");
      out.arc_max_degrees[use[0].index] = out.arc_max_degrees[use[1].index] =
          std::min(a0.max_side_degrees, a1.max_side_degrees);
    }
    BoundaryCondition& first = problem.boundaries[b];
    first.kind = bdry.type == 4 ? BoundaryKind::periodic : BoundaryKind::antiperiodic;
    first.pairs_by_angle = use[0].arc;  // FEMM pairs arcs of one angle, whatever their radii
    BoundaryCondition second = first;
    second.partner = b;
    first.partner = static_cast<int>(problem.boundaries.size());
    problem.boundaries.push_back(second);
    (use[0].arc ? out.arc_condition : out.segment_condition)[use[0].index] = b;
    (use[1].arc ? out.arc_condition : out.segment_condition)[use[1].index] = first.partner;
  }
  return out;
}

Problem parse_femm(std::string_view text, const std::string& source) {
  FemReader reader(text, source);
  const FemFile file = read_file(text, reader);
  auto fail = [&](int line, const std::string& message) { reader.fail(line, message); };

  Problem problem;
  problem.symmetry = file.axisymmetric ? Symmetry::axisymmetric : Symmetry::planar;
  // FEMM ignores [Depth] in axisymmetric problems (its Lua idiom mi_probdef(0, "millimeters",
  // "axi", ...) writes 0); a planar problem needs a positive depth.
  if (!file.axisymmetric && !(file.depth > 0))
    fail(file.depth_line,
         "[Depth] must be positive in a planar problem, got " + format_number(file.depth));
  problem.depth = file.axisymmetric ? 1.0 : file.depth * file.unit;
  problem.outer = OuterBoundary::none;
  problem.geometry.source = source;

  // Boundary properties: index i of the file -> index in problem.boundaries (or rejected).
  for (const FemBoundary& b : file.boundaries) {
    BoundaryCondition bc;
    bc.name = b.name;
    if (b.type == 0) {
      bc.kind = BoundaryKind::prescribed_a;
      bc.a_value = b.a0;
    } else if (b.type == 2) {
      bc.kind = BoundaryKind::mixed;
      // FEMM: (1/mu) dA/dn + c0 A + c1 = 0; rheomag: nu dA/dn + c0 A = c1.
      bc.c0 = b.c0;
      bc.c1 = -b.c1;
    }
    problem.boundaries.push_back(bc);
  }
  auto check_boundary_use = [&](int marker, int line) {
    if (marker == 0) return -1;
    if (marker < 0 || marker > static_cast<int>(file.boundaries.size()))
      fail(line, "boundary property number " + std::to_string(marker) +
                     " does not exist (the "
                     "file defines " +
                     std::to_string(file.boundaries.size()) + ")");
    const FemBoundary& b = file.boundaries[marker - 1];
    const std::string name =
        "boundary '" + b.name + "' (defined at line " + std::to_string(b.line) + ")";
    switch (b.type) {
      case 0:
        if (b.a1 != 0.0 || b.a2 != 0.0)
          reader.fail(line,
                      name +
                          ": prescribed A varying in space (A_1, A_2 not 0) is not supported; "
                          "only a constant A_0");
        break;
      case 2:
        break;
      case 1:
        reader.fail(line, name +
                              ": small skin depth boundaries (BdryType 1) describe eddy currents "
                              "at a frequency > 0 (time-harmonic only); not a magnetostatic "
                              "condition");
      case 3:
        reader.fail(line,
                    name +
                        ": strategic dual image boundaries (BdryType 3) are not supported; use "
                        "a mixed (asymptotic) boundary or rheomag's automatic open boundary");
      case 4:
      case 5:
        return -1;  // pair_periodic_edges gives each paired edge its condition, others none
      case 6:
      case 7:
        reader.fail(line, name + ": " + (b.type == 6 ? "periodic" : "antiperiodic") +
                              " air-gap elements (BdryType " + std::to_string(b.type) +
                              ") couple a rotor and a stator at an arbitrary angle (rotating "
                              "machines) and are not supported; model the air gap as a region");
      default:
        reader.fail(line, name + ": unknown BdryType " + std::to_string(b.type));
    }
    return marker - 1;
  };

  const PeriodicEdges periodic = pair_periodic_edges(file, problem, reader);

  // Points.
  for (std::size_t i = 0; i < file.points.size(); ++i) {
    const auto& [p, marker] = file.points[i];
    const int line = file.point_lines[i];
    if (file.axisymmetric && p.r < 0)
      fail(line, "axisymmetric model has a point at negative r = " + format_number(p.r));
    problem.geometry.points.push_back({p.r * file.unit, p.z * file.unit});
    if (marker == 0) continue;
    if (marker < 0 || marker > static_cast<int>(file.point_props.size()))
      fail(line, "point property number " + std::to_string(marker) +
                     " does not exist (the file defines " +
                     std::to_string(file.point_props.size()) + ")");
    const FemPointProp& prop = file.point_props[marker - 1];
    if (prop.i_im != 0.0 || prop.a_im != 0.0)
      fail(prop.line, "point property '" + prop.name +
                          "': imaginary parts (I_im, A_im) are time-harmonic only");
    // FEMM: a point with no current is a prescribed A (A_re), else a point current I_re [A].
    PointCondition condition;
    condition.name = prop.name;
    condition.point = static_cast<int>(i);
    condition.prescribed = prop.i_re == 0.0;
    condition.a_value = prop.a_re;
    condition.current = prop.i_re;
    problem.point_conditions.push_back(condition);
  }
  const int point_count = static_cast<int>(file.points.size());
  auto check_point = [&](int index, int line) {
    if (index < 0 || index >= point_count)
      fail(line, "point number " + std::to_string(index) +
                     " does not exist (points are numbered "
                     "0 to " +
                     std::to_string(point_count - 1) + ")");
  };

  for (std::size_t i = 0; i < file.segments.size(); ++i) {
    const FemSegment& s = file.segments[i];
    check_point(s.n0, s.line);
    check_point(s.n1, s.line);
    if (s.n0 == s.n1) fail(s.line, "segment joins point " + std::to_string(s.n0) + " to itself");
    mesh::Segment segment;
    segment.a = s.n0;
    segment.b = s.n1;
    segment.boundary = check_boundary_use(s.marker, s.line);
    if (periodic.segment_condition[i] >= 0) segment.boundary = periodic.segment_condition[i];
    const double max_length = periodic.segment_max_length[i];
    segment.max_length = max_length > 0 ? max_length * file.unit : 0.0;
    problem.geometry.segments.push_back(segment);
  }
  for (std::size_t i = 0; i < file.arcs.size(); ++i) {
    const FemArc& a = file.arcs[i];
    check_point(a.n0, a.line);
    check_point(a.n1, a.line);
    if (a.n0 == a.n1)
      fail(a.line, "arc segment joins point " + std::to_string(a.n0) + " to itself");
    if (!(a.degrees > 0.0 && a.degrees <= 180.0))
      fail(a.line, "arc angle must be in (0, 180] degrees, got " + format_number(a.degrees));
    if (!(periodic.arc_max_degrees[i] >= 0.01))
      fail(a.line,
           "arc maximum segment angle must be at least 0.01 degrees (FEMM's minimum), got " +
               format_number(periodic.arc_max_degrees[i]) +
               (periodic.arc_condition[i] >= 0 ? " (the finer of the two paired arcs)" : ""));
    int boundary = check_boundary_use(a.marker, a.line);
    if (periodic.arc_condition[i] >= 0) boundary = periodic.arc_condition[i];
    std::vector<mesh::Point> pieces;
    append_arc(pieces, problem.geometry.points[a.n0], problem.geometry.points[a.n1], a.degrees,
               periodic.arc_max_degrees[i]);
    int previous = a.n0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      int current = a.n1;
      if (k + 1 < pieces.size()) {
        problem.geometry.points.push_back(pieces[k]);
        current = static_cast<int>(problem.geometry.points.size()) - 1;
      }
      problem.geometry.segments.push_back({previous, current, boundary, 0.0});
      previous = current;
    }
  }

  // Materials, circuits, regions.
  std::map<int, int> material_of_block;  // file block index (0-based) -> problem material
  for (std::size_t i = 0; i < file.circuits.size(); ++i) {
    const FemCircuit& c = file.circuits[i];
    if (c.type != 0 && c.type != 1)
      fail(c.line, "circuit '" + c.name + "': unknown CircuitType " + std::to_string(c.type));
    problem.circuits.push_back({c.name, c.amps});
  }
  std::vector<int> labels_per_circuit(file.circuits.size(), 0);
  std::map<std::string, int> name_count;
  for (const FemLabel& l : file.labels)
    if (l.block > 0 && l.block <= static_cast<int>(file.blocks.size()))
      ++name_count[file.blocks[l.block - 1].name];
  std::map<std::string, int> name_seen;

  for (const FemLabel& h : file.holes) {
    mesh::RegionSeed seed;
    seed.seed = {h.x * file.unit, h.y * file.unit};
    seed.name = "hole";
    seed.hole = true;
    seed.where = source + ":" + std::to_string(h.line);
    problem.geometry.regions.push_back(seed);
    problem.regions.push_back({});
  }
  for (const FemLabel& l : file.labels) {
    mesh::RegionSeed seed;
    seed.seed = {l.x * file.unit, l.y * file.unit};
    seed.where = source + ":" + std::to_string(l.line);
    RegionData data;
    if (l.block < 0 || l.block > static_cast<int>(file.blocks.size()))
      fail(l.line, "block type " + std::to_string(l.block) + " does not exist (the file defines " +
                       std::to_string(file.blocks.size()) + " block properties)");
    if (l.block == 0) {  // <No Mesh>
      seed.name = "no_mesh";
      seed.hole = true;
      problem.geometry.regions.push_back(seed);
      problem.regions.push_back(data);
      continue;
    }
    // FEMM's external region (Kelvin transformation) is a disk standing for the outside of a
    // circle, joined to it by a periodic pair. The planar map is conformal: the field equation
    // and the energy density keep their form, and FEMM's planar solver treats the region as any
    // other. Axisymmetric external regions scale the permeability with position
    // (KelvinExterior), from the header's [extRo], [extRi] and [extZo].
    const FemBlock& external_block = file.blocks[l.block - 1];
    if ((l.external & 1) != 0 && file.axisymmetric) {
      if (!(file.ext_ro > 0.0 && file.ext_ri > 0.0))
        fail(file.ext_line > 0 ? file.ext_line : l.line,
             "block label in an axisymmetric external region needs [extRo] > 0 and [extRi] > 0 "
             "(the radii of the external disk and of the domain's boundary); got extRo = " +
                 format_number(file.ext_ro) + ", extRi = " + format_number(file.ext_ri));
      if (!external_block.bh.empty() || external_block.h_c != 0.0 || external_block.j != 0.0 ||
          l.circuit > 0)
        fail(l.line, "block '" + external_block.name +
                         "' in an axisymmetric external region must be a linear material "
                         "without magnet, current or circuit (the region stands for the space "
                         "outside the model)");
      problem.kelvin =
          KelvinExterior{file.ext_ri * file.unit, file.ext_ro * file.unit, file.ext_zo * file.unit};
      data.kelvin_exterior = true;
    }
    const FemBlock& block = file.blocks[l.block - 1];
    auto found = material_of_block.find(l.block - 1);
    if (found == material_of_block.end()) {
      found =
          material_of_block.emplace(l.block - 1, static_cast<int>(problem.materials.size())).first;
      problem.materials.push_back(femm_material(block, source, reader, problem.warnings));
    }
    data.current_density = block.j * 1e6;  // MA/m^2 -> A/m^2
    if (block.h_c != 0.0) {
      data.magnetisation = {l.magdir, l.magdir_expression, file.unit};
      const MagnetDirectionField check(data.magnetisation,
                                       source + ":" + std::to_string(l.line));  // parses
    } else if (!l.magdir_expression.empty()) {
      data.magnetisation.expression.clear();  // FEMM ignores a direction without H_c
    }
    data.material = found->second;
    if (l.circuit < 0 || l.circuit > static_cast<int>(file.circuits.size()))
      fail(l.line, "circuit number " + std::to_string(l.circuit) + " does not exist");
    if (l.circuit > 0) {
      const FemCircuit& c = file.circuits[l.circuit - 1];
      if (l.turns == 0) fail(l.line, "block label in circuit '" + c.name + "' has 0 turns");
      data.circuit = l.circuit - 1;
      data.turns = l.turns;
      if (c.type == 0) {
        if (++labels_per_circuit[l.circuit - 1] > 1)
          fail(l.line, "parallel circuit '" + c.name +
                           "' (CircuitType 0) feeds more than one "
                           "block: the current split needs a voltage-driven solve; use a series "
                           "circuit (CircuitType 1) with turns per block");
        if (l.turns != 1)
          fail(l.line, "parallel circuit '" + c.name + "' (CircuitType 0) with " +
                           std::to_string(l.turns) +
                           " turns: a parallel circuit is a solid "
                           "conductor; use a series circuit for a winding");
      }
    }
    // FEMM's default label (flag bit 2) gives its block to every area without a label; it may
    // lie outside the geometry.
    if ((l.external & 2) != 0)
      problem.geometry.default_region = static_cast<int>(problem.geometry.regions.size());
    seed.name = block.name;
    if (name_count[block.name] > 1) seed.name += "_" + std::to_string(++name_seen[block.name]);
    seed.mesh_size = l.size > 0 ? femm_mesh_size_to_edge(l.size * file.unit) : 0.0;
    problem.geometry.regions.push_back(seed);
    problem.regions.push_back(data);
  }
  if (file.labels.empty()) fail(reader.line_number(), "the model has no block labels");
  drop_labels_in_hole_areas(problem);
  return problem;
}

Problem read_femm_file(const std::filesystem::path& path) {
  return parse_femm(read_input_file(path.string()), path.string());
}

}  // namespace rheomag::cases
