#pragma once
// The magnetised gaps of a solved case: each gap region's geometry (from its rectangle in the
// meridian plane) and the normal flux density |B_n| sampled along its mid-line. Shared by the
// valve, the damper and the brake.

#include <string>
#include <vector>

#include "fluid/field_samples.hpp"
#include "fluid/gap.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::valve {

/// One gap region with its geometry and mid-line field.
struct SampledGap {
  std::string name;
  bool annular = true;             ///< annular (B_r sampled along z) or radial (B_z along r)
  fluid::AnnulusGeometry annulus;  ///< annular: mean radius = mid-line r, length = z extent,
                                   ///< clearance = area / length
  fluid::RadialGeometry radial;    ///< radial: r_in..r_out of the mid-line (r_in raised to
                                   ///< `inlet_radius`), clearance = area / (r_out - r_in)
  fluid::GapFieldSamples field;    ///< |B_n| at 101 mid-line points
};

/// Samples every gap of `results` in `solution`. A radial gap keeps the samples at r >=
/// `inlet_radius`; InputError if a gap has fewer than 2 samples or a radial gap starts on the
/// axis with inlet_radius = 0 (the message names `inlet_key`, where the user sets it).
std::vector<SampledGap> sample_gaps(const magnetostatics::MagnetostaticSolver& solver,
                                    const magnetostatics::Solution& solution,
                                    const magnetostatics::Results& results, double inlet_radius,
                                    const std::string& inlet_key = "[valve] inlet_radius");

/// Sets |B| to zero at every sample of every gap (the zero-field state of a device).
void zero_fields(std::vector<SampledGap>& gaps);

}  // namespace rheomag::valve
