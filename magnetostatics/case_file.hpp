#pragma once
// The TOML case file: geometry (template or general regions), materials, circuits and solver
// options -> a magnetostatic Problem plus the case's metadata. Format: docs/case-format.md.

#include <toml++/toml.h>
#include <filesystem>
#include <string>
#include <string_view>

#include "magnetostatics/material_library.hpp"
#include "magnetostatics/problem.hpp"

namespace rheomag::magnetostatics {

/// A case read from a file: the problem to solve and what later links need about it.
struct Case {
  std::string name;               ///< [case] name (default: the file's stem)
  std::string description;        ///< [case] description
  std::filesystem::path source;   ///< the file read
  std::string fluid;              ///< MR fluid material of the gaps ("" if no gap)
  Problem problem;                ///< SI units; the background region is named "air"
  toml::table table;              ///< the whole parsed file (empty for a .fem), for later links
  std::string geometry_template;  ///< template name, "" for general regions or a .fem
};

/// Top-level tables of a case file that belong to later links (fluid, valve, ...): passed
/// through unchecked here, checked by their own readers.
const std::vector<std::string_view>& case_sections_of_later_links();

/// Parses case text (`source` names it in messages); InputError on any bad input.
Case parse_case(std::string_view text, const std::string& source,
                const MaterialLibrary& library = MaterialLibrary::standard());

/// Reads a TOML case file.
Case read_case_file(const std::filesystem::path& path,
                    const MaterialLibrary& library = MaterialLibrary::standard());

/// Reads a case from a .toml case file or a FEMM .fem file (by extension).
Case load_case(const std::filesystem::path& path,
               const MaterialLibrary& library = MaterialLibrary::standard());

}  // namespace rheomag::magnetostatics
