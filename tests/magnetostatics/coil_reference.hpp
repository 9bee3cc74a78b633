#pragma once
// Test helper: semi-analytic inductances of air-core coils.
//
// Thick coil (rectangular cross-section, radii a1 < a2, length l, N turns, uniform current
// density): with the Fourier-Bessel form of the vector potential of a circular filament,
// A_phi = (mu0 I a / 2) integral_0^inf J1(k a) J1(k r) exp(-k |z - z'|) dk, integrated over both
// cross-sections,
//   L = mu0 pi (N / ((a2 - a1) l))^2 integral_0^inf T(k)^2 Z(k) dk,
//   T(k) = integral_{a1}^{a2} r J1(k r) dr,   Z(k) = 2 (k l - 1 + exp(-k l)) / k^2
// (J. T. Conway, "Inductance calculations for circular coils of rectangular cross section and
// parallel axes using Bessel and Struve functions", IEEE Trans. Magn. 46(1), 2010, 75-81, where
// T is written with Struve functions). Here T is integrated numerically: F(X) = integral_0^X
// t J1(t) dt is accumulated along the monotone k grid with 10-point Gauss-Legendre pieces, and
// the k integral uses 10-point Gauss-Legendre panels of width min(pi / (4 a2), 1 / (4 l)) up to
// k a1 = 4000 (the integrand decays like k^-4; the truncated tail is < 1e-9 relative).
//
// Thin solenoid (current sheet): Lorenz / Nagaoka, L = mu0 pi a^2 N^2 / l K_N with
// K_N = 4 / (3 pi k') ((k'^2 / k^2)(K(k) - E(k)) + E(k) - k), k^2 = 4 a^2 / (4 a^2 + l^2).

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace rheomag::test {

/// 10-point Gauss-Legendre nodes and weights on [-1, 1].
inline const std::array<std::array<double, 2>, 10>& gauss_legendre_10() {
  static const std::array<std::array<double, 2>, 10> rule = {{
      {-0.9739065285171717, 0.0666713443086881},
      {-0.8650633666889845, 0.1494513491505806},
      {-0.6794095682990244, 0.2190863625159820},
      {-0.4333953941292472, 0.2692667193099963},
      {-0.1488743389816312, 0.2955242247147529},
      {0.1488743389816312, 0.2955242247147529},
      {0.4333953941292472, 0.2692667193099963},
      {0.6794095682990244, 0.2190863625159820},
      {0.8650633666889845, 0.1494513491505806},
      {0.9739065285171717, 0.0666713443086881},
  }};
  return rule;
}

/// integral_x0^x1 t J1(t) dt by the 4-point Gauss-Legendre rule (pieces x1 - x0 <= 0.4).
inline double t_j1_piece(double x0, double x1) {
  static constexpr double kNode[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                      0.8611363115940526};
  static constexpr double kWeight[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                        0.3478548451374538};
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double t = 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * kNode[i];
    sum += kWeight[i] * t * std::cyl_bessel_j(1.0, t);
  }
  return 0.5 * (x1 - x0) * sum;
}

/// Self-inductance [H] of a thick air-core coil (see the header comment).
inline double thick_coil_inductance(double a1, double a2, double length, double turns,
                                    double k_max_a1 = 1000.0, double panel = 0.5) {
  constexpr double mu0 = 4e-7 * std::numbers::pi;
  const double dk = panel * std::min(std::numbers::pi / a2, 1.0 / length);
  const double k_max = k_max_a1 / a1;
  double f1 = 0.0, f2 = 0.0, x1 = 0.0, x2 = 0.0;  // F(k a1), F(k a2) at the previous node
  double integral = 0.0;
  for (double k0 = 0.0; k0 < k_max; k0 += dk) {
    for (const auto& [x, w] : gauss_legendre_10()) {
      const double k = k0 + 0.5 * dk * (1.0 + x);
      f1 += t_j1_piece(x1, k * a1), x1 = k * a1;
      f2 += t_j1_piece(x2, k * a2), x2 = k * a2;
      const double t = (f2 - f1) / (k * k);
      const double kl = k * length;
      const double z = kl < 1e-4 ? length * length * (1.0 - kl / 3.0 + kl * kl / 12.0)
                                 : 2.0 * (kl + std::expm1(-kl)) / (k * k);
      integral += 0.5 * dk * w * t * t * z;
    }
  }
  const double density = turns / ((a2 - a1) * length);
  return mu0 * std::numbers::pi * density * density * integral;
}

/// Self-inductance [H] of a thin solenoid (current sheet of radius a, length l): Nagaoka.
inline double nagaoka_inductance(double a, double length, double turns) {
  constexpr double mu0 = 4e-7 * std::numbers::pi;
  const double k2 = 4 * a * a / (4 * a * a + length * length), k = std::sqrt(k2);
  const double kp = std::sqrt(1 - k2);
  const double big_k = std::comp_ellint_1(k), big_e = std::comp_ellint_2(k);
  const double nagaoka =
      4.0 / (3.0 * std::numbers::pi * kp) * (kp * kp / k2 * (big_k - big_e) + big_e - k);
  return mu0 * std::numbers::pi * a * a * turns * turns / length * nagaoka;
}

}  // namespace rheomag::test
