// Fitting and running the two-node thermal network.

#include "thermal/thermal_network.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/error.hpp"
#include "thermal/device_regions.hpp"
#include "thermal/device_temperature.hpp"

namespace rheomag::thermal {

Eigen::Vector2d ThermalNetwork::steady(const Eigen::Vector2d& power) const {
  return baseline + resistance * power;
}

Eigen::Vector2d ThermalNetwork::time_constants() const {
  // dT/dt = -C^-1 G T: rates are the eigenvalues of C^-1 G (real and positive: similar to the
  // symmetric C^-1/2 G C^-1/2).
  const Eigen::Matrix2d a = capacity.cwiseInverse().asDiagonal() * resistance.inverse();
  const Eigen::Vector2d rates = a.eigenvalues().real();
  Eigen::Vector2d tau(1.0 / rates.minCoeff(), 1.0 / rates.maxCoeff());
  return tau;
}

Eigen::Vector2d ThermalNetwork::after(const Eigen::Vector2d& start, const Eigen::Vector2d& power,
                                      double duration) const {
  const Eigen::Matrix2d a = capacity.cwiseInverse().asDiagonal() * resistance.inverse();
  const Eigen::EigenSolver<Eigen::Matrix2d> eigen(a);
  const Eigen::Matrix2d v = eigen.eigenvectors().real();
  const Eigen::Vector2d rates = eigen.eigenvalues().real();
  const Eigen::Vector2d target = steady(power);
  const Eigen::Vector2d modes = v.inverse() * (start - target);
  Eigen::Vector2d decayed;
  for (int i = 0; i < 2; ++i) decayed[i] = modes[i] * std::exp(-rates[i] * duration);
  return target + v * decayed;
}

ThermalNetwork fit_network(HeatSolver& solver, const std::vector<int>& coil,
                           const std::vector<int>& fluid, const std::vector<double>& volume) {
  if (coil.empty() || fluid.empty())
    throw InputError("thermal network: needs coil regions and fluid-gap regions");
  ThermalNetwork n;
  const std::size_t regions = volume.size();
  solver.set_sources(std::vector<double>(regions, 0.0));
  const HeatSolution none = solver.steady();
  n.baseline = {mean_over(none, coil), mean_over(none, fluid)};
  for (int column = 0; column < 2; ++column) {
    std::vector<double> power(regions, 0.0);
    spread_power(1.0, column == 0 ? coil : fluid, volume, power);
    solver.set_sources(source_densities(power, volume));
    const HeatSolution s = solver.steady();
    n.resistance(0, column) = mean_over(s, coil) - n.baseline[0];
    n.resistance(1, column) = mean_over(s, fluid) - n.baseline[1];
  }
  solver.set_sources(std::vector<double>(regions, 0.0));
  const std::vector<double> c = solver.region_heat_capacity();
  n.capacity.setZero();
  for (std::size_t r = 0; r < regions; ++r) {
    bool in_coil = false;
    for (int k : coil) in_coil = in_coil || k == static_cast<int>(r);
    n.capacity[in_coil ? 0 : 1] += c[r];
  }
  return n;
}

}  // namespace rheomag::thermal
