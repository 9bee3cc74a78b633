// Steady fixed point and transient of a device's temperatures.

#include "thermal/device_temperature.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "thermal/device_regions.hpp"

namespace rheomag::thermal {

namespace {

/// The heat at the temperatures of `t` (or at the fixed temperature); a temperature outside
/// the models' range there means the device runs away: ConvergenceError.
DeviceHeat heat_at(DeviceHeatModel& device, const CouplingOptions& options,
                   const DeviceTemperatures& t) {
  const double coil = options.temperature.value_or(t.coil_mean);
  const double fluid =
      options.temperature.value_or(std::isfinite(t.fluid_mean) ? t.fluid_mean : t.coil_mean);
  try {
    return device.heat(coil, fluid);
  } catch (const InputError& e) {
    if (options.temperature) throw;
    throw ConvergenceError(
        format_text("thermal: the device leaves the models' range at coil "
                    "%.4g C, fluid %.4g C (%s)",
                    coil, fluid, e.what()));
  }
}

}  // namespace

double mean_over(const HeatSolution& solution, const std::vector<int>& regions) {
  double volume = 0.0, integral = 0.0;
  for (int r : regions) {
    volume += solution.regions[r].volume;
    integral += solution.regions[r].mean * solution.regions[r].volume;
  }
  return volume > 0.0 ? integral / volume : NAN;
}

DeviceTemperatures temperatures_over(const HeatSolution& solution, const std::vector<int>& coil,
                                     const std::vector<int>& gaps) {
  const auto max_over = [&](const std::vector<int>& regions) {
    double max = regions.empty() ? NAN : -INFINITY;
    for (int r : regions) max = std::max(max, solution.regions[r].max);
    return max;
  };
  DeviceTemperatures t;
  t.coil_mean = mean_over(solution, coil);
  t.coil_max = max_over(coil);
  t.fluid_mean = mean_over(solution, gaps);
  t.fluid_max = max_over(gaps);
  return t;
}

DeviceTemperatures device_temperatures(const HeatSolution& solution,
                                       const DeviceHeatModel& device) {
  return temperatures_over(solution, device.coil_regions(), device.gap_regions());
}

SteadyDevice steady_device(DeviceHeatModel& device, HeatSolver& solver,
                           const CouplingOptions& options, double ambient) {
  SteadyDevice out;
  out.coupled = !options.temperature.has_value();
  HeatSolution solution = solver.evaluate(solver.uniform(ambient), Eigen::VectorXd());
  DeviceTemperatures t = device_temperatures(solution, device);
  const auto heat_or_runaway = [&](const DeviceTemperatures& at) {
    try {
      return heat_at(device, options, at);
    } catch (const ConvergenceError& e) {
      throw ConvergenceError(std::string(e.what()) +
                             ": no steady temperature at this operating point (try --duration "
                             "for the time to get there, a duty below 1 or more cooling)");
    }
  };
  for (int k = 1; k <= options.max_iterations; ++k) {
    const DeviceHeat heat = heat_or_runaway(t);
    solver.set_sources(source_densities(heat.region_power, device.region_volume()));
    solution = solver.steady();
    const DeviceTemperatures next = device_temperatures(solution, device);
    const double change =
        std::max(std::abs(next.coil_mean - t.coil_mean),
                 std::isfinite(next.fluid_mean) ? std::abs(next.fluid_mean - t.fluid_mean) : 0.0);
    t = next;
    out.iterations = k;
    if (!out.coupled || change < options.tolerance) {
      out.solution = solution;
      out.temperatures = t;
      out.heat = heat;  // the sources of this solution (at the last iterate, within tolerance)
      return out;
    }
  }
  throw ConvergenceError(
      format_text("thermal: the coil and fluid temperatures did not settle "
                  "in %d iterations (last coil mean %.4g C): thermal runaway "
                  "at this current?",
                  options.max_iterations, t.coil_mean));
}

DeviceTransient transient_device(DeviceHeatModel& device, HeatSolver& solver,
                                 const CouplingOptions& options, double ambient, double duration,
                                 int steps, std::optional<double> limit) {
  if (!(duration > 0.0) || !std::isfinite(duration))
    throw InputError(format_text("--duration: expected a time > 0 s, got %.6g", duration));
  if (steps < 1) throw InputError("--steps: expected at least 1 step");
  DeviceTransient out;
  const auto record = [&](const HeatSolution& s) {
    DeviceSample sample;
    sample.time = s.time;
    sample.temperatures = device_temperatures(s, device);
    DeviceHeat heat;
    try {
      heat = heat_at(device, options, sample.temperatures);
    } catch (const ConvergenceError& e) {
      out.stopped = e.what();
      out.samples.push_back(sample);
      return false;
    }
    sample.coil_power = heat.coil_power;
    sample.fluid_power = heat.fluid_power;
    solver.set_sources(source_densities(heat.region_power, device.region_volume()));  // next step
    if (limit && !out.time_to_limit && sample.temperatures.hottest() >= *limit) {
      // Linear interpolation between the last two states.
      if (out.samples.empty()) {
        out.time_to_limit = 0.0;
      } else {
        const DeviceSample& before = out.samples.back();
        const double a = before.temperatures.hottest(), b = sample.temperatures.hottest();
        out.time_to_limit = before.time + (sample.time - before.time) * (*limit - a) / (b - a);
      }
    }
    out.samples.push_back(sample);
    return true;
  };
  const Eigen::VectorXd start = solver.uniform(ambient);
  record(solver.evaluate(start, Eigen::VectorXd()));  // sets the first step's sources
  out.samples.clear();
  out.time_to_limit.reset();
  out.last = solver.transient(start, duration / steps, steps, record);
  if (!out.stopped.empty()) {  // the last sample has no heat: it is where the models stop
    out.samples.back().coil_power = NAN;
    out.samples.back().fluid_power = NAN;
  }
  return out;
}

}  // namespace rheomag::thermal
