#include "transient/transient_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "magnetostatics/cholmod_status.hpp"
#include "magnetostatics/serial_openmp.hpp"
#include "transient/gap_flux.hpp"
#include "transient/step_system.hpp"

namespace rheomag::transient {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The most equal time steps a run takes (adaptive runs need a few hundred).
constexpr int kMaxEqualSteps = 1'000'000;

void check_options(const TransientOptions& o, const std::string& where) {
  auto fail = [&](const std::string& what) { throw InputError(where + ": " + what); };
  if (!(o.duration > 0.0) || !std::isfinite(o.duration))
    fail("duration must be a finite time > 0 s");
  if (!std::isfinite(o.value) || !std::isfinite(o.from_current))
    fail("the step's current or voltage and the initial current must be finite");
  if (o.drive == Drive::voltage && !(o.resistance > 0.0 && std::isfinite(o.resistance)))
    fail("a voltage step needs the coil resistance > 0 Ohm (a wire in the case, or a resistance)");
  if (!(o.resistance >= 0.0) || !std::isfinite(o.resistance)) fail("resistance must be >= 0 Ohm");
  // Each step is a nonlinear solve and a stored state: 2e9 equal steps ran for hours.
  if (o.steps < 0 || o.steps > kMaxEqualSteps)
    fail("steps must be in [0, " + std::to_string(kMaxEqualSteps) + "] (0: adaptive), got " +
         std::to_string(o.steps));
  // A current step to the current it starts from has no response to follow: the run divided by
  // the zero change and reported a residual of -nan (exit 3).
  if (o.drive == Drive::current && o.value == o.from_current)
    fail("the current step goes from " + std::to_string(o.from_current) + " A to the same " +
         "current; expected a different --current or --from");
  if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance)) fail("tolerance must be > 0");
  if (!(o.max_step >= 0.0) || !(o.first_step >= 0.0)) fail("step limits must be >= 0 s");
  if (!(o.stop_at_gap_fraction >= 0.0 && o.stop_at_gap_fraction <= 1.0))
    fail("the gaps' fraction to stop at must be in [0, 1] (0: the whole duration)");
}

/// Whether `values` has reached `fraction` of its change from `start` to `end` (as rise_time).
bool has_risen(const std::vector<double>& values, double start, double end, double fraction) {
  if (end == start || values.empty()) return false;
  const double target = start + fraction * (end - start);
  return (end > start ? 1.0 : -1.0) * (values.back() - target) >= 0.0;
}

/// (s, w) points of the scheme on the step [0, 1].
std::vector<std::pair<double, double>> scheme_points(TimeScheme scheme, bool linear) {
  if (scheme == TimeScheme::backward_euler) return {{1.0, 1.0}};
  if (linear) return {{0.5, 1.0}};  // the midpoint rule integrates R(A(s)) . dA exactly here
  // 2-point Gauss-Legendre on [0, 1]: exact for R(A(s)) . dA cubic in s; its error on a B-H
  // curve is the reported numerical dissipation (docs/transient.md: 2e-7 of the energy per step
  // on the annular valve, vanishing with the step at order 3), and each point is a B-H assembly.
  const double d = 0.5 / std::sqrt(3.0);
  return {{0.5 - d, 0.5}, {0.5 + d, 0.5}};
}

/// Value at `t` of the polynomial through the last `count` samples (t_k, v_k).
double extrapolate(const std::vector<double>& t, const std::vector<double>& v, int count,
                   double at) {
  const int n = static_cast<int>(t.size());
  double sum = 0.0;
  for (int j = n - count; j < n; ++j) {
    double l = 1.0;
    for (int m = n - count; m < n; ++m)
      if (m != j) l *= (at - t[m]) / (t[j] - t[m]);
    sum += l * v[j];
  }
  return sum;
}

