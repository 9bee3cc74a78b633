#pragma once
// `rheomag valve` as a library call: a case's valve at a list of currents and flow rates plus its
// coil at the largest current, and that result as a JSON document and as a text report.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "valve/coil.hpp"
#include "valve/valve_chain.hpp"
#include "valve/valve_options.hpp"

namespace rheomag::valve {

/// A valve evaluated over currents x flows, with its coil at the largest current.
struct ValveReport {
  std::string case_name, fluid;
  ValveOptions options;            ///< as used (wire, temperature)
  std::vector<ValvePoint> points;  ///< current-major
  std::size_t flows_per_current = 0;
  double turns = 0.0;                  ///< of the first circuit
  std::size_t peak = 0;                ///< index in points of the largest |current| (first of them)
  std::optional<CoilProperties> coil;  ///< at the peak, when the options name a wire
};

/// Evaluates the case's valve at `currents` (empty: the case's) and `flows` (empty: [valve] flow;
/// InputError if neither gives one) with `options`, and its coil at the largest current.
ValveReport evaluate_valve(const cases::Case& c, const ValveOptions& options,
                           const std::vector<double>& currents, const std::vector<double>& flows,
                           const ProgressCallback& progress = {});

/// The JSON document of `rheomag valve --json` (SI units).
nlohmann::json valve_json(const ValveReport& report);

/// The text report of `rheomag valve` (pressures in bar).
std::string valve_text(const ValveReport& report);

}  // namespace rheomag::valve
