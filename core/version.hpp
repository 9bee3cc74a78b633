#pragma once
// The version of this build of rheomag: the project version and the git revision it was built
// from, printed by `rheomag --version` and carried by every JSON document rheomag writes.

#include <nlohmann/json.hpp>
#include <string>

namespace rheomag {

/// The project version, e.g. "0.1.0" (CMakeLists.txt's project()).
std::string project_version();

/// The git revision the library was built from (`git describe --always --dirty`), e.g.
/// "8559daf1c2e4-dirty"; "unknown" when built outside a git checkout.
std::string git_revision();

/// The version as JSON documents carry it: "<project version>+<git revision>" (SemVer build
/// metadata), e.g. "0.1.0+8559daf1c2e4".
std::string version_text();

/// Adds "version": version_text() to a JSON object that has no "version" yet; other values
/// (arrays, numbers) are left as they are.
void stamp_version(nlohmann::json& document);

}  // namespace rheomag
