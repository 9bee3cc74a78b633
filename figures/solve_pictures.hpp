#pragma once
// The pictures of one magnetostatic solve, written as files: what `rheomag plot` and
// `solve --plot` write.

#include <filesystem>
#include <string>
#include <vector>

#include "figures/field_map.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::figures {

/// A solved case and what was computed from it, for its pictures.
struct SolvedCase {
  std::string name;
  const magnetostatics::MagnetostaticSolver& solver;
  const magnetostatics::Solution& solution;
  const magnetostatics::Results& results;
  std::vector<magnetostatics::SweepPoint> sweep;  ///< lambda(I) of the first circuit; may be empty
};

/// Writes into folder `dir` (created if absent) field_map, one gap_NAME per fluid gap and, with
/// a sweep, lambda_L, each as .svg and .png (the field map at the options' size, the others at
/// 900 x 560 / 900 x 800). Returns the written files in that order.
std::vector<std::filesystem::path> write_solve_pictures(const std::filesystem::path& dir,
                                                        const SolvedCase& solved,
                                                        const FieldMapOptions& options);

/// Writes the field map alone to `path`, as PNG or SVG by its extension (`what` names the
/// option in messages).
void write_field_map(const std::filesystem::path& path, const std::string& what,
                     const SolvedCase& solved, const FieldMapOptions& options);

/// `name` with every character other than a letter, digit, '-' or '_' replaced by '_' (a file
/// name part).
std::string file_name_part(const std::string& name);

}  // namespace rheomag::figures
