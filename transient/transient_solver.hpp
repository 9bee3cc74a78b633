#pragma once
// Axisymmetric (or planar) nonlinear transient magnetics with eddy currents, the first circuit
// driven by a current or voltage step: sigma dA/dt + curl(nu(|B|) curl A) = J_s(i), and for a
// voltage drive V = R i + dlambda/dt solved together with the field (docs/transient.md).

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "magnetostatics/solver.hpp"
#include "transient/eddy.hpp"
#include "transient/step_system.hpp"
#include "transient/transient_options.hpp"

namespace rheomag::transient {

/// Energy bookkeeping of a run [J], summed over the time steps after the step at t = 0.
/// Per step, the scheme's discrete equations dotted with the step's change give exactly
///   source = field_work + eddy_loss + copper_loss          (to the Newton tolerance),
/// and field_work = stored_change + numerical_dissipation, the last the scheme's own error in
/// integral H . dB (zero for the midpoint scheme on linear materials, >= 0 and O(h) for backward
/// Euler, the error of the 2-point rule in s for the midpoint scheme on a B-H curve).
struct EnergyBalance {
  double source = 0.0;  ///< work of the source: integral V i dt (voltage) or i dlambda + R i^2 dt
  double field_work = 0.0;     ///< the scheme's integral H . dB dV over the steps
  double stored_change = 0.0;  ///< W(end) - W(0+), W = integral integral_0^B H dB dV (+ exterior)
  double numerical_dissipation = 0.0;  ///< field_work - stored_change
  double eddy_loss = 0.0;              ///< integral (sigma |dA/dt|^2 + kappa |dB/dt|^2) dV dt
  double copper_loss = 0.0;            ///< integral R i^2 dt
  double step_energy = 0.0;  ///< current step only: W(0+) - W(0-), the lossless jump at t = 0
  /// Largest |source - field_work - losses| of one step, relative to the run's energy scale
  /// max(|source|, |stored_change|, eddy_loss + copper_loss).
  double max_step_error = 0.0;
  double total_error = 0.0;  ///< |source - field_work - losses| / the same scale
  /// Largest |field_work - (W(x1) - W(x0))| of one step / the same scale.
  double max_step_dissipation = 0.0;
};

/// The mean |B| over one fluid gap region at every recorded time.
struct GapSeries {
  std::string name;
  int region = -1;
  std::vector<double> b_avg;       ///< area-weighted mean |B| [T]
  double final_b = 0.0;            ///< static mean |B| at the final current [T]
  std::optional<double> t63, t90;  ///< of b_avg's change towards final_b [s]
};

/// One recorded state (for field output).
struct TransientState {
  double time = 0.0;       ///< [s]
  double current = 0.0;    ///< first circuit [A]
  Eigen::VectorXd a;       ///< nodal A [Wb/m]
  Eigen::VectorXd a_rate;  ///< nodal dA/dt over the last step [Wb/(m s)] (0 at t = 0)
};

/// Everything a step-response run produces. Arrays share the time axis; for a current step the
/// first two entries are t = 0 before and after the instantaneous jump.
struct TransientResult {
  std::vector<double> time;          ///< [s]
  std::vector<double> current;       ///< first circuit [A]
  std::vector<double> flux_linkage;  ///< first circuit [Wb]
  std::vector<double> eddy_power;    ///< eddy-current loss rate over the step ending there [W]
  std::vector<GapSeries> gaps;
  double final_current = 0.0;       ///< steady state after the step [A] (V / R for a voltage)
  double final_flux_linkage = 0.0;  ///< static lambda at final_current [Wb]
  std::optional<double> t63, t90;   ///< of lambda's change towards final_flux_linkage [s]
  EnergyBalance energy;
  int steps = 0;              ///< accepted time steps
  int rejected_steps = 0;     ///< steps repeated with a smaller step (adaptive)
  int newton_iterations = 0;  ///< in all steps (static solves excluded)
  int factorizations = 0;     ///< CHOLMOD numeric factorisations of the step matrices
  int dofs = 0;
  double seconds = 0.0;  ///< wall time of the run (static solves included)
  /// Largest local error of lambda per accepted step relative to its whole change, estimated
  /// as the adaptive control does (the polynomial through the previous steps); for equal steps
  /// whose estimate exceeds kStepCheckTrigger, the error measured against half steps instead.
  double step_error = 0.0;
  bool step_error_measured = false;  ///< step_error is the half-step measurement
  /// The run ended before `duration` at TransientOptions::stop_at_gap_fraction.
  bool stopped_early = false;
};

/// Receives every accepted state (e.g. a field writer); may be empty.
using StateCallback = std::function<void(const TransientState&)>;

/// The transient solver on a solved static problem's mesh: reuses its dof map, element
/// assembly, circuit sources and Newton iteration, and factorises the step matrix
/// M / h + sum_g w_g s_g K_t(A_g) (+ kappa curl-curl / h) with CHOLMOD (symbolic analysis once,
/// at the first run).
/// A voltage drive adds the circuit unknown; its row is eliminated by a Schur complement on the
/// single current, so only the symmetric positive definite field block is factorised.
class TransientSolver {
 public:
  /// `statics` provides the problem, mesh, assembly and the steady states; `eddy` the
  /// per-region coefficients (eddy_coefficients). InputError for a problem without circuit.
  TransientSolver(magnetostatics::MagnetostaticSolver& statics, EddyCoefficients eddy);
  TransientSolver(const TransientSolver&) = delete;
  TransientSolver& operator=(const TransientSolver&) = delete;

