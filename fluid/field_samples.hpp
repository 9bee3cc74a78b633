#pragma once
// Flux density sampled along a gap's mid-line and the sums over those samples shared by the
// field-coupled gap models (valves, dampers, brakes).

#include <vector>

namespace rheomag::fluid {

/// Flux density sampled along a gap's mid-line in the flow (or, for a disc, radial) direction.
struct GapFieldSamples {
  std::vector<double> position;  ///< annular: axial distance from the gap start [m];
                                 ///< radial: radius [m]; strictly increasing
  std::vector<double> b;         ///< flux density magnitude driving tau_y (normal component) [T]
};

/// Throws InputError (prefixed by `what`) unless the samples pair up, are finite, increase
/// strictly and lie in [start, end].
void check_field_samples(const GapFieldSamples& field, double start, double end, const char* what);

/// int_start^end f ds with f known at the positions x: trapezoid between samples, f held
/// constant from the first/last sample to the ends.
double integrate_samples(const std::vector<double>& x, const std::vector<double>& f, double start,
                         double end);

/// Linear interpolation of the samples at `at` (held constant outside).
double interpolate_samples(const std::vector<double>& x, const std::vector<double>& f, double at);

/// |b| of every sample.
std::vector<double> sample_magnitudes(const std::vector<double>& b);

}  // namespace rheomag::fluid
