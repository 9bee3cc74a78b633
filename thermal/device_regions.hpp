#pragma once
// Where a device's heat goes on its field problem: the coil regions, the fluid-gap regions, and
// a power spread over regions by volume.

#include <vector>

#include "case/problem.hpp"

namespace rheomag::thermal {

/// Regions of the coil: a circuit, turns or a fixed source current density.
std::vector<int> coil_regions(const cases::Problem& problem);

/// Fluid-gap regions (RegionSeed::gap != none).
std::vector<int> gap_regions(const cases::Problem& problem);

/// Adds `power` [W] to `out` (per region) over `regions` in proportion to `volume` (per
/// region). InputError when there is power but no region (or no volume) to put it in.
void spread_power(double power, const std::vector<int>& regions, const std::vector<double>& volume,
                  std::vector<double>& out);

/// Source densities [W/m^3] of per-region powers (0 where a region has no volume).
std::vector<double> source_densities(const std::vector<double>& power,
                                     const std::vector<double>& volume);

}  // namespace rheomag::thermal
