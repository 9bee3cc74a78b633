#pragma once
// Magnet wire: bare copper diameter from a gauge (AWG or metric) and the turns that fit a
// winding window at a given copper fill factor (the case's coil, before the field solve).

#include <string>

namespace rheomag::cases {

/// Bare copper diameter [m] of American Wire Gauge `gauge` (ASTM B258: d = 0.127 mm x
/// 92^((36 - n)/39); 0, 00, 000, 0000 are n = 0, -1, -2, -3), for n in [-3, 56].
double awg_diameter(int gauge);

/// Bare diameter [m] of AWG `n` for any real n (the same formula between the whole gauges: the
/// continuous relaxation a wire-gauge design variable uses).
double awg_diameter_relaxed(double n);

/// The (real) AWG number of a bare diameter [m], the inverse of awg_diameter_relaxed.
double awg_number(double diameter);

/// Bare diameter [m] from a wire specification: "AWG 24", "awg24", "24 AWG", "0.5 mm", "0.5mm".
/// Throws InputError naming the text and the accepted forms.
double wire_diameter(const std::string& spec);

/// Turns of bare diameter `wire_diameter` [m] that fit `window_area` [m^2] at copper fill factor
/// `fill` (copper cross-section / window area, in (0, pi/4]): floor(fill A / (pi d^2 / 4)).
/// Throws InputError for bad values or when not even one turn fits.
double winding_turns(double window_area, double wire_diameter, double fill);

}  // namespace rheomag::cases
