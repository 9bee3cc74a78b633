#pragma once
// Shear-mode brake or rotary damper built on the FE field of a case: every annular gap region is
// a drum (inner wall turning), every radial gap region one sheared disc face, each with the
// local yield stress tau_y(B) along it -> torque at a rotor speed and coil current
// (docs/dampers.md).

#include <memory>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "fluid/device_in_field.hpp"
#include "fluid/fluid.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "valve/coil.hpp"
#include "valve/device_chain.hpp"
#include "valve/sampled_gaps.hpp"
#include "valve/solved_device.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::valve {

/// [brake] is a section of brake case files.
inline const bool kBrakeSectionRegistered = cases::register_case_section("brake");

/// The [brake] table of a case (SI units; optional).
struct BrakeOptions {
  std::vector<double> speeds;  ///< default rotor speeds [rad/s]
  double inner_radius = 0.0;   ///< disc gaps starting on the axis start here instead [m]
};

/// Reads the [brake] table (absent: defaults); InputError naming the key if invalid.
BrakeOptions read_brake_options(const cases::Case& c);

/// One sheared gap at one operating point.
struct BrakeGapResult {
  std::string name;
  std::string kind;        ///< "drum" (annular gap region) or "disc" (radial gap region)
  double b_average = 0.0;  ///< mean |B_n| along the mid-line [T]
  fluid::ShearTorque torque;
};

/// The brake at one (current, speed).
struct BrakePoint {
  double current = 0.0, speed = 0.0;  ///< [A], [rad/s]
  fluid::ShearTorque torque;          ///< the gaps summed (yielded_fraction: area-weighted mean)
  double inductance = 0.0;            ///< secant lambda/I of circuit 0 [H]
  std::vector<BrakeGapResult> gaps;
};

/// A brake whose field is solved: gaps sampled once, then any speed.
class SolvedBrake : public SolvedDevice {
 public:
  SolvedBrake(const magnetostatics::MagnetostaticSolver& solver,
              const magnetostatics::Solution& solution, const magnetostatics::Results& results,
              const fluid::Fluid& fluid, const BrakeOptions& options);
  /// The torque at rotor speed `speed` [rad/s] (either sign; 0 gives the breakaway torque).
  BrakePoint point(double speed) const;
  /// The same brake with zero flux density in every gap (current and inductance 0).
  SolvedBrake zero_field() const;

 private:
};

/// A brake case: mesh and solver once, one field solve per current.
class BrakeChain : public DeviceChain {
 public:
  /// InputError if the case has no gap, no coil or no fluid.
  BrakeChain(const cases::Case& c, BrakeOptions options);
  /// current-major list of points.
  std::vector<BrakePoint> evaluate(const std::vector<double>& currents,
                                   const std::vector<double>& speeds);

 private:
  BrakeOptions options_;
};

}  // namespace rheomag::valve
