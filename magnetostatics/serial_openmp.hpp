#pragma once
// Runs CHOLMOD's OpenMP regions on the calling thread.

namespace rheomag::magnetostatics {

/// While alive, OpenMP parallel regions started by the calling thread run on that thread alone
/// (OpenMP max-active-levels 0, a per-thread setting in libgomp); the previous setting is
/// restored on destruction. Debian's CHOLMOD opens a region with a compiled-in team of 4 threads
/// for each supernode: on a 2-core machine its barrier waits doubled the time of a numeric
/// factorisation (docs/performance.md). The regions also run inline, without libgomp's team of
/// one and its system call (inline_openmp.hpp; RHEOMAG_INLINE_OPENMP=0 turns that off). No effect
/// when the user set OMP_THREAD_LIMIT.
class SerialOpenMp {
 public:
  SerialOpenMp();
  ~SerialOpenMp();
  SerialOpenMp(const SerialOpenMp&) = delete;
  SerialOpenMp& operator=(const SerialOpenMp&) = delete;

 private:
  int saved_ = -1;       // previous max-active-levels, -1 when unchanged
  bool inline_ = false;  // this scope counts in inline_openmp_depth()
};

}  // namespace rheomag::magnetostatics
