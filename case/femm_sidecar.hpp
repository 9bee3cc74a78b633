#pragma once
// The gaps and flow path of a FEMM model, given in a small TOML file beside it (`valve.fem` +
// `valve.toml` with a [fem] table; docs/femm.md): which block labels are fluid gaps, of which
// kind, in flow order, and which MR fluid; its other tables ([valve], [damper], ...) are the
// later layers' sections, as in a case file. `rheomag export` writes it.

#include <filesystem>
#include <string>

#include "case/case_file.hpp"

namespace rheomag::cases {

/// The sidecar path of a .fem model: the same name with the extension .toml.
std::filesystem::path femm_sidecar_path(const std::filesystem::path& fem);

/// The file a case's document (`Case::table`) was read from, for messages: the sidecar of a
/// .fem model, else the case file itself.
std::string case_document_source(const Case& c);

/// True when `path` is a TOML file with a top-level [fem] table (a sidecar, not a case).
bool is_femm_sidecar(const std::filesystem::path& path);

/// Applies the sidecar `path` to a case read from a .fem: marks the named block labels' regions
/// as gaps (annular or radial), renames them, moves them first in the listed (flow) order, sets
/// the MR fluid and keeps the document for the later layers. InputError naming the label for a
/// label that is no block label of the model, a block that is not an MR fluid of the material
/// library, or fluids that differ.
void apply_femm_sidecar(Case& c, const std::filesystem::path& path,
                        const MaterialLibrary& library = MaterialLibrary::standard());

/// The sidecar text for the .fem that write_femm makes of `closed` (the case `c` closed by
/// magnetostatics::close_domain): its gaps by their label points [m] in region order, the fluid,
/// and the case's later-layer sections. Empty when the case has no gap.
std::string femm_sidecar_text(const Case& c, const Problem& closed);

}  // namespace rheomag::cases
