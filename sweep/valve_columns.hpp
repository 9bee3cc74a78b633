#pragma once
// The valve chain's columns in a sweep: pressure drop at each design's current and flow, and the
// coil's resistance, time constant L/R and power (valve::SolvedValve, docs/fluid.md).

#include <vector>

#include "sweep/row.hpp"

namespace rheomag::sweep {

/// Columns from the valve chain for a base case with a [valve] table:
/// - with [valve] flow: dp_total_Pa, dp_yield_Pa, dp_viscous_Pa (field-integrated along every
///   gap) and dp_total_average_b_Pa (the one-average-B shortcut), at the design's first-circuit
///   current and [valve] flow;
/// - with [valve] wire: coil_resistance_Ohm, coil_time_constant_s (secant L / R) and
///   coil_power_W (I^2 R) at that current.
/// Empty (no columns) when the base case has neither. Evaluated from the design's own field
/// solve (valve::SolvedValve): no extra mesh or FE solve per design.
std::vector<ColumnGroup> valve_columns(const SweepSpec& spec);

}  // namespace rheomag::sweep
