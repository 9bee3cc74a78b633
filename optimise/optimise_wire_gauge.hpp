#pragma once
// Wire gauge as a design variable: the continuous relaxation of the American Wire Gauge (the
// ASTM B258 diameter formula for non-integer n) for a coil wound from [geometry] wire +
// fill_factor (docs/case-format.md), whose turns follow the winding window.

#include <toml++/toml.h>
#include <string>

namespace rheomag::optimise {

/// The design-variable key of the gauge (AWG number, continuous while optimising).
inline constexpr const char* kWireGaugeKey = "wire_gauge";

/// Bare diameter [m] of AWG `n` for any real n: 0.127 mm x 92^((36 - n) / 39) (ASTM B258's
/// formula, which the integer gauges follow).
double awg_diameter_relaxed(double n);

/// The (real) AWG number of a bare diameter [m], the inverse of awg_diameter_relaxed.
double awg_number(double diameter);

/// The [geometry] wire text of gauge `n`: "AWG n" for a whole n >= 1, "AWG 0", "AWG 00", ... for
/// n <= 0, otherwise the bare diameter "0.51234567 mm".
std::string wire_text(double n);

/// The start gauge of a case winding its coil from [geometry] wire + fill_factor; InputError
/// (prefixed by `where`) naming what is missing otherwise.
double wire_gauge_start(const toml::table& table, const std::string& where);

}  // namespace rheomag::optimise
