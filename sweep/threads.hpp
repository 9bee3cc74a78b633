#pragma once
// Threads inside the numerical libraries during a sweep (which parallelises over designs).

namespace rheomag::sweep {

/// Makes every OpenMP parallel region started by the calling thread run on that thread (its
/// OpenMP max-active-levels 0, a per-thread setting: call it in each worker) unless the user
/// set OMP_THREAD_LIMIT. Debian's CHOLMOD 3 opens a team
/// of 4 threads (a compiled-in num_threads) for each supernode of every factorisation; in a
/// sweep those teams only add wake-ups and barrier waits (measured in docs/performance.md,
/// sweep section). The numbers are unchanged: the regions split independent loops. The OpenMP
/// runtime is looked up at run time (it is loaded with CHOLMOD), so nothing links OpenMP.
void sweep_serial_openmp();

}  // namespace rheomag::sweep
