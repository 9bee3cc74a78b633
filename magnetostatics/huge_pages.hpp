#pragma once
// Transparent huge pages for CHOLMOD's large blocks (the Cholesky factor, its workspace).

namespace rheomag::magnetostatics {

/// Makes CHOLMOD's (SuiteSparse's) malloc and calloc mark every block of 4 MiB or more for
/// transparent huge pages (madvise MADV_HUGEPAGE on its whole 2 MiB pages, before the first
/// touch); the blocks still come from the C library and are freed by it. On kernels whose
/// huge-page mode is "madvise" (Debian's default) the 450 MB factor of a 1e6-unknown solve took
/// 110 000 page faults at its first factorisation and missed the TLB in every substitution
/// (docs/performance.md, round 4). Idempotent; the first call installs it, process-wide, unless
/// the environment sets RHEOMAG_HUGE_PAGES=0. Every MagnetostaticSolver calls it.
void use_huge_pages_for_cholmod();

}  // namespace rheomag::magnetostatics
