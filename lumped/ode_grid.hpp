#pragma once
// Fixed-step stiff integration on the sample grid of a recording: every sample interval is split
// into the same number of steps of a stiffly accurate, L-stable SDIRK method, each stage solved by
// Newton to a tight tolerance. Unlike an adaptive step, the simulated output is then a smooth
// function of the model's parameters (finite-difference Jacobians of a fit stay clean), and the
// cost is fixed by the number of samples, not by how often the inputs switch.

#include <vector>

#include "lumped/ode.hpp"

namespace rheomag::lumped {

/// Integrates from `x0` at `times[0]` with `substeps` equal SDIRK2 steps per interval of `times`
/// (strictly increasing; piecewise-linear inputs are then smooth inside every step) and returns
/// the state at every entry of `times`. A step whose Newton iteration fails is split in halves;
/// throws ConvergenceError when that does not help or a state is not finite.
std::vector<std::vector<double>> integrate_on_grid(const OdeSystem& system, std::vector<double> x0,
                                                   const std::vector<double>& times,
                                                   int substeps = 1);

}  // namespace rheomag::lumped
