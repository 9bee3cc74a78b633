#include "magnetostatics/inline_openmp.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <string>

// Why: Debian's CHOLMOD opens an OpenMP region (a team of its compiled-in size) around several
// loops of every large supernode. SerialOpenMp already makes each region a team of one thread,
// but libgomp still builds that team and ends it with a futex wake-up system call: 1.6 million of
// them in one nested 1e6-unknown solve (docs/performance.md). A region that the OpenMP rules
// serialise may as well run as a plain call: its loops then run as orphaned work-sharing
// constructs on this thread (omp_get_num_threads() = 1, omp_get_thread_num() = 0, barriers return
// at once), which is what the serialised team would have done.
//
// GOMP_parallel is libgomp's entry point for `#pragma omp parallel` (GCC 4.9 on). This library
// comes before libgomp in the executable's symbol lookup order, so CHOLMOD's calls land here;
// outside a SerialOpenMp scope every call goes on to libgomp's own. Where libgomp comes first (a
// program that loads it earlier), this definition is simply not used.

namespace rheomag::magnetostatics {

int& inline_openmp_depth() {
  thread_local int depth = 0;
  return depth;
}

namespace {

/// This thread's count of regions run inline.
long& inline_region_count() {
  thread_local long count = 0;
  return count;
}

}  // namespace

long inline_openmp_regions() {
  return inline_region_count();
}

bool inline_openmp_enabled() {
  static const bool enabled = [] {
    const char* setting = std::getenv("RHEOMAG_INLINE_OPENMP");
    return setting == nullptr || std::string(setting) != "0";
  }();
  return enabled;
}

}  // namespace rheomag::magnetostatics

namespace {

using GompParallel = void (*)(void (*)(void*), void*, unsigned, unsigned);

/// libgomp's GOMP_parallel, the next definition after this library's.
GompParallel next_gomp_parallel() {
  static const auto next = reinterpret_cast<GompParallel>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  if (next == nullptr) {
    std::fputs(
        "rheomag: no OpenMP runtime (libgomp's GOMP_parallel) after librheomag_magnetostatics"
        " in the symbol lookup order\n",
        stderr);
    std::abort();
  }
  return next;
}

}  // namespace

/// `#pragma omp parallel`: inline inside a SerialOpenMp scope, else libgomp's region.
extern "C" void GOMP_parallel(void (*body)(void*), void* data, unsigned num_threads,
                              unsigned flags) {
  if (rheomag::magnetostatics::inline_openmp_depth() > 0) {
    ++rheomag::magnetostatics::inline_region_count();
    body(data);
    return;
  }
  next_gomp_parallel()(body, data, num_threads, flags);
}
