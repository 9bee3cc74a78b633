#pragma once
// A current sweep of one circuit (`rheomag solve --sweep`) as a JSON array and as a text table.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics {

/// The sweep as a JSON array of {current, flux_linkage, inductance, incremental_inductance,
/// newton_iterations} (SI units).
nlohmann::json sweep_json(const std::vector<SweepPoint>& table);

/// The sweep as a text table (mWb, mH) headed by the circuit's name; nothing for an empty table.
std::string sweep_text(const std::vector<SweepPoint>& table, const std::string& circuit);

}  // namespace rheomag::magnetostatics
