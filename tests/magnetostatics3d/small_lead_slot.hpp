#pragma once
// A small 3D test model: the small valve of the test data with a 2 x 1.5 mm lead slot in its
// core at 2 A, and coarse swept-mesh settings for its half model.

#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "magnetostatics3d/solve3d.hpp"

namespace rheomag::magnetostatics3d {

/// The small valve with a lead slot in its core, at 2 A.
inline cases::Case small_valve_with_lead_slot() {
  const std::string path = std::string(RHEOMAG_TEST_DATA) + "/magnetostatics3d/small_valve.toml";
  cases::Case c = cases::parse_case(
      cases::read_input_file(path) +
          "\n[[feature]]\nkind = \"lead_slot\"\nregion = \"core\"\nwidth = 2.0\ndepth = 1.5\n",
      path);
  c.problem.circuits.at(0).current = 2.0;
  return c;
}

/// swept_options() coarsened for tests: one layer across a gap, 7.5-degree steps (3.75 at the
/// feature's edges), regions at half their smaller side.
inline Solve3dOptions coarse_swept_options() {
  Solve3dOptions options = swept_options();
  options.gap_layers = 1;
  options.region_fraction = 0.5;
  options.facet_angle = 7.5 * std::numbers::pi / 180.0;
  options.fine_angle = 3.75 * std::numbers::pi / 180.0;
  return options;
}

}  // namespace rheomag::magnetostatics3d
