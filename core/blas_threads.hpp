#pragma once
// The BLAS behind CHOLMOD, single-threaded unless the user asked otherwise: what the CLI and the
// Python module both do when they start.

namespace rheomag {

/// Makes OpenBLAS (when it is the system BLAS behind CHOLMOD) single-threaded unless the user
/// set OPENBLAS_NUM_THREADS: at rheomag's problem sizes a second BLAS thread gains little, and
/// with parallel sweep workers or a busy machine its spinning threads cost 20x (see
/// docs/performance.md, "Threads"). It also makes the sums' order, and so the last digits of
/// every result, the same in every program. Looked up at run time: other BLAS builds lack the
/// symbol.
void prefer_single_threaded_blas();

}  // namespace rheomag
