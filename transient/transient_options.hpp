#pragma once
// What a transient run is asked to do: the drive of the first circuit, the time span, the time
// scheme and step control.

#include <functional>

#include "core/enum_names.hpp"
#include "core/progress.hpp"
#include "magnetostatics/newton.hpp"

namespace rheomag::transient {

/// How the first circuit is driven after the step at t = 0.
enum class Drive {
  current,  ///< ideal current source: i(t) = value for t > 0
  voltage,  ///< ideal voltage source through the coil resistance: V = R i + dlambda/dt
};

/// Time discretisation of sigma dA/dt + curl(nu curl A) = J_s.
enum class TimeScheme {
  /// Continuous Galerkin cG(1) in time (the implicit midpoint / average-vector-field rule):
  /// second order, A-stable, and its discrete energy balance is exact (docs/transient.md).
  midpoint,
  backward_euler,  ///< first order, L-stable (strong damping of unresolved fast modes)
};

/// Text names of Drive and TimeScheme (CLI, JSON).
inline constexpr EnumNames<Drive, 2> kDriveNames{
    {{{Drive::current, "current"}, {Drive::voltage, "voltage"}}}};
inline constexpr EnumNames<TimeScheme, 2> kTimeSchemeNames{
    {{{TimeScheme::midpoint, "midpoint"}, {TimeScheme::backward_euler, "backward_euler"}}}};

/// Settings of one step-response run.
struct TransientOptions {
  Drive drive = Drive::current;
  double from_current = 0.0;  ///< steady state before the step [A]
  double value = 0.0;         ///< after the step: current [A] or supply voltage [V]
  double duration = 0.0;      ///< simulated time after the step [s] (> 0)
  int steps = 0;              ///< > 0: that many equal steps; 0: adaptive steps
  double tolerance = 1e-4;    ///< adaptive: local error of lambda per step / its total change
  double max_step = 0.0;      ///< adaptive: largest step [s]; 0 = duration / 50
  /// adaptive: first step [s]; 0 = duration * 1e-6 after a current step, 1e-4 after a voltage step
  double first_step = 0.0;
  double resistance = 0.0;  ///< first circuit's resistance [Ohm] (required for a voltage step)
  TimeScheme scheme = TimeScheme::midpoint;
  magnetostatics::NewtonOptions newton;  ///< Newton at every step (local corrections unused)
  ProgressCallback progress;             ///< one report per accepted step
  /// Equal steps: when the local error indicator exceeds kStepCheckTrigger, measure the run's
  /// error against a run of half the step (TransientResult::step_error).
  bool check_steps = true;
  /// > 0: end the run at the first step after which every fluid gap's mean |B| has passed this
  /// fraction of its change (a response time needs no more: rise times are first crossings, so
  /// those up to the fraction are the whole run's, bit for bit); 0: simulate the whole duration.
  double stop_at_gap_fraction = 0.0;
  /// Start each step's Newton from the last state when its residual is smaller than that of the
  /// extrapolation through the last states (false: always the extrapolation; docs/transient.md,
  /// "Where a step's Newton starts"). The answer is the same to Newton's tolerance.
  bool choose_start = true;
};

/// Indicator of the local error (per step, relative to lambda's change) above which a run of
/// equal steps is checked against half steps; the indicator over-estimates (3.6 % on a run whose
/// t63 and t90 are within 0.7 % of the adaptive run's).
inline constexpr double kStepCheckTrigger = 0.01;

}  // namespace rheomag::transient
