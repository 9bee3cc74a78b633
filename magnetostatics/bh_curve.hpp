#pragma once
// Monotone smooth B-H curve: H(B), reluctivity nu(|B|^2) = H/B, its derivative and the energy.

#include <string>
#include <utility>
#include <vector>

#include "case/problem.hpp"

namespace rheomag::magnetostatics {

/// Magnetisation curve H(B) of a soft magnetic material, built from a B-H table.
///
/// Interpolation: monotone piecewise cubic Hermite (Fritsch-Carlson / PCHIP weighted harmonic-mean
/// slopes) of H(B) through the table points. On the first interval [0, B1] the cubic is replaced
/// by the odd polynomial H = B (a + c B^2) matching H and dH/dB at B1, so that the reluctivity
/// nu = H/B = a + c B^2 is linear in B^2 near B = 0: nu(0) = a and d nu/d(B^2) = c are finite
/// (the B -> 0 limit is exact, no division by B). dH/dB > 0 everywhere (strictly monotone).
///
/// With BhInterpolation::femm_natural_spline (tables read from FEMM files) the slopes are those
/// of FEMM's natural cubic spline instead; its first interval has zero second derivative at B = 0,
/// so it is the same odd polynomial with a = dH/dB(0). A table whose spline turns back (dH/dB <= 0
/// somewhere: FEMM would have smoothed it first) keeps the monotone slopes.
///
/// Extrapolation beyond the last table point (B_n, H_n, end slope d_n), with x = B - B_n and
/// tau = B_n - B_{n-1} (the last table spacing):
///   H = H_n + x / mu0 + (d_n - 1/mu0) tau (1 - exp(-x / tau)),
/// i.e. the differential permeability dB/dH relaxes from the table's end value to mu0 within a
/// few tau (full saturation: M = B/mu0 - H tends to the constant M_n + (1/mu0 - d_n) tau).
/// H and dH/dB are continuous (dH/dB Lipschitz, which keeps Newton quadratic); FEMM's linear
/// extrapolation with slope 1/mu0 is the tau -> 0 limit.
class BhCurve {
 public:
  /// Builds the curve; `material` names the material in error messages. A leading (0, 0) point is
  /// optional (added when absent). Throws InputError unless the table has >= 2 points, all
  /// finite, B and H >= 0 and both strictly increasing.
  BhCurve(const std::vector<cases::BhPoint>& table, const std::string& material,
          cases::BhInterpolation interpolation = cases::BhInterpolation::monotone_cubic);

  /// Field strength H(B) [A/m] for B >= 0 [T].
  double h(double b) const;
  /// Differential reluctivity dH/dB [m/H].
  double dh_db(double b) const;
  /// Reluctivity nu = H/B [m/H] as a function of b2 = |B|^2 [T^2] (nu(0) is the limit).
  double nu(double b2) const;
  /// d nu / d(b2) [m/(H T^2)], finite at b2 = 0.
  double dnu_db2(double b2) const;
  /// {nu(b2), dnu_db2(b2)} from one interval search (the same values as the two calls).
  std::pair<double, double> nu_and_dnu_db2(double b2) const;
  /// Magnetic energy density w(B) = integral_0^B H(b) db [J/m^3].
  double energy_density(double b) const;

 private:
  // The Hermite cubic of one interval in power form: with t = (b - b0) / w,
  // H = p0 + p1 t + p2 t^2 + p3 t^3 (p0 = H(b0), p1 = w H'(b0)).
  struct Cubic {
    double b0, w, inv_w, p0, p1, p2, p3;
  };
  // The interval [b0, b1]'s cubic through (b0, h0) and (b1, h1) with slopes d0 and d1.
  static Cubic hermite(double b0, double b1, double h0, double h1, double d0, double d1);
  int interval(double b) const;  // index of the cubic containing b; -1 first interval, n = beyond
  double cubic_h(const Cubic& c, double b) const;
  double cubic_dh(const Cubic& c, double b) const;
  double cubic_energy(const Cubic& c, double b) const;  // integral from c.b0 to b

  std::vector<double> b_, h_;           // table with (0, 0) first
  double a_ = 0.0, c_ = 0.0;            // first interval: H = B (a + c B^2)
  std::vector<Cubic> cubics_;           // intervals 1 .. n-1 (cubics_[k] spans b_[k+1] .. b_[k+2])
  std::vector<double> energy_at_;       // w(b_[k])
  double end_slope_ = 0.0, tau_ = 0.0;  // extrapolation: d_n and relaxation length [T]
  // Interval search table: b_[1] .. b_.back() cut into equal cells, each with the first table
  // index k >= 1 where b_[k] >= the cell's left end (the search then steps a point or two).
  std::vector<int> cell_first_;
  double cell_scale_ = 0.0;  // cells per tesla
};

}  // namespace rheomag::magnetostatics
