// Two-stage SDIRK of order 2 (gamma = 1 - 1/sqrt(2): L-stable and stiffly accurate) with Newton
// stages on scaled states and a finite-difference Jacobian shared by both stages of a step.

#include "lumped/ode_grid.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::lumped {

namespace {

constexpr double kGamma = 1.0 - 0.70710678118654752440;
constexpr double kNewtonTolerance = 1e-10;  // on scaled states (typical magnitude 1)
constexpr int kNewtonIterations = 25;
constexpr int kMaxHalvings = 12;

/// Largest state count whose vectors and Newton matrix live on the stack (every rig of the
/// diagnosis has fewer states): the stages' temporaries then cost no heap allocation, which was a
/// fifth of the time of a diagnosis on the whole dyke1996 record. Larger systems use the heap.
constexpr int kStackStates = 12;

/// x' = f(t, x) in scaled states xi = x / scale, with its Newton stage solver; MaxN bounds the
/// state count at compile time (Eigen::Dynamic: unbounded, on the heap).
template <int MaxN>
class ScaledStepper {
 public:
  using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, MaxN, 1>;
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, MaxN, MaxN>;

  explicit ScaledStepper(const OdeSystem& sys) : sys_(sys), n_(sys.state_size()) {
    scale_ = Vec::Ones(static_cast<Eigen::Index>(n_));
    const auto s = sys.state_scales();
    for (std::size_t k = 0; k < n_; ++k)
      if (s[k] > 0.0 && std::isfinite(s[k])) scale_[static_cast<Eigen::Index>(k)] = s[k];
    x_.resize(n_);
    dx_.resize(n_);
  }

  const Vec& scale() const { return scale_; }

  /// f in scaled states.
  Vec rate(double t, const Vec& xi) const {
    for (std::size_t k = 0; k < n_; ++k) x_[k] = xi[static_cast<Eigen::Index>(k)] * scale_[k];
    sys_.derivatives(t, x_.data(), dx_.data());
    Vec out(static_cast<Eigen::Index>(n_));
    for (std::size_t k = 0; k < n_; ++k) out[static_cast<Eigen::Index>(k)] = dx_[k] / scale_[k];
    return out;
  }

  /// Factorises I - hg J with J the forward-difference Jacobian at (t, xi), f(t, xi) = f0.
  void factorise(double t, const Vec& xi, const Vec& f0, double hg) {
    const auto n = static_cast<Eigen::Index>(n_);
    Mat m(n, n);
    Vec xp = xi;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double d = 1e-7 * std::max(1.0, std::abs(xi[j]));
      xp[j] = xi[j] + d;
      m.col(j) = -hg * (rate(t, xp) - f0) / d;
      xp[j] = xi[j];
    }
    m.diagonal().array() += 1.0;
    lu_.compute(m);
  }

  /// Solves Y = base + hg f(t, Y) from the guess Y (Newton; the matrix is refreshed at the
  /// iterate when the iteration contracts slowly). Returns false if it does not converge.
  bool solve_stage(double t, const Vec& base, double hg, Vec& y) {
    double previous = 0.0;
    for (int it = 0; it < kNewtonIterations; ++it) {
      const Vec f = rate(t, y);
      if (!f.allFinite()) return false;
      if (!fresh_) {
        factorise(t, y, f, hg);
        fresh_ = true;
      }
      const Vec g = y - base - hg * f;
      const Vec delta = lu_.solve(-g);
      if (!delta.allFinite()) return false;
      y += delta;
      const double size = delta.template lpNorm<Eigen::Infinity>();
      if (size <= kNewtonTolerance * std::max(1.0, y.template lpNorm<Eigen::Infinity>()))
        return true;
      if (it > 0 && size > 0.3 * previous) fresh_ = false;  // slow: new Jacobian at the iterate
      previous = size;
    }
    return false;
  }

