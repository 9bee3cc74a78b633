#pragma once
// The typed case: what a TOML case file (or a FEMM .fem model) says, read once into typed values
// (lengths in metres), and the magnetostatic Problem built from them. Format:
// docs/case-format.md. Design edits change the typed values and rebuild (case/case_key.hpp).

#include <toml++/toml.h>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "case/material_library.hpp"
#include "case/problem.hpp"
#include "case/region_outline.hpp"
#include "case/templates.hpp"

namespace rheomag::cases {

/// A coil wound from its wire: [geometry] wire + fill_factor give the turns of every coil region
/// of a template from its winding window.
struct Winding {
  std::string wire;            ///< as written or set ("AWG 24", "0.5 mm"); "" = not given
  double wire_diameter = 0.0;  ///< bare copper diameter [m]; 0 = not given
  double fill_factor = 0.0;    ///< copper area / window area; 0 = turns given instead
  std::string wire_where;      ///< "file:line: geometry.wire" for messages
  std::string fill_where;      ///< "file:line: geometry.fill_factor" for messages
};

/// The typed values a case's geometry, materials and fluid are built from.
struct CaseInput {
  double length_unit = 1.0;                        ///< metres per length unit of the file
  std::shared_ptr<const MaterialLibrary> library;  ///< the library the case was read against
  MaterialLibrary materials;                       ///< `library` plus inline [[material]] tables
  std::string fluid;                               ///< [case] fluid as written ("" = from gaps)
  std::string fluid_where;                         ///< "file:line: case.fluid"
  const ValveTemplate* valve = nullptr;            ///< the parametric template, if any
  TemplateValues template_values;                  ///< its parameters, defaults filled in
  Winding winding;                                 ///< template coils wound from their wire
  std::vector<RegionOutline> regions;              ///< general geometry: [[region]] outlines
  std::string background_material = "Air";         ///< material between the regions
  std::string background_where;                    ///< where it was given
};

/// A case: its typed input, the problem to solve built from it, and what later layers need.
struct Case {
  std::string name;               ///< [case] name (default: the file's stem)
  std::string description;        ///< [case] description
  std::filesystem::path source;   ///< the file read
  std::string fluid;              ///< MR fluid material of the gaps ("" if no gap)
  Problem problem;                ///< SI units; the background region is named "air"
  toml::table table;              ///< the document (a .fem: its sidecar, else empty)
  std::string geometry_template;  ///< template name, "" for general regions or a .fem
  CaseInput input;                ///< the typed values `problem` was built from
  bool femm = false;  ///< read from a FEMM .fem: `problem` is the model, `input` holds no geometry
};

/// Parses a case document (`source` names it in messages); InputError on any bad input. The
/// table is taken by value: a document parsed from text keeps its line numbers for messages
/// only while it is moved, not copied (toml++ copies drop them).
Case parse_case(toml::table table, const std::string& source,
                const MaterialLibrary& library = MaterialLibrary::standard());

/// Parses case text (`source` names it in messages); InputError on any bad input.
Case parse_case(std::string_view text, const std::string& source,
                const MaterialLibrary& library = MaterialLibrary::standard());

/// Rebuilds `c.problem` (geometry, regions, materials) and `c.fluid` from `c.input` and the
/// problem's circuits and solver options; InputError when the values are inconsistent.
void build_case(Case& c);

/// The case as TOML case-file text (its document, every edit applied).
std::string case_file_text(const Case& c);

/// Reads a TOML case file.
Case read_case_file(const std::filesystem::path& path,
                    const MaterialLibrary& library = MaterialLibrary::standard());

/// Reads a case from a .toml case file or a FEMM .fem file (by extension).
Case load_case(const std::filesystem::path& path,
               const MaterialLibrary& library = MaterialLibrary::standard());

}  // namespace rheomag::cases