  /// Steady state at `options.from_current`, then the step response over `options.duration`.
  /// InputError for a duration <= 0, a non-finite value, a voltage drive without resistance > 0
  /// or bad step settings; ConvergenceError naming the time when a step does not converge even
  /// at the smallest step.
  TransientResult run(const TransientOptions& options, const StateCallback& on_state = {});

  const magnetostatics::MagnetostaticSolver& statics() const { return statics_; }
  magnetostatics::MagnetostaticSolver& statics() { return statics_; }
  /// The eddy currents' matrix D over the free dofs (lower triangle; see eddy_matrix).
  const magnetostatics::SparseMatrix& damping() const { return damping_; }
  const EddyCoefficients& eddy() const { return eddy_; }

 private:
  /// The error of a run of equal steps (`coarse`, run with `options`): the largest difference
  /// of lambda from a run of half the step at the coarse times, Richardson-scaled, relative to
  /// lambda's change.
  double half_step_error(const TransientOptions& options, const TransientResult& coarse);

  /// CHOLMOD's symbolic analysis of the step matrix, once, at the first run (a solver that only
  /// lends its operators, as to quasi_static_table, never factorises a step matrix).
  void analyse_step_pattern();

  class Step;
  friend class Step;

  magnetostatics::MagnetostaticSolver& statics_;
  EddyCoefficients eddy_;
  magnetostatics::SparseMatrix damping_;  // eddy_matrix: sigma mass + kappa micro-eddy term
  Eigen::VectorXd drive_source_;          // first circuit's unit-current source, free dofs
  Eigen::VectorXd other_source_;          // other circuits at their problem currents, free dofs
  std::vector<char> conducting_;          // free dof has a mass or micro-eddy row
  LinearPart linear_;                     // linear materials' residual and tangent, assembled once
  Eigen::CholmodSupernodalLLT<magnetostatics::SparseMatrix, Eigen::Lower> cholesky_;
  bool analysed_ = false;  // cholesky_ holds the step matrix's symbolic analysis
};

/// Time at which `values` first reaches `start + fraction (end - start)` (linear interpolation
/// between samples), or nothing when it does not within the series.
std::optional<double> rise_time(const std::vector<double>& time, const std::vector<double>& values,
                                double start, double end, double fraction);

}  // namespace rheomag::transient
