#pragma once
// The FE side of a rig's static valve map: a case's valve chain evaluated on a current x flow grid
// into the lumped layer's ChainMapTable (lumped/valve_chain_map.hpp).

#include <memory>
#include <string>

#include "lumped/valve_chain_map.hpp"

namespace rheomag::coupling {

/// Evaluates `case_file` with valve::ValveChain (a damper piston case, one with a [damper] table:
/// valve::DamperChain, its force minus the gas force over the piston area) at `currents` x
/// `flows` once and returns the table
/// (currents from 0 to max_current, flows log-spaced from 1e-3 to 1.5 times max_flow). Throws
/// InputError if the case cannot be read or has no valve.
std::shared_ptr<const lumped::ChainMapTable> tabulate_valve_chain(const std::string& case_file,
                                                                  double max_current,
                                                                  double max_flow,
                                                                  int current_points = 6,
                                                                  int flow_points = 12);

}  // namespace rheomag::coupling