/// InputError when the coil's L/R (`inductance` [H]) is below 1e-9 of the duration: the
/// adaptive steps stop at 1e-10 of it, so such a run takes billions of steps.
void check_time_constant(const TransientOptions& options, double inductance) {
  const double tau = inductance / options.resistance, floor = 1e-9 * options.duration;
  if (inductance > 0.0 && tau < floor) {
    throw InputError(format_text(
        "resistance %.6g Ohm: the coil's L/R would be %.3g s (L %.3g H), less than 1e-9 of the "
        "duration %.3g s, so the current settles within the smallest time step; expected a "
        "resistance up to %.3g Ohm (or a shorter --duration)",
        options.resistance, tau, inductance, options.duration, inductance / floor));
  }
}

}  // namespace

std::optional<double> rise_time(const std::vector<double>& time, const std::vector<double>& values,
                                double start, double end, double fraction) {
  if (end == start || time.size() != values.size()) return std::nullopt;
  const double target = start + fraction * (end - start);
  const double sign = end > start ? 1.0 : -1.0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (sign * (values[k] - target) < 0.0) continue;
    if (k == 0 || values[k] == values[k - 1]) return time[k];
    return time[k - 1] +
           (target - values[k - 1]) / (values[k] - values[k - 1]) * (time[k] - time[k - 1]);
  }
  return std::nullopt;
}

TransientSolver::TransientSolver(magnetostatics::MagnetostaticSolver& statics,
                                 EddyCoefficients eddy)
    : statics_(statics), eddy_(std::move(eddy)) {
  const cases::Problem& problem = statics_.problem();
  if (problem.circuits.empty())
    throw InputError(problem.geometry.source + ": the case has no circuit to drive");
  if (eddy_.sigma.size() != problem.regions.size() || eddy_.kappa.size() != problem.regions.size())
    throw InputError(problem.geometry.source + ": eddy coefficients for " +
                     std::to_string(eddy_.sigma.size()) + " regions, the problem has " +
                     std::to_string(problem.regions.size()));
  if (statics_.dofs().constrained())
    throw InputError(problem.geometry.source +
                     ": periodic or antiperiodic boundaries are not supported by the transient "
                     "solver (magnetostatic solves only)");
  const auto& assembler = statics_.assembler();
  damping_ = eddy_matrix(assembler, eddy_.sigma, eddy_.kappa);
  linear_ = linear_part(statics_);
  drive_source_ = statics_.nodes_to_free(statics_.circuit_source(0));
  other_source_ = Eigen::VectorXd::Zero(drive_source_.size());
  for (std::size_t c = 1; c < problem.circuits.size(); ++c)
    other_source_ += problem.circuits[c].current *
                     statics_.nodes_to_free(statics_.circuit_source(static_cast<int>(c)));
  const mesh::Mesh& m = statics_.mesh();
  const magnetostatics::DofMap& dofs = statics_.dofs();
  conducting_.assign(dofs.free_count(), 0);
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    const int region = m.region[e];
    if (eddy_.sigma[region] == 0.0 && eddy_.kappa[region] == 0.0) continue;
    for (int i = 0; i < m.nodes_per_triangle(); ++i) {
      const int d = dofs.dof_of_node[m.triangles[e][i]];
      if (d >= 0) conducting_[d] = 1;
    }
  }
}

void TransientSolver::analyse_step_pattern() {
  if (analysed_ || statics_.dofs().free_count() == 0) return;
  const magnetostatics::SerialOpenMp serial;
  cholesky_.analyzePattern(statics_.assembler().pattern());
  magnetostatics::throw_if_out_of_memory(cholesky_);
  if (cholesky_.info() != Eigen::Success)
    throw ConvergenceError("CHOLMOD symbolic analysis of the time-step matrix failed");
  analysed_ = true;
}

