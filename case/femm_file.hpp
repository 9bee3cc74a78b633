#pragma once
// Internal to rheomag_case: a FEMM 4.2 .fem text read into its raw sections (properties,
// geometry, labels) with file:line messages, before any conversion to a Problem.

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/pslg.hpp"

namespace rheomag::cases::femm {

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

/// The raw .fem data of one block label (or a [NumHoles] point).
struct FemLabel {
  double x = 0, y = 0, size = -1, magdir = 0;
  std::string magdir_expression;  // FEMM's direction expression (quoted last column)
  int block = 0, circuit = 0, group = 0, turns = 1, external = 0;
  int line = 0;
};

/// The raw .fem data of one arc segment.
struct FemArc {
  int n0 = 0, n1 = 0, marker = 0, line = 0;
  double degrees = 0, max_side_degrees = 0;
};

/// The raw .fem data of one straight segment.
struct FemSegment {
  int n0 = 0, n1 = 0, marker = 0, line = 0;
  double max_length = -1;
};

/// Line-by-line reader with file:line error messages.
class FemReader {
 public:
  /// Splits `text` into lines (any of \n, \r\n, \r; a byte-order mark skipped); `source` names
  /// the file in messages. The text must outlive the reader.
  FemReader(std::string_view text, std::string source);

  /// "file:line", the prefix of every message about that line.
  std::string where(int line) const;

  /// Throws InputError "file:line: message".
  [[noreturn]] void fail(int line, const std::string& message) const;

  /// The next non-empty line, trimmed; false at the end of the file.
  bool next(std::string_view& line);

  /// The next non-empty line, which must exist (`what` says what was expected).
  std::string_view require(const std::string& what);

  /// The number of the line last returned (1-based; 0 before the first).
  int line_number() const { return static_cast<int>(index_); }
  /// The line last returned by next() or require(), trimmed.
  std::string_view current_line() const;
  /// The file name used in messages.
  const std::string& source() const { return source_; }

  /// A finite number, or InputError naming `what` and the token.
  double number(std::string_view token, const std::string& what) const;

  /// A whole number within +-1e9, or InputError naming `what` and the token.
  int integer(std::string_view token, const std::string& what) const;

  /// Whitespace-separated numeric columns of a data line (quoted strings end the columns).
  std::vector<double> columns(std::string_view line, std::size_t minimum, const std::string& what);

 private:
  std::vector<std::string_view> lines_;
  std::size_t index_ = 0;
  std::string source_;
};

/// Everything read from the file before conversion.
struct FemFile {
  double unit = 0.0254;  // FEMM's default length unit is inches
  double depth = 1.0;
  int depth_line = 0;
  bool axisymmetric = false;
  bool polar = false;  // [Coordinates] = polar: a boundary's A_1, A_2 multiply r and theta
  int coordinates_line = 0;
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

/// Reads every section of a .fem text (magnetostatics only; InputError with file:line for
/// anything malformed, unsupported or inconsistent with its declared counts).
FemFile read_fem_text(std::string_view text, FemReader& reader);

}  // namespace rheomag::cases::femm
