#pragma once
// Presenting a quasi-static response (`rheomag transient --quasi-static`): JSON and text.

#include <nlohmann/json.hpp>
#include <string>

#include "transient/quasi_static.hpp"

namespace rheomag::transient {

/// What was asked of the reduction and what it gave.
struct QuasiStaticRun {
  std::string drive;           ///< "current" or "voltage"
  double value = 0.0;          ///< current [A] or supply voltage [V] after the step
  double from_current = 0.0;   ///< [A]
  double final_current = 0.0;  ///< [A]
  double resistance = 0.0;     ///< [Ohm]; 0 for a current step
  std::vector<std::string> gap_names;
  QuasiStaticTable table;
  QuasiStaticStep step;
  int dofs = 0;
};

/// Keys: model ("quasi_static"), drive, value, from, final_current, resistance, t63, t90 (null
/// when not reached), gaps [{name, B_from, B_final, t63, t90}], table [{current, flux_linkage,
/// inductance, eddy_load}], newton_iterations, dofs (SI units).
nlohmann::json quasi_static_json(const QuasiStaticRun& run);

/// Plain-text summary (ms, mH, mT).
std::string quasi_static_summary(const QuasiStaticRun& run);

}  // namespace rheomag::transient
