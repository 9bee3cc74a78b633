#pragma once
// A CHOLMOD factorisation that ran out of memory is a resource failure, not a solver failure:
// it reaches the CLI as std::bad_alloc, which reports "out of memory" with exit 2 (the input is
// too large for this machine), instead of "did not converge" (exit 3).

#include <Eigen/CholmodSupport>
#include <new>

namespace rheomag::magnetostatics {

/// Throws std::bad_alloc when the last call of `factor` (an Eigen CHOLMOD wrapper) failed for
/// want of memory; does nothing otherwise (the caller checks info() for other failures).
template <class Factor>
void throw_if_out_of_memory(Factor& factor) {
  if (factor.info() != Eigen::Success && factor.cholmod().status == CHOLMOD_OUT_OF_MEMORY)
    throw std::bad_alloc();
}

}  // namespace rheomag::magnetostatics
