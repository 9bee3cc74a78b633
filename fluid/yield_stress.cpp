// Yield-stress models. References:
//  - PCHIP: F. N. Fritsch, R. E. Carlson, "Monotone piecewise cubic interpolation", SIAM J. Numer.
//    Anal. 17 (1980) 238-246 (Boost's pchip uses the Fritsch-Butland harmonic-mean slopes).
//  - MRF-132DG polynomial: the fit of LORD's published tau_y(B) curve used by Nguyen & Choi and
//    many MR-valve design papers; it has a maximum near 1.16 T and is clamped there.
//  - Carlson model: J. D. Carlson, "MR fluids and devices in the real world", Int. J. Mod.
//    Phys. B 19 (2005) 1463-1470 (tau_y(phi, H) and B(phi, H) fits for carbonyl-iron fluids).

#include "fluid/yield_stress.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
// Boost 1.74's pchip.hpp calls isnan unqualified in a template; make std::isnan visible there.
using std::isnan;
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <string>
#include <unsupported/Eigen/Polynomials>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::fluid {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

YieldStressTable::YieldStressTable(std::vector<double> b, std::vector<double> tau)
    : b_(std::move(b)), tau_(std::move(tau)) {
  if (b_.size() != tau_.size())
    throw InputError("yield-stress table: " + std::to_string(b_.size()) + " B values but " +
                     std::to_string(tau_.size()) + " tau values; expected equal lengths");
  if (b_.size() < 2)
    throw InputError("yield-stress table: needs at least 2 (B, tau) points, got " +
                     std::to_string(b_.size()));
  for (std::size_t i = 0; i < b_.size(); ++i) {
    if (!std::isfinite(b_[i]) || !std::isfinite(tau_[i]) || b_[i] < 0.0 || tau_[i] < 0.0)
      throw InputError("yield-stress table: point " + std::to_string(i) + " (B=" + num(b_[i]) +
                       " T, tau=" + num(tau_[i]) + " Pa) must be finite and >= 0");
    if (i > 0 && !(b_[i] > b_[i - 1]))
      throw InputError("yield-stress table: B must be strictly increasing, but B[" +
                       std::to_string(i) + "]=" + num(b_[i]) + " T <= B[" + std::to_string(i - 1) +
                       "]=" + num(b_[i - 1]) + " T");
    if (i > 0 && tau_[i] < tau_[i - 1])
      throw InputError("yield-stress table: tau must not decrease with B (monotone), but tau[" +
                       std::to_string(i) + "]=" + num(tau_[i]) + " Pa < tau[" +
                       std::to_string(i - 1) + "]=" + num(tau_[i - 1]) + " Pa");
  }
  if (b_.size() >= 4) {
    auto spline = std::make_shared<boost::math::interpolators::pchip<std::vector<double>>>(
        std::vector<double>(b_), std::vector<double>(tau_));
    interpolant_ = std::make_shared<const std::function<double(double)>>(
        [spline](double x) { return (*spline)(x); });
  } else {
    // Boost's PCHIP needs 4 points; with 2-3 points linear interpolation is the monotone choice.
    interpolant_ =
        std::make_shared<const std::function<double(double)>>([b = b_, tau = tau_](double x) {
          auto it = std::upper_bound(b.begin(), b.end(), x);
          std::size_t i = std::clamp<std::size_t>(it - b.begin(), 1, b.size() - 1);
          double w = (x - b[i - 1]) / (b[i] - b[i - 1]);
          return tau[i - 1] + w * (tau[i] - tau[i - 1]);
        });
  }
}

double YieldStressTable::operator()(double b) const {
  double x = std::abs(b);
  if (x <= b_.front()) return tau_.front();
  if (x >= b_.back()) return tau_.back();
  return (*interpolant_)(x);
}