TransientResult TransientSolver::run(const TransientOptions& options,
                                     const StateCallback& on_state) {
  const auto start = Clock::now();
  const cases::Problem& problem = statics_.problem();
  check_options(options, problem.geometry.source);
  const auto& assembler = statics_.assembler();
  const bool voltage = options.drive == Drive::voltage;
  const bool adaptive = options.steps == 0;
  const int n = statics_.dofs().free_count();
  const double duration = options.duration;

  // Steady states before and long after the step.
  std::vector<double> currents;
  for (const cases::Circuit& c : problem.circuits) currents.push_back(c.current);
  currents[0] = options.from_current;
  const magnetostatics::Solution before = statics_.solve(currents);
  TransientResult result;
  result.dofs = n;
  result.final_current = voltage ? options.value / options.resistance : options.value;
  currents[0] = result.final_current;
  const magnetostatics::Solution after = statics_.solve(currents, &before.a);
  result.final_flux_linkage = after.flux_linkage[0];
  if (voltage) {  // secant L of the step; at 1 A when the step is too small to give one
    const double di = result.final_current - options.from_current;
    double inductance = std::abs((result.final_flux_linkage - before.flux_linkage[0]) / di);
    if (!(inductance > 0.0) || !std::isfinite(inductance)) {
      std::vector<double> unit = currents;
      unit[0] = 1.0;
      inductance = std::abs(statics_.solve(unit).flux_linkage[0] - before.flux_linkage[0]);
    }
    check_time_constant(options, inductance);
  }

  const std::vector<int> gap_ids = gap_regions(statics_);
  const std::vector<double> final_b = region_mean_b(statics_, gap_ids, after.a);
  for (std::size_t g = 0; g < gap_ids.size(); ++g)
    result.gaps.push_back(
        {problem.geometry.regions[gap_ids[g]].name, gap_ids[g], {}, final_b[g], {}, {}});
  Eigen::VectorXd x = statics_.nodes_to_free(before.a);
  double current = options.from_current;
  double w_now = assembler.energy(before.a);
  auto flux_linkage = [&](const Eigen::VectorXd& a) { return statics_.circuit_source(0).dot(a); };
  auto record = [&](double t, const Eigen::VectorXd& a, const Eigen::VectorXd& rate,
                    double eddy_power) {
    result.time.push_back(t);
    result.current.push_back(current);
    result.flux_linkage.push_back(flux_linkage(a));
    result.eddy_power.push_back(eddy_power);
    const std::vector<double> b = region_mean_b(statics_, gap_ids, a);
    for (std::size_t g = 0; g < b.size(); ++g) result.gaps[g].b_avg.push_back(b[g]);
    if (on_state) on_state({t, current, a, rate});
  };
  record(0.0, before.a, Eigen::VectorXd::Zero(before.a.size()), 0.0);

  analyse_step_pattern();
  StepOperators::Factor factor;
  StepOperators ops{&statics_,    &damping_, &drive_source_, &other_source_,
                    &conducting_, &linear_,  &cholesky_,     &factor};
  // Reference of Newton's relative residual: the drive's own size (a floor in amperes would
  // call a tiny drive converged before its first iteration and print zeros).
  const double reference_current =
      std::max(std::abs(options.from_current), std::abs(result.final_current));
  const double scale =
      std::max(drive_source_.norm() * reference_current + other_source_.norm(), 1e-300);
  magnetostatics::NewtonOptions newton = options.newton;
  newton.local_iterations = 0;

  // A current step: the non-conducting part of the field follows at once.
  if (!voltage) {
    StepSystem jump(ops, {x, current, 0.0, false, options.value, options.resistance, true, {}});
    Eigen::VectorXd y = x;
    try {
      result.newton_iterations += magnetostatics::newton_solve(jump, y, scale, newton).iterations;
    } catch (const ConvergenceError& e) {
      throw ConvergenceError("the instantaneous response at t = 0 s did not converge: " +
                             std::string(e.what()));
    }
    result.factorizations += jump.factorizations();
    x = y;
    current = options.value;
    const Eigen::VectorXd a = statics_.free_to_nodes(x);
    const double w = assembler.energy(a);
    result.energy.step_energy = w - w_now;
    w_now = w;
    record(0.0, a, Eigen::VectorXd::Zero(a.size()), 0.0);
  }

  const auto points = scheme_points(options.scheme, !assembler.nonlinear());
  const int order = options.scheme == TimeScheme::midpoint ? 2 : 1;
  const double max_step = options.max_step > 0.0 ? options.max_step : duration / 50.0;
  // After a current step the field enters the conductors from their surfaces as sqrt(t). The
  // first two steps run before the error estimate has its three points, and the midpoint rule
  // does not damp what they get wrong, so after a current step they are short (docs/transient.md,
  // "The first steps").
  const double first_step = options.first_step > 0.0 ? options.first_step
                            : voltage                ? duration * 1e-4
                                                     : duration * 1e-6;
  double h = adaptive ? std::min(first_step, max_step) : duration / options.steps;
  const double min_step = duration * 1e-10;
  const double lambda_change =
      std::max(std::abs(result.final_flux_linkage - result.flux_linkage.front()),
               1e-12 * std::abs(result.final_flux_linkage) + 1e-300);
  // History since t = 0+ for the error estimate and the predictor.
  std::vector<double> hist_t{0.0}, hist_lambda{result.flux_linkage.back()};
  // The last accepted states (newest last) and their times, for the Newton predictor.
  std::vector<Eigen::VectorXd> x_history;
  std::vector<double> t_history;
  bool extrapolated_last = true;   // the last step started from the extrapolation
  int keep_choice = 0;             // steps left that take the last choice without trying both
  double worst_imbalance = 0.0;    // largest |source - field work - losses| of a step [J]
  double worst_dissipation = 0.0;  // largest |field work - dW| of a step [J]
  std::vector<char> gap_risen(result.gaps.size(), 0);  // for stop_at_gap_fraction
  double t = 0.0;
  while (t < duration * (1.0 - 1e-12)) {
    h = std::min(h, duration - t);
    StepSystem step(ops,
                    {x, current, h, voltage, options.value, options.resistance, false, points});
    Eigen::VectorXd y(voltage ? n + 1 : n);
    y.head(n) = x;
    // Predictor: the polynomial through the last (up to 3) accepted states at t + h (quadratic
    // extrapolation saves about a Newton iteration per step on smooth responses).
    if (!t_history.empty()) {
      const int count = std::min<int>(static_cast<int>(t_history.size()) + 1, 3);
      std::vector<double> tt(t_history.end() - (count - 1), t_history.end());
      tt.push_back(t);
      y.head(n).setZero();
      for (int j = 0; j < count; ++j) {
        double l = 1.0;
        for (int m = 0; m < count; ++m)
          if (m != j) l *= (t + h - tt[m]) / (tt[j] - tt[m]);
        const Eigen::VectorXd& xj =
            j == count - 1 ? x : x_history[x_history.size() - (count - 1) + j];
        y.head(n) += l * xj;
      }
    }
    if (voltage) y[n] = current;
    // ... unless the last state itself has the smaller residual. Long midpoint steps leave the
    // conductors' stiff modes ringing (the rule is A- but not L-stable), and a polynomial through
    // ringing states can land further off than the last state: on a saturating valve under a
    // voltage step, 3-5 times its residual and 2-4 more Newton iterations per step
    // (docs/transient.md, "Where a step's Newton starts"). Both are tried, the last step's choice
    // second, so that the residual Newton starts with is usually the one just assembled. A choice
    // that won by more than kClearWin is kept for the next kKeepSteps steps untried.
    if (options.choose_start && !t_history.empty()) {
      constexpr double kClearWin = 4.0;
      constexpr int kKeepSteps = 4;
      if (keep_choice > 0) {
        --keep_choice;
      } else {
        Eigen::VectorXd r, last = y;
        last.head(n) = x;
        const double r1 = step.residual(extrapolated_last ? last : y, r);
        const double r2 = step.residual(extrapolated_last ? y : last, r);
        const double r_last = extrapolated_last ? r1 : r2;
        const double r_extrapolated = extrapolated_last ? r2 : r1;
        extrapolated_last = r_extrapolated <= r_last;
        if (std::max(r_last, r_extrapolated) > kClearWin * std::min(r_last, r_extrapolated))
          keep_choice = kKeepSteps;
      }
      if (!extrapolated_last) y.head(n) = x;
    }
    magnetostatics::NewtonReport report;
    try {
      report = magnetostatics::newton_solve(step, y, scale, newton);
    } catch (const ConvergenceError& e) {
      result.factorizations += step.factorizations();
      if (adaptive && h > 4.0 * min_step) {
        h *= 0.25;
        ++result.rejected_steps;
        continue;
      }
      std::ostringstream msg;
      msg << "time step from t = " << t << " s to " << t + h << " s did not converge: " << e.what();
      throw ConvergenceError(msg.str());
    }
    result.newton_iterations += report.iterations;
    result.factorizations += step.factorizations();
    const Eigen::VectorXd a = statics_.free_to_nodes(y.head(n));
    const double lambda = flux_linkage(a);
    double growth = 2.0;
    const int count = static_cast<int>(hist_t.size());
    const double error =
        count >= order + 1
            ? std::abs(lambda - extrapolate(hist_t, hist_lambda, order + 1, t + h)) / lambda_change
            : 0.0;
    if (adaptive) {
      if (count >= order + 1) {
        growth = std::clamp(
            0.9 * std::pow(options.tolerance / std::max(error, 1e-300), 1.0 / (order + 1)), 0.25,
            2.0);
        if (error > options.tolerance && h > 4.0 * min_step) {
          h *= std::min(growth, 0.5);
          ++result.rejected_steps;
          continue;
        }
      } else {
        growth = 1.0;
      }
    }
    // Energy bookkeeping of the accepted step (exact for the midpoint scheme: docs/transient.md).
    const Eigen::VectorXd delta = y.head(n) - x;
    const double i_bar = step.mean_current(y);
    const double eddy = delta.dot(damping_.selfadjointView<Eigen::Lower>() * delta) / h;
    const double copper = options.resistance * i_bar * i_bar * h;
    const double other_work = other_source_.dot(delta);
    const double source = (voltage ? options.value * i_bar * h
                                   : i_bar * (lambda - result.flux_linkage.back()) + copper) +
                          other_work;
    const double field_work = step.field_work(y);
    const double w = assembler.energy(a);
    const double stored = w - w_now;
    worst_imbalance = std::max(worst_imbalance, std::abs(source - field_work - eddy - copper));
    worst_dissipation = std::max(worst_dissipation, std::abs(field_work - stored));
    result.energy.source += source;
    result.energy.field_work += field_work;
    result.energy.stored_change += stored;
    result.energy.eddy_loss += eddy;
    result.energy.copper_loss += copper;
    w_now = w;

    x_history.push_back(x);
    t_history.push_back(t);
    if (x_history.size() > 2) {
      x_history.erase(x_history.begin());
      t_history.erase(t_history.begin());
    }
    x = y.head(n);
    if (voltage) current = y[n];
    t += h;
    ++result.steps;
    Eigen::VectorXd rate = Eigen::VectorXd::Zero(a.size());
    for (int d = 0; d < n; ++d) rate[statics_.dofs().node_of_dof[d]] = delta[d] / h;
    record(t, a, rate, eddy / h);
    hist_t.push_back(t), hist_lambda.push_back(lambda);
    result.step_error = std::max(result.step_error, error);
    if (options.progress) {
      // Time left: the rate so far (simulated s per wall s); adaptive steps grow, so it errs
      // on the long side.
      const double elapsed = seconds_since(start), left = elapsed * (duration - t) / t;
      std::ostringstream detail;
      detail << "t = " << t << " s of " << duration << " s (" << std::lround(100.0 * t / duration)
             << " %), step " << h << " s, i = " << current << " A, Newton " << report.iterations
             << ", about " << std::setprecision(2) << left << " s left";
      options.progress({"transient", t, duration, elapsed, detail.str()});
    }
    if (options.stop_at_gap_fraction > 0.0) {  // each gap's first crossing, once seen, stays
      for (std::size_t g = 0; g < result.gaps.size(); ++g)
        gap_risen[g] =
            gap_risen[g] || has_risen(result.gaps[g].b_avg, result.gaps[g].b_avg.front(),
                                      result.gaps[g].final_b, options.stop_at_gap_fraction);
      if (!gap_risen.empty() &&
          std::all_of(gap_risen.begin(), gap_risen.end(), [](char r) { return r != 0; })) {
        result.stopped_early = t < duration * (1.0 - 1e-12);
        break;
      }
    }
    // Growth below 25 % keeps h, and with it the factorised step matrix (linear materials).
    if (growth > 1.0 && growth < 1.25) growth = 1.0;
    h = adaptive ? std::min(h * growth, max_step) : duration / options.steps;
  }

  EnergyBalance& e = result.energy;
  const double energy_scale =
      std::max({std::abs(e.source), std::abs(e.stored_change), e.eddy_loss + e.copper_loss});
  if (energy_scale > 0.0) {
    e.max_step_error = worst_imbalance / energy_scale;
    e.total_error = std::abs(e.source - e.field_work - e.eddy_loss - e.copper_loss) / energy_scale;
    e.max_step_dissipation = worst_dissipation / energy_scale;
  }
  e.numerical_dissipation = e.field_work - e.stored_change;
  const double lambda0 = result.flux_linkage.front();
  result.t63 = rise_time(result.time, result.flux_linkage, lambda0, result.final_flux_linkage,
                         1.0 - std::exp(-1.0));
  result.t90 = rise_time(result.time, result.flux_linkage, lambda0, result.final_flux_linkage, 0.9);
  for (GapSeries& g : result.gaps) {
    g.t63 = rise_time(result.time, g.b_avg, g.b_avg.front(), g.final_b, 1.0 - std::exp(-1.0));
    g.t90 = rise_time(result.time, g.b_avg, g.b_avg.front(), g.final_b, 0.9);
  }
  if (!adaptive && options.check_steps && result.step_error > kStepCheckTrigger) {
    result.step_error = half_step_error(options, result);
    result.step_error_measured = true;
  }
  result.seconds = seconds_since(start);
  return result;
}

