#include "magnetostatics/huge_pages.hpp"

#include <SuiteSparse_config.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <string>

namespace rheomag::magnetostatics {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLargeBlock = std::size_t{4} << 20;

/// Asks for huge pages on the whole 2 MiB pages inside [p, p + bytes); returns p.
void* advise_huge_pages(void* p, std::size_t bytes) {
  if (p == nullptr || bytes < kLargeBlock) return p;
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kHugePage - 1) & ~(kHugePage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  return p;  // a refused advice (no THP in this kernel) leaves ordinary pages
}

void* huge_page_malloc(std::size_t bytes) {
  return advise_huge_pages(std::malloc(bytes), bytes);
}

void* huge_page_calloc(std::size_t count, std::size_t size) {
  return advise_huge_pages(std::calloc(count, size), count * size);
}

}  // namespace

void use_huge_pages_for_cholmod() {
  // A function-local static: one thread-safe installation, before this process's first solver
  // uses CHOLMOD. realloc and free stay the C library's (the blocks are ordinary malloc blocks).
  static const bool installed = [] {
    const char* setting = std::getenv("RHEOMAG_HUGE_PAGES");
    if (setting != nullptr && std::string(setting) == "0") return false;
    SuiteSparse_config.malloc_func = huge_page_malloc;
    SuiteSparse_config.calloc_func = huge_page_calloc;
    return true;
  }();
  (void)installed;
}

}  // namespace rheomag::magnetostatics