  /// One SDIRK2 step of length h from (t, xi); false if a stage's Newton iteration fails. The
  /// last stage is evaluated a hair before t + h so that an input that is piecewise linear
  /// between samples is read on this step's segment (its slope, not the next one's).
  bool step(double t, double h, Vec& xi) {
    const double hg = kGamma * h;
    const double end = t + h * (1.0 - 1e-9);
    fresh_ = false;  // one Jacobian per step, refreshed only when Newton stalls
    Vec y1 = xi;
    if (!solve_stage(t + kGamma * h, xi, hg, y1)) return false;
    const Vec k1 = (y1 - xi) / hg;
    const Vec base2 = xi + (1.0 - kGamma) * h * k1;
    Vec y2 = xi + h * k1;
    if (!solve_stage(end, base2, hg, y2)) return false;
    xi = y2;
    return true;
  }

  /// Advances xi from t to t + h, splitting the step in halves where Newton fails.
  void advance(double t, double h, Vec& xi, int depth = 0) {
    Vec trial = xi;
    if (step(t, h, trial)) {
      xi = trial;
      return;
    }
    if (depth == kMaxHalvings)
      throw ConvergenceError("grid integrator: Newton failed for a step of " + std::to_string(h) +
                             " s at t = " + std::to_string(t) + " s");
    advance(t, 0.5 * h, xi, depth + 1);
    advance(t + 0.5 * h, 0.5 * h, xi, depth + 1);
  }

 private:
  const OdeSystem& sys_;
  std::size_t n_;
  Vec scale_;
  mutable std::vector<double> x_, dx_;
  Eigen::PartialPivLU<Mat> lu_;
  bool fresh_ = false;
};

}  // namespace

std::vector<std::vector<double>> integrate_on_grid(const OdeSystem& system, std::vector<double> x0,
                                                   const std::vector<double>& times, int substeps) {
  const std::vector<int> each(times.empty() ? 0 : times.size() - 1, std::max(substeps, 1));
  return integrate_on_grid(system, std::move(x0), times, each);
}

namespace {

/// integrate_on_grid with the stepper of state bound MaxN.
template <int MaxN>
std::vector<std::vector<double>> integrate_with(const OdeSystem& system,
                                                const std::vector<double>& x0,
                                                const std::vector<double>& times,
                                                const std::vector<int>& substeps) {
  using Stepper = ScaledStepper<MaxN>;
  const std::size_t n = system.state_size();
  std::vector<std::vector<double>> out;
  out.reserve(times.size());
  Stepper stepper(system);
  const typename Stepper::Vec& scale = stepper.scale();
  typename Stepper::Vec xi(static_cast<Eigen::Index>(n));
  for (std::size_t k = 0; k < n; ++k) xi[static_cast<Eigen::Index>(k)] = x0.at(k) / scale[k];
  auto record = [&](double t) {
    std::vector<double> x(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = xi[static_cast<Eigen::Index>(k)] * scale[k];
      if (!std::isfinite(x[k]))
        throw ConvergenceError("grid integrator: state " + std::to_string(k) +
                               " is not finite at t = " + std::to_string(t) + " s");
    }
    out.push_back(std::move(x));
  };
  record(times.front());
  for (std::size_t i = 1; i < times.size(); ++i) {
    const int m = std::max(substeps[i - 1], 1);
    const double h = (times[i] - times[i - 1]) / m;
    for (int s = 0; s < m; ++s) stepper.advance(times[i - 1] + s * h, h, xi);
    record(times[i]);
  }
  return out;
}

}  // namespace

std::vector<std::vector<double>> integrate_on_grid(const OdeSystem& system, std::vector<double> x0,
                                                   const std::vector<double>& times,
                                                   const std::vector<int>& substeps) {
  const std::size_t n = system.state_size();
  if (times.empty() || n == 0) return std::vector<std::vector<double>>(times.size());
  if (substeps.size() + 1 != times.size())
    throw InputError("grid integrator: " + std::to_string(substeps.size()) +
                     " substep counts for " + std::to_string(times.size() - 1) + " intervals");
  if (n <= static_cast<std::size_t>(kStackStates))
    return integrate_with<kStackStates>(system, x0, times, substeps);
  return integrate_with<Eigen::Dynamic>(system, x0, times, substeps);
}

}  // namespace rheomag::lumped
