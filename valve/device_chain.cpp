// Shared set-up of the damper and brake chains (device_chain.hpp).

#include "valve/device_chain.hpp"

#include "core/error.hpp"
#include "valve/solved_valve.hpp"

namespace rheomag::valve {

DeviceChain::DeviceChain(const cases::Case& c, std::string device)
    : DeviceChain(c, std::move(device), read_valve_options(c)) {}

DeviceChain::DeviceChain(const cases::Case& c, std::string device, ValveOptions options)
    : device_(std::move(device)), valve_options_(std::move(options)) {
  fluid_ = case_fluid(c);
  reference_fluid_ = fluid_;
  if (c.problem.circuits.empty())
    throw InputError(c.source.string() + ": the case has no coil circuit");
  solver_ = make_device_solver(c);
  coil_ = coil_spec(*solver_, valve_options_);
}

CoilProperties DeviceChain::coil(double current, double inductance) const {
  if (valve_options_.wire.empty())
    throw InputError(
        device_ +
        ": the coil resistance needs the wire: set [valve] wire = \"AWG 24\" (or \"0.5 mm\") "
        "in the case (or pass --wire where the command offers it)");
  return coil_properties(coil_, current, inductance);
}

void DeviceChain::set_fluid_temperature(double celsius) {
  fluid_ = fluid::fluid_at_temperature(reference_fluid_, celsius);
}

void DeviceChain::set_coil_temperature(double celsius) {
  const std::string problem = kCoilTemperature.violation(celsius);
  if (!problem.empty()) throw InputError(device_ + ": coil temperature: " + problem);
  coil_.temperature = celsius;
}

std::vector<double> currents_or_case(const cases::Case& c, const std::vector<double>& currents) {
  if (!currents.empty()) return currents;
  std::vector<double> out;
  for (const auto& circuit : c.problem.circuits) out = {circuit.current};
  return out;
}

}  // namespace rheomag::valve
