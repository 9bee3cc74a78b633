#pragma once
// The layer order of docs/architecture.md as data, and a check of a source tree against it: every
// `#include "FOLDER/..."` and every `rheomag_FOLDER` a folder's CMakeLists.txt links must name
// a layer the including folder may depend on (itself, or below it through the table).

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace rheomag::architecture {

/// Layer name -> the layers it depends on directly, as the table writes them.
using LayerTable = std::map<std::string, std::set<std::string>>;

/// Reads the table whose header row starts with `| layer | depends on |` from the Markdown file
/// `doc`: the first cell names the layer (in backticks), the second its dependencies; words that
/// name no layer (external libraries, "nothing of rheomag") are ignored, "all" means every other
/// layer. Throws std::runtime_error naming the file and line of a malformed table or a circle.
LayerTable read_layer_table(const std::filesystem::path& doc);

/// Every layer `layer` may include: itself and all it depends on, directly or not.
std::set<std::string> allowed_layers(const LayerTable& table, const std::string& layer);

/// One reference that runs against the table.
struct Violation {
  std::string file;  ///< path relative to the tree's root
  int line = 0;      ///< 1-based
  std::string text;  ///< what is wrong, e.g. "lumped includes diagnose/diagnose_run.hpp"
};

/// Checks every .cpp/.hpp/.h under each layer's folder of `root` (sub-folders included) and each
/// layer's CMakeLists.txt, and every top-level folder holding a CMakeLists.txt that is neither a
/// layer nor one of `unlayered` (tests, benchmarks): such a folder is reported as missing from
/// the table.
std::vector<Violation> check_tree(const std::filesystem::path& root, const LayerTable& table,
                                  const std::set<std::string>& unlayered);

}  // namespace rheomag::architecture
