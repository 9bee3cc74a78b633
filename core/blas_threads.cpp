// OpenBLAS single-threaded by default (see blas_threads.hpp).

#include "core/blas_threads.hpp"

#include <dlfcn.h>

#include <cstdlib>

namespace rheomag {

void prefer_single_threaded_blas() {
  if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return;
  using SetThreads = void (*)(int);
  if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
    set(1);
}

}  // namespace rheomag
