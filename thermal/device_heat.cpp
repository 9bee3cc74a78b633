// The heat of a device at an operating point: the chain of its kind evaluated at the coil's and
// the fluid's temperatures, and the powers placed on the coil and gap regions.

#include "thermal/device_heat.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "thermal/device_regions.hpp"
#include "thermal/heat_solver.hpp"
#include "valve/brake.hpp"
#include "valve/damper.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::thermal {

DeviceHeatModel::~DeviceHeatModel() = default;

DeviceHeatModel::DeviceHeatModel(const cases::Case& c, const OperatingPoint& point)
    : point_(point) {
  if (!(point.duty >= 0.0 && point.duty <= 1.0))
    throw InputError(
        format_text("--duty: expected a fraction of the time in [0, 1], got %.6g", point.duty));
  if (!std::isfinite(point.current)) throw InputError("--current: expected a finite current in A");
  switch (point.motion) {
    case Motion::none:
      chain_ = std::make_unique<valve::DeviceChain>(c, "thermal");
      break;
    case Motion::flow:
      chain_ = std::make_unique<valve::ValveChain>(c, valve::read_valve_options(c));
      break;
    case Motion::velocity:
      chain_ = std::make_unique<valve::DamperChain>(c, valve::read_damper_options(c));
      break;
    case Motion::speed:
      chain_ = std::make_unique<valve::BrakeChain>(c, valve::read_brake_options(c));
      break;
  }
  const cases::Problem& problem = chain_->solver().problem();
  coil_regions_ = thermal::coil_regions(problem);
  gap_regions_ = thermal::gap_regions(problem);
  region_volume_ = region_volumes(problem, chain_->solver().mesh());
  copper_fill_ = chain_->coil(point.current, 0.0).copper_fill;
}

int DeviceHeatModel::gap_region(const std::string& name) const {
  const cases::Problem& problem = chain_->solver().problem();
  for (int r : gap_regions_)
    if (problem.geometry.regions[r].name == name) return r;
  return -1;
}

DeviceHeat DeviceHeatModel::heat(double coil_celsius, double fluid_celsius) {
  chain_->set_coil_temperature(coil_celsius);
  chain_->set_fluid_temperature(fluid_celsius);
  DeviceHeat h;
  h.region_power.assign(chain_->solver().problem().regions.size(), 0.0);
  const valve::CoilProperties coil = chain_->coil(point_.current, 0.0);
  h.coil_resistance = coil.resistance;
  h.coil_power = point_.duty * coil.power;
  spread_power(h.coil_power, coil_regions_, region_volume_, h.region_power);
  const std::vector<double> currents{point_.current}, values{point_.value};
  double unplaced = 0.0;  // dissipation not tied to one gap: spread over all gaps
  if (point_.motion == Motion::flow) {
    const valve::ValvePoint p =
        static_cast<valve::ValveChain&>(*chain_).evaluate(currents, values).front();
    h.output = p.dp_total;
    for (const valve::SegmentResult& s : p.segments) {
      const double power = point_.duty * s.drop.integrated.dp * point_.value;
      h.fluid_power += power;
      const int r = gap_region(s.name);
      if (r >= 0)
        h.region_power[r] += power;
      else
        unplaced += power;
    }
  } else if (point_.motion == Motion::velocity) {
    const valve::DamperPoint p =
        static_cast<valve::DamperChain&>(*chain_).evaluate(currents, values).front();
    h.output = p.force;
    // The gas spring's force stores energy and gives it back: it dissipates nothing.
    unplaced = point_.duty * (p.force - p.force_gas) * p.velocity;
    h.fluid_power = unplaced;
  } else if (point_.motion == Motion::speed) {
    const valve::BrakePoint p =
        static_cast<valve::BrakeChain&>(*chain_).evaluate(currents, values).front();
    h.output = p.torque.torque;
    for (const valve::BrakeGapResult& g : p.gaps) {
      const double power = point_.duty * g.torque.torque * point_.value;
      h.fluid_power += power;
      const int r = gap_region(g.name);
      if (r >= 0)
        h.region_power[r] += power;
      else
        unplaced += power;
    }
  }
  spread_power(unplaced, gap_regions_, region_volume_, h.region_power);
  if (!std::isfinite(h.coil_power) || !std::isfinite(h.fluid_power))
    throw ConvergenceError("thermal: the device's heat is not finite");
  return h;
}

}  // namespace rheomag::thermal
