#include "magnetostatics/serial_openmp.hpp"

#include <omp.h>

#include "magnetostatics/inline_openmp.hpp"

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
  inline_ = inline_openmp_enabled();
  if (inline_) ++inline_openmp_depth();
}

SerialOpenMp::~SerialOpenMp() {
  if (inline_) --inline_openmp_depth();
  if (saved_ > 0) omp_set_max_active_levels(saved_);
}

}  // namespace rheomag::magnetostatics
