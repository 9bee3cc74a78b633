#pragma once
// Smooth (C-infinity) replacements of sign, |.|, max(.,0) used wherever a sign or plug switch would
// make the right-hand side non-differentiable. Each takes a regularisation width `eps` in the
// units of its argument; as eps -> 0 each converges to the exact switch (error O(eps)).
// Templated so Ceres Jets pass through unchanged.

#include <cmath>

namespace rheomag::lumped {

/// The value of a double (itself) or of a Ceres Jet (its scalar part), for decisions that must not
/// be differentiated (table segments, step counts).
inline double value_of(double x) {
  return x;
}
template <class J>
double value_of(const J& x) {
  return x.a;
}

/// x^g for x > 0: std::pow for doubles.
inline double positive_power(double x, double g) {
  return std::pow(x, g);
}
/// x^g for x > 0 on Ceres Jets: the value of std::pow, and its derivative g x^g / x dx +
/// x^g log(x) dg from that one power (Ceres' pow computes a second, x^(g - 1); the fits' time went
/// to these powers).
template <class J>
J positive_power(const J& x, const J& g) {
  J result;
  result.a = std::pow(x.a, g.a);
  result.v = (result.a * g.a / x.a) * x.v + (result.a * std::log(x.a)) * g.v;
  return result;
}

/// sign(x) regularised: tanh(x / eps).
template <class T>
T smooth_sign(const T& x, double eps) {
  using std::tanh;
  return tanh(x / eps);
}

/// |x| regularised: sqrt(x^2 + eps^2) - eps (exact at 0, error <= eps).
template <class T>
T smooth_abs(const T& x, double eps) {
  using std::sqrt;
  return sqrt(x * x + eps * eps) - eps;
}

/// max(x, 0) regularised: (x + sqrt(x^2 + eps^2)) / 2 (error <= eps / 2).
template <class T>
T smooth_ramp(const T& x, double eps) {
  using std::sqrt;
  return 0.5 * (x + sqrt(x * x + eps * eps));
}

/// sign(x)|x|^alpha regularised: x (x^2 + eps^2)^((alpha - 1) / 2) (finite slope at 0).
template <class T, class A>
T smooth_signed_power(const T& x, const A& alpha, double eps) {
  using std::pow;
  return x * pow(x * x + eps * eps, (alpha - 1.0) * 0.5);
}

}  // namespace rheomag::lumped
