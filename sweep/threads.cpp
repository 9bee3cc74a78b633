#include "sweep/threads.hpp"

#include <dlfcn.h>

#include <cstdlib>

namespace rheomag::sweep {

void sweep_serial_openmp() {
  if (std::getenv("OMP_THREAD_LIMIT") != nullptr) return;
  using SetLevels = void (*)(int);
  if (auto set = reinterpret_cast<SetLevels>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")))
    set(0);
}

}  // namespace rheomag::sweep
