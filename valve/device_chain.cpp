// Shared set-up of the damper and brake chains (device_chain.hpp).

#include "valve/device_chain.hpp"

#include "core/error.hpp"
#include "valve/solved_valve.hpp"

namespace rheomag::valve {

DeviceChain::DeviceChain(const cases::Case& c, std::string device)
    : device_(std::move(device)), valve_options_(read_valve_options(c)) {
  fluid_ = case_fluid(c);
  if (c.problem.circuits.empty())
    throw InputError(c.source.string() + ": the case has no coil circuit");
  solver_ = make_device_solver(c);
  coil_ = coil_spec(*solver_, valve_options_);
}

CoilProperties DeviceChain::coil(double current, double inductance) const {
  if (valve_options_.wire.empty())
    throw InputError(device_ +
                     ": the coil resistance needs the wire: set [valve] wire in the case");
  return coil_properties(coil_, current, inductance);
}

}  // namespace rheomag::valve
