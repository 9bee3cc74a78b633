#include "magnetostatics/serial_openmp.hpp"

#include <omp.h>

#include <cstdlib>

namespace rheomag::magnetostatics {
namespace {

bool user_limits_threads() {
  static const bool set = std::getenv("OMP_THREAD_LIMIT") != nullptr;
  return set;
}

}  // namespace

SerialOpenMp::SerialOpenMp() {
  if (user_limits_threads()) return;
  saved_ = omp_get_max_active_levels();
  if (saved_ != 0) omp_set_max_active_levels(0);
}

SerialOpenMp::~SerialOpenMp() {
  if (saved_ > 0) omp_set_max_active_levels(saved_);
}

}  // namespace rheomag::magnetostatics