double TransientSolver::half_step_error(const TransientOptions& options,
                                        const TransientResult& coarse) {
  TransientOptions half = options;
  half.steps = 2 * options.steps;
  half.check_steps = false;
  if (options.progress) {
    half.progress = [&](const ProgressEvent& e) {
      options.progress({"transient check", e.done, e.total, e.elapsed,
                        "checking the equal steps against half steps: " + e.detail});
    };
  }
  const TransientResult fine = run(half, {});
  // Both series start with the same t = 0 entries (two for a current step); then coarse step k
  // ends where fine step 2k does.
  const std::size_t head = coarse.time.size() - static_cast<std::size_t>(coarse.steps);
  const double change =
      std::max(std::abs(coarse.final_flux_linkage - coarse.flux_linkage.front()), 1e-300);
  double largest = 0.0;
  for (std::size_t k = head; k < coarse.time.size(); ++k) {
    const std::size_t j = head + 2 * (k - head + 1) - 1;
    if (j < fine.flux_linkage.size())
      largest = std::max(largest, std::abs(coarse.flux_linkage[k] - fine.flux_linkage[j]));
  }
  // Richardson: the coarse run's error is 2^p / (2^p - 1) of the difference (p = 2 midpoint).
  const double factor = options.scheme == TimeScheme::midpoint ? 4.0 / 3.0 : 2.0;
  return factor * largest / change;
}

}  // namespace rheomag::transient
