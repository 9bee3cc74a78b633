#pragma once
// The two-node thermal network of a device (coil; fluid with the body around it) fitted from
// its FE heat conduction, for long duty cycles on the lumped side:
//   C dT/dt = P - G (T - T_ambient),  T = (coil mean, fluid mean),  G = R^-1,
// (T - T_ambient read as T - baseline, the temperatures without sources), with R the FE steady
// rise of both means per watt into the coil and into the fluid (exact at
// steady state for any powers) and C the heat capacities of the coil and of everything else.

#include <Eigen/Core>
#include <vector>

#include "thermal/heat_solver.hpp"

namespace rheomag::thermal {

/// A fitted two-node network.
struct ThermalNetwork {
  Eigen::Vector2d baseline;    ///< (coil, fluid) without sources [deg C] (the ambient)
  Eigen::Vector2d capacity;    ///< coil, fluid-and-body [J/K]
  Eigen::Matrix2d resistance;  ///< rise of (coil, fluid) mean per W into (coil, fluid) [K/W]
  /// Steady (coil, fluid) temperatures [deg C] under powers (coil, fluid) [W].
  Eigen::Vector2d steady(const Eigen::Vector2d& power) const;
  /// Time constants of the network, slow first [s].
  Eigen::Vector2d time_constants() const;
  /// Temperatures after `duration` seconds at constant `power` from `start` (exact: the
  /// matrix exponential of the 2 x 2 system).
  Eigen::Vector2d after(const Eigen::Vector2d& start, const Eigen::Vector2d& power,
                        double duration) const;
};

/// Fits the network from three steady solves of `solver` (no source, 1 W spread over `coil`,
/// then over `fluid`, by `volume`), with the capacity of the coil regions and of every other
/// region of the model. The solver's sources are left at zero.
ThermalNetwork fit_network(HeatSolver& solver, const std::vector<int>& coil,
                           const std::vector<int>& fluid, const std::vector<double>& volume);

}  // namespace rheomag::thermal
