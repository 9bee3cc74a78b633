#pragma once
// `rheomag damper` as a library call: a piston case's force-velocity curves at a list of currents,
// and that result as a JSON document and as a text report.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/progress.hpp"
#include "valve/damper.hpp"

namespace rheomag::valve {

/// A damper evaluated over currents x velocities.
struct DamperReport {
  std::string case_name, fluid;
  GapWall gap_wall = GapWall::cylinder;
  double gas_extended = 0.0, gas_compressed = 0.0;  ///< gas_force_range [N]
  std::vector<DamperPoint> points;                  ///< current-major
};

/// Reads [damper] and evaluates the piston at `currents` (empty: the case's) and `velocities`
/// (empty: [damper] velocity; InputError if neither gives one).
/// `progress` (if set) hears of every point evaluated.
DamperReport evaluate_damper(const cases::Case& c, const std::vector<double>& currents,
                             const std::vector<double>& velocities,
                             const ProgressCallback& progress = {});

/// The JSON document of `rheomag damper --json` (SI units).
nlohmann::json damper_json(const DamperReport& report);

/// The text report of `rheomag damper`.
std::string damper_text(const DamperReport& report);

}  // namespace rheomag::valve
