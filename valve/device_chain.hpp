#pragma once
// What the damper and brake chains share: the case's fluid, the mesh and solver set up once, the
// coil, and one field solve per coil current handed to the device's own evaluation.

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "core/format_text.hpp"
#include "core/progress.hpp"
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
  virtual ~DeviceChain() = default;  ///< a valve, damper or brake chain may be held as a chain
  /// Coil quantities at `current` with inductance `inductance` (needs [valve] wire).
  CoilProperties coil(double current, double inductance) const;
  const fluid::Fluid& fluid() const { return fluid_; }
  /// Evaluates the next points with the fluid at `celsius` [deg C] (its temperature law,
  /// fluid/fluid_temperature.hpp); InputError outside the law's range.
  void set_fluid_temperature(double celsius);
  /// Evaluates the next points with the winding at `celsius` [deg C] (its resistance);
  /// InputError outside kCoilTemperature.
  void set_coil_temperature(double celsius);
  /// The field solver (its problem and mesh are those of the device's thermal model).
  const magnetostatics::MagnetostaticSolver& solver() const { return *solver_; }
  /// Reports the evaluation's progress (points done of currents x points) to `progress`.
  void set_progress(ProgressCallback progress) { progress_ = std::move(progress); }

 protected:
  /// Called by a device's visit after each point it evaluated.
  using PointDone = std::function<void()>;

  /// Solves the field at each current in turn and appends visit(solver, field, point_done) (a
  /// vector of `count` points) to the result; InputError (naming `what`) if `currents` or
  /// `count` is empty.
  template <class Point, class Visit>
  std::vector<Point> per_current(const std::vector<double>& currents, std::size_t count,
                                 const std::string& what, Visit visit) {
    if (currents.empty() || count == 0)
      throw InputError(device_ + ": needs at least one current and one " + what);
    const auto start = std::chrono::steady_clock::now();
    const double total = static_cast<double>(currents.size() * count);
    double done = 0.0;
    std::string stage;
    const auto report = [&] {
      if (!progress_) return;
      const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
      progress_({stage, done, total, elapsed.count(), "", false});
    };
    const PointDone point_done = [&] {
      done += 1.0;
      report();
    };
    std::vector<Point> points;
    for (double current : currents) {
      stage = format_text("%s at %.6g A", device_.c_str(), current);
      report();
      // The field does not depend on the fluid's or the coil's temperature: the last one is
      // reused for the same current (a thermal fixed point evaluates one current many times).
      if (!last_field_ || last_current_ != current) {
        last_field_ = std::make_unique<DeviceField>(solve_at_current(*solver_, current));
        last_current_ = current;
      }
      for (Point& p : visit(*solver_, *last_field_, point_done)) points.push_back(std::move(p));
    }
    return points;
  }

  std::string device_;
  std::unique_ptr<magnetostatics::MagnetostaticSolver> solver_;
  fluid::Fluid fluid_;
  fluid::Fluid reference_fluid_;  ///< the case's fluid at its reference temperature
  ValveOptions valve_options_;
  CoilSpec coil_;
  ProgressCallback progress_;
  std::unique_ptr<DeviceField> last_field_;  ///< the field of the last current solved
  double last_current_ = 0.0;
};

}  // namespace rheomag::valve
