#include "core/memory_limit.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/error.hpp"

namespace rheomag {

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

double available_memory_bytes() {
  double bytes = physical_memory_bytes();
  const auto lower = [&bytes](double limit) {
    if (limit > 0.0 && std::isfinite(limit) && (bytes <= 0.0 || limit < bytes)) bytes = limit;
  };
  // ulimit -v / -d: the process cannot map more, whatever the machine has.
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    struct rlimit limit {};
    if (::getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      lower(static_cast<double>(limit.rlim_cur));
  }
  // A container's memory (cgroup v2, then v1): "max" or a huge number means no limit.
  for (const char* file :
       {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(file);
    double value = 0.0;
    if (in >> value) lower(value);
  }
  return bytes;
}

double default_memory_limit() {
  const double available = available_memory_bytes();
  return available > 0 ? 0.75 * available : 4.0 * 1024 * 1024 * 1024;
}

double parse_memory_size(std::string_view text, std::string_view option) {
  const std::string expected =
      std::string(option) +
      ": expected a memory size in bytes with an optional K, M, G or T suffix (e.g. 8G, 512M), "
      "got \"" +
      std::string(text) + "\"";
  std::string number(text);
  double scale = 1.0;
  if (!number.empty()) {
    const char suffix = static_cast<char>(std::toupper(static_cast<unsigned char>(number.back())));
    const std::string suffixes = "KMGT";
    const std::size_t power = suffixes.find(suffix);
    if (power != std::string::npos) {
      scale = std::pow(1024.0, static_cast<double>(power + 1));
      number.pop_back();
    }
  }
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(number, &used);
  } catch (const std::exception&) {
    throw InputError(expected);
  }
  if (used != number.size() || !std::isfinite(value)) throw InputError(expected);
  const double bytes = value * scale;
  // 1 MiB .. 1 PiB: below, no mesh fits; above, no machine has it (and 1e300 is a typo).
  if (!(bytes >= 1024.0 * 1024.0) || !(bytes <= std::pow(1024.0, 5)))
    throw InputError(std::string(option) + ": expected a memory size from 1M to 1024T, got \"" +
                     std::string(text) + "\"");
  return bytes;
}

std::string memory_size_text(double bytes) {
  char text[32];
  if (bytes >= 1e9)
    std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  else
    std::snprintf(text, sizeof text, "%.3g MB", bytes / 1e6);
  return text;
}

}  // namespace rheomag