YieldStressPolynomial::YieldStressPolynomial(std::vector<double> coefficients, double b_limit)
    : coefficients_(std::move(coefficients)) {
  while (coefficients_.size() > 1 && coefficients_.back() == 0.0) coefficients_.pop_back();
  if (coefficients_.empty())
    throw InputError("yield-stress polynomial: expected at least one coefficient");
  for (double c : coefficients_)
    if (!std::isfinite(c)) throw InputError("yield-stress polynomial: coefficients must be finite");
  if (!(b_limit > 0.0))
    throw InputError("yield-stress polynomial: validity limit b_max must be > 0 T, got " +
                     num(b_limit));
  if (coefficients_[0] < 0.0)
    throw InputError("yield-stress polynomial: tau_y(0) = " + num(coefficients_[0]) +
                     " Pa is negative");
  clamp_b_ = b_limit;
  const std::size_t degree = coefficients_.size() - 1;
  if (degree >= 2) {
    // Critical points: real positive roots of the derivative p'(B) = sum k c_k B^(k-1).
    Eigen::VectorXd derivative(degree);
    for (std::size_t k = 1; k <= degree; ++k) derivative[k - 1] = double(k) * coefficients_[k];
    Eigen::PolynomialSolver<double, Eigen::Dynamic> solver;
    solver.compute(derivative);
    std::vector<double> critical;
    for (const auto& root : solver.roots())
      if (std::abs(root.imag()) <= 1e-10 * std::max(1.0, std::abs(root.real())) &&
          root.real() > 0.0)
        critical.push_back(root.real());
    std::sort(critical.begin(), critical.end());
    // The first critical point where p' changes sign from + to - is the maximum to clamp at.
    for (double r : critical) {
      const double h = 1e-6 * std::max(r, 1e-3);
      auto slope = [&](double x) { return Eigen::poly_eval(derivative, x); };
      if (slope(r - h) > 0.0 && slope(r + h) < 0.0) {
        clamp_b_ = std::min(clamp_b_, r);
        break;
      }
    }
  }
  if (coefficients_.size() >= 2 && coefficients_[1] < 0.0)
    throw InputError("yield-stress polynomial: decreases at B = 0 (linear coefficient " +
                     num(coefficients_[1]) + " Pa/T < 0); expected a non-decreasing fit");
}

double YieldStressPolynomial::evaluate(double b) const {
  double value = 0.0;
  for (auto it = coefficients_.rbegin(); it != coefficients_.rend(); ++it) value = value * b + *it;
  return value;
}

double YieldStressPolynomial::operator()(double b) const {
  return evaluate(std::min(std::abs(b), clamp_b_));
}

YieldStressPolynomial YieldStressPolynomial::mrf132dg() {
  // kPa coefficients with B in T, converted to Pa.
  return YieldStressPolynomial({0.1442e3, 13.708e3, 158.79e3, -176.51e3, 52.962e3});
}

CarlsonYieldStress::CarlsonYieldStress(double volume_fraction, double carrier_factor)
    : phi_(volume_fraction), c_(carrier_factor) {
  if (!(phi_ > 0.0 && phi_ <= 0.6))
    throw InputError("Carlson yield stress: volume_fraction must be in (0, 0.6], got " + num(phi_));
  if (!(c_ > 0.0))
    throw InputError("Carlson yield stress: carrier_factor must be > 0, got " + num(c_));
}

double CarlsonYieldStress::of_field_strength(double h) const {
  return 271700.0 * c_ * std::pow(phi_, 1.5239) * std::tanh(6.33e-6 * std::abs(h));
}

double CarlsonYieldStress::flux_density(double h) const {
  const double ha = std::abs(h);
  return 1.91 * std::pow(phi_, 1.133) * (-std::expm1(-10.97 * kMu0 * ha)) + kMu0 * ha;
}

double CarlsonYieldStress::field_strength(double b) const {
  const double target = std::abs(b);
  if (target == 0.0) return 0.0;
  // B(H) is strictly increasing with B >= mu0 H, so the root lies in [0, |b|/mu0].
  auto residual = [&](double h) { return flux_density(h) - target; };
  boost::uintmax_t iterations = 200;
  auto [lo, hi] = boost::math::tools::toms748_solve(
      residual, 0.0, target / kMu0, boost::math::tools::eps_tolerance<double>(50), iterations);
  if (iterations >= 200)
    throw ConvergenceError("Carlson H(B) inversion did not converge at B = " + num(target) + " T");
  return 0.5 * (lo + hi);
}

YieldStressCurve::YieldStressCurve(Model model, double scale)
    : model_(std::move(model)), scale_(scale) {
  if (!(scale_ > 0.0 && std::isfinite(scale_)))
    throw InputError("yield-stress scale must be a finite number > 0, got " + num(scale_));
}

double YieldStressCurve::operator()(double b) const {
  return scale_ * std::visit([b](const auto& m) { return m(b); }, model_);
}

}  // namespace rheomag::fluid
