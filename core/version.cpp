// The build's version: the project version and git revision from the header that
// cmake/rheomag_revision.cmake writes at build time (absent in builds that do not run it).

#include "core/version.hpp"

#if __has_include("rheomag_revision.h")
#include "rheomag_revision.h"
#endif
#ifndef RHEOMAG_VERSION
#define RHEOMAG_VERSION "unknown"
#endif
#ifndef RHEOMAG_GIT_REVISION
#define RHEOMAG_GIT_REVISION "unknown"
#endif

namespace rheomag {

std::string project_version() {
  return RHEOMAG_VERSION;
}

std::string git_revision() {
  return RHEOMAG_GIT_REVISION;
}

std::string version_text() {
  return project_version() + "+" + git_revision();
}

void stamp_version(nlohmann::json& document) {
  if (document.is_object() && !document.contains("version")) document["version"] = version_text();
}

}  // namespace rheomag
