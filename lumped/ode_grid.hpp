#pragma once
// Fixed-step stiff integration on the sample grid of a recording: every sample interval is split
// into the same number of steps of a stiffly accurate, L-stable SDIRK method, each stage solved by
// Newton to a tight tolerance. Unlike an adaptive step, the simulated output is then a smooth
// function of the model's parameters (finite-difference Jacobians of a fit stay clean), and the
// cost is fixed by the number of samples, not by how often the inputs switch.

#include <vector>

#include "lumped/ode.hpp"

namespace rheomag::lumped {

/// Integrates from `x0` at `times[0]` with `substeps[k]` equal SDIRK2 steps over the interval
/// times[k] -> times[k+1] (strictly increasing times; substeps has one entry per interval, each
/// >= 1; inputs piecewise linear between samples are then smooth inside every step) and returns
/// the state at every entry of `times`. A step whose Newton iteration fails is split in halves;
/// throws ConvergenceError when that does not help or a state is not finite.
std::vector<std::vector<double>> integrate_on_grid(const OdeSystem& system, std::vector<double> x0,
                                                   const std::vector<double>& times,
                                                   const std::vector<int>& substeps);

/// The same with `substeps` steps in every interval.
std::vector<std::vector<double>> integrate_on_grid(const OdeSystem& system, std::vector<double> x0,
                                                   const std::vector<double>& times,
                                                   int substeps = 1);

}  // namespace rheomag::lumped
