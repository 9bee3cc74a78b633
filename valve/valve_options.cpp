// Reads the [valve] table of a case file (valve_options.hpp).

#include "valve/valve_options.hpp"

#include "case/femm_sidecar.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"
#include "valve/coil.hpp"

namespace rheomag::valve {

ValveOptions read_valve_options(const cases::Case& c) {
  ValveOptions options;
  const cases::TomlSection top(c.table, "", cases::case_document_source(c));
  // A template case winding its coil from [geometry] wire + fill_factor has its wire there.
  options.wire = c.input.winding.wire;
  options.wire_diameter = c.input.winding.wire_diameter;
  auto valve = top.table("valve");
  if (!valve) return options;
  valve->allow_only({"wire", "temperature", "inlet_radius", "flow", "passage", "loss"});
  options.passages = fluid::read_passages(*valve);
  options.losses = fluid::read_losses(*valve);
  if (auto wire = valve->string("wire")) {
    double diameter = 0.0;
    try {
      diameter = wire_diameter(*wire);
    } catch (const InputError& e) {
      valve->fail("wire", e.what());
    }
    if (!options.wire.empty() && diameter != options.wire_diameter)
      valve->fail("wire", "\"" + *wire + "\" differs from [geometry] wire = \"" + options.wire +
                              "\"; give the wire once");
    options.wire = *wire;
    options.wire_diameter = diameter;
  }
  options.temperature = valve->quantity_or("temperature", kCoilTemperature, 20.0);
  options.inlet_radius = valve->non_negative_or("inlet_radius", 0.0);
  if (auto flow = valve->number("flow")) {
    if (!(*flow > 0.0)) throw InputError(c.source.string() + ": [valve].flow must be > 0 m^3/s");
    options.flows = {*flow};
  }
  return options;
}

}  // namespace rheomag::valve
