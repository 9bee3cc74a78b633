#pragma once
// What the damper and brake chains share: the case's fluid, the mesh and solver set up once, the
// coil, and one field solve per coil current handed to the device's own evaluation.

#include <memory>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "fluid/fluid.hpp"
#include "magnetostatics/solver.hpp"
#include "valve/coil.hpp"
#include "valve/field_solve.hpp"
#include "valve/valve_options.hpp"

namespace rheomag::valve {

/// The currents asked for, or (none) the case's circuit current (that of its last circuit).
std::vector<double> currents_or_case(const cases::Case& c, const std::vector<double>& currents);

/// A device case (damper, brake): mesh and solver once, one field solve per current.
class DeviceChain {
 public:
  /// `device` names the device in messages ("damper", "brake"). InputError if the case has no
  /// coil or no fluid.
  DeviceChain(const cases::Case& c, std::string device);
  /// The same with the [valve] options given (e.g. overridden on the command line).
  DeviceChain(const cases::Case& c, std::string device, ValveOptions options);
  /// Coil quantities at `current` with inductance `inductance` (needs [valve] wire).
  CoilProperties coil(double current, double inductance) const;
  const fluid::Fluid& fluid() const { return fluid_; }

 protected:
  /// Solves the field at each current in turn and appends visit(solver, field) (a vector of
  /// points) to the result; InputError (naming `what`) if `currents` or `count` is empty.
  template <class Point, class Visit>
  std::vector<Point> per_current(const std::vector<double>& currents, std::size_t count,
                                 const std::string& what, Visit visit) {
    if (currents.empty() || count == 0)
      throw InputError(device_ + ": needs at least one current and one " + what);
    std::vector<Point> points;
    for (double current : currents) {
      const DeviceField field = solve_at_current(*solver_, current);
      for (Point& p : visit(*solver_, field)) points.push_back(std::move(p));
    }
    return points;
  }

  std::string device_;
  std::unique_ptr<magnetostatics::MagnetostaticSolver> solver_;
  fluid::Fluid fluid_;
  ValveOptions valve_options_;
  CoilSpec coil_;
};

}  // namespace rheomag::valve
