#pragma once
// A sweep file (format: docs/sweep-format.md): a base case, the axes over its keys, how
// designs are drawn from them (full factorial or Latin hypercube) and what is written.

#include <toml++/toml.h>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_key.hpp"

namespace rheomag::sweep {

/// How designs are drawn from the axes.
enum class SweepMethod {
  factorial,        ///< every combination of the axis levels (last axis varies fastest)
  latin_hypercube,  ///< `samples` designs, each axis stratified into `samples` intervals
};

/// One swept key: its levels (a list or a range) or, for a Latin hypercube, its bounds.
struct SweepAxis {
  cases::CaseKey key;
  std::vector<cases::KeyValue> levels;  ///< factorial levels; for a Latin hypercube: categories
  double lower = 0.0;                   ///< Latin hypercube bounds (when `levels` is empty)
  double upper = 0.0;
};

/// A parsed, checked sweep file.
struct SweepSpec {
  std::filesystem::path source;     ///< the sweep file
  std::filesystem::path base_case;  ///< resolved against the sweep file's directory
  cases::Case base;                 ///< the base case as read (base.table: its TOML table)
  SweepMethod method = SweepMethod::factorial;
  long long samples = 0;   ///< Latin hypercube sample count
  std::uint64_t seed = 1;  ///< Latin hypercube seed (std::mt19937_64)
  std::vector<SweepAxis> axes;
  std::string csv = "results.csv";  ///< results file, relative to the output directory
  /// "sweep.toml:12: output.csv" (or the file and the default) for messages about the results path.
  std::string csv_where;
  bool write_vtu = false;  ///< one .vtu per design in <out>/<csv stem>_vtu/
};

/// Most designs a sweep may have.
inline constexpr long long kMaxDesigns = 10'000'000;

/// Parses sweep-file text; `source` is its path (relative base paths resolve against its
/// directory). Reads and checks the base case (it must parse as a case file) and resolves
/// every axis key in it. Throws InputError naming the file and key.
SweepSpec parse_sweep(std::string_view text, const std::filesystem::path& source);

/// Reads a sweep file.
SweepSpec read_sweep(const std::filesystem::path& path);

/// Number of designs of the sweep.
long long design_count(const SweepSpec& spec);

}  // namespace rheomag::sweep
