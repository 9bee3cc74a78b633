#pragma once
// What a damper and a brake on a solved field share: the sampled gaps, the fluid, the coil's
// current and inductance, and the zero-field copy.

#include <string>
#include <vector>

#include "fluid/fluid.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "valve/sampled_gaps.hpp"

namespace rheomag::valve {

/// The gaps of a device sampled once from a solved field.
class SolvedDevice {
 public:
  /// Samples the gaps (radial gaps from `inner_radius`, set by the user under `inner_key`);
  /// InputError naming the `device` if the case has no fluid gap.
  SolvedDevice(const magnetostatics::MagnetostaticSolver& solver,
               const magnetostatics::Solution& solution, const magnetostatics::Results& results,
               const fluid::Fluid& fluid, const std::string& device, double inner_radius = 0.0,
               const std::string& inner_key = "[valve] inlet_radius");

 protected:
  /// Sets |B| = 0 in every gap and the current and inductance to 0 (the zero-field state).
  void clear_field();

  std::vector<SampledGap> gaps_;
  fluid::Fluid fluid_;
  double current_ = 0.0, inductance_ = 0.0;
};

}  // namespace rheomag::valve
