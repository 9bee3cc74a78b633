#pragma once
// Runs CHOLMOD's OpenMP regions on the calling thread.

namespace rheomag::magnetostatics {

/// While alive, OpenMP parallel regions started by the calling thread run on that thread alone
/// (OpenMP max-active-levels 0, a per-thread setting in libgomp); the previous setting is
/// restored on destruction. Debian's CHOLMOD opens a region with a compiled-in team of 4 threads
/// for each supernode: on a 2-core machine its barrier waits doubled the time of a numeric
/// factorisation (docs/performance.md). No effect when the user set OMP_THREAD_LIMIT.
class SerialOpenMp {
 public:
  SerialOpenMp();
  ~SerialOpenMp();
  SerialOpenMp(const SerialOpenMp&) = delete;
  SerialOpenMp& operator=(const SerialOpenMp&) = delete;

 private:
  int saved_ = -1;  // previous max-active-levels, -1 when unchanged
};

}  // namespace rheomag::magnetostatics
