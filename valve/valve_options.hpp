#pragma once
// The [valve] table of a case file: the coil's wire and temperature, default flows, unmagnetised
// passages and minor losses in series.

#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "fluid/passage.hpp"

namespace rheomag::valve {

/// [valve] (this layer's) and [damper] (reserved for damper devices) are sections of case files.
inline const bool kValveSectionsRegistered =
    cases::register_case_section("valve") && cases::register_case_section("damper");

/// Options of the [valve] table of a case file (docs/fluid.md); all optional except where noted.
struct ValveOptions {
  std::string wire;            ///< wire gauge, e.g. "AWG 24" (needed for the coil resistance)
  double wire_diameter = 0.0;  ///< its bare diameter [m] (0: from `wire`'s text)
  double temperature = 20.0;   ///< coil temperature [deg C]
  double inlet_radius = 0.0;   ///< radial gaps starting on the axis start here instead [m]
  std::vector<double> flows;   ///< default flow rates [m^3/s]
  std::vector<fluid::Passage> passages;  ///< unmagnetised passages in series ([[valve.passage]])
  std::vector<fluid::MinorLoss> losses;  ///< minor losses in series ([[valve.loss]])
};

/// Reads the [valve] table of a case (absent: defaults). InputError names unknown keys.
ValveOptions read_valve_options(const cases::Case& c);

}  // namespace rheomag::valve
