// A process-wide set, created on first use (safe from any static initialiser).

#include "case/case_sections.hpp"

#include <mutex>
#include <set>

namespace rheomag::cases {
namespace {

struct Registry {
  std::mutex mutex;
  std::set<std::string, std::less<>> names;
};

Registry& registry() {
  static Registry instance;
  return instance;
}

}  // namespace

bool register_case_section(std::string_view name) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  r.names.emplace(name);
  return true;
}

std::vector<std::string> registered_case_sections() {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  return {r.names.begin(), r.names.end()};
}

}  // namespace rheomag::cases
