#pragma once
// `rheomag brake` as a library call: a shear-mode case's torque-speed curves at a list of
// currents, and that result as a JSON document and as a text report.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/progress.hpp"
#include "valve/brake.hpp"

namespace rheomag::valve {

/// A brake evaluated over currents x speeds.
struct BrakeReport {
  std::string case_name, fluid;
  std::vector<BrakePoint> points;  ///< current-major
};

/// Reads [brake] and evaluates the brake at `currents` (empty: the case's) and `speeds` (empty:
/// [brake] speed; InputError if neither gives one); `progress` (if set) hears of every point.
BrakeReport evaluate_brake(const cases::Case& c, const std::vector<double>& currents,
                           const std::vector<double>& speeds,
                           const ProgressCallback& progress = {});

/// The JSON document of `rheomag brake --json` (SI units).
nlohmann::json brake_json(const BrakeReport& report);

/// The text report of `rheomag brake`.
std::string brake_text(const BrakeReport& report);

}  // namespace rheomag::valve
