#pragma once
// Distributing a sweep over MPI ranks (when rheomag is built with OpenMPI): rank 0 prepares the
// output, hands design ids to the other ranks one at a time as they ask (dynamic balancing),
// and appends the rows they send back to one CSV; ranks 1..K-1 evaluate.

#include "sweep/run.hpp"

namespace rheomag::sweep {

/// True when this rheomag was built with MPI support (RHEOMAG_HAVE_MPI).
bool mpi_built();

/// True when the process was started by mpirun/srun with more than one rank (from the launcher's
/// environment: OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_SIZE... > 1).
bool launched_with_mpi();

/// Runs the sweep over all MPI ranks (initialises and finalises MPI). Rank 0 returns the summary
/// with `is_root` true; other ranks return an empty summary. An InputError found by rank 0
/// (output checks) stops every rank and is rethrown on rank 0 only. Each worker rank evaluates
/// one design at a time (run one rank per core). Throws InputError when built without MPI.
SweepSummary run_sweep_mpi(const SweepSpec& spec, const SweepRunOptions& options, bool& is_root);

}  // namespace rheomag::sweep
