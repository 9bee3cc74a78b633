#pragma once
// A rig spec made ready for the lumped simulation: its valve's FE-chain map tabulated over the
// range a drive recording covers.

#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"

namespace rheomag::coupling {

/// The spec with its valve's FE-chain map tabulated once over the drive's current and flow range
/// (unchanged when the valve is a table, the map is already there, or the rig is a coil bench).
/// Throws InputError if the case cannot be read, ConvergenceError if it does not solve.
lumped::RigSpec with_chain_map(const lumped::RigSpec& spec, const lumped::Recording& drive);

}  // namespace rheomag::coupling
