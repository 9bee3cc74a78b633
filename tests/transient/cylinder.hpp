#pragma once
// Test helper: a conducting cylinder of radius a in a long solenoid (1-D in r): structured
// r-z mesh of the cylinder and a thin winding around it, natural boundaries (H_t = 0 outside
// an ideal solenoid, B_r = 0 on the ends), and the analytic flux after a current step.

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "case/problem.hpp"
#include "core/constants.hpp"
#include "mesh/mesh.hpp"
#include "tests/magnetostatics/structured_mesh.hpp"

namespace rheomag::test {

/// An AISI-1010-like B-H curve (B [T], H [A/m]) for the saturating tests.
inline const std::vector<cases::BhPoint> kSaturatingBh = {
    {0.0, 0.0},    {0.5, 200.0},   {1.0, 500.0},   {1.3, 800.0},   {1.5, 1300.0},  {1.6, 2500.0},
    {1.7, 5000.0}, {1.8, 10000.0}, {1.9, 16000.0}, {2.0, 30000.0}, {2.1, 50000.0}, {2.3, 150000.0}};

/// The reference: mu_r = 1000, sigma = 5 MS/m, a = 10 mm; a winding of `turns` over
/// a length `length` just outside it.
struct Cylinder {
  double mu_r = 1000.0, sigma = 5e6, a = 0.01, length = 0.002, turns = 10.0;
  double winding = 0.0005;  ///< radial thickness of the winding [m]
  /// tau_1 = mu sigma a^2 / j_1^2 [s] (108.6 ms for the defaults).
  double tau1() const {
    const double j1 = boost::math::cyl_bessel_j_zero(0.0, 1);
    return kMu0 * mu_r * sigma * a * a / (j1 * j1);
  }
  /// Phi(t) / Phi_inf = 1 - sum_n 4 / j_n^2 exp(-j_n^2 t / (mu sigma a^2)) (Carslaw & Jaeger,
  /// diffusion into a cylinder at a suddenly changed surface value), 2000 terms.
  double relative_flux(double t) const {
    static const std::vector<double> zeros = [] {
      std::vector<double> j;
      for (int n = 1; n <= 2000; ++n) j.push_back(boost::math::cyl_bessel_j_zero(0.0, n));
      return j;
    }();
    const double d = kMu0 * mu_r * sigma * a * a;
    double sum = 0.0;
    for (double j : zeros) sum += 4.0 / (j * j) * std::exp(-j * j * t / d);
    return 1.0 - sum;
  }
  /// Time at which relative_flux reaches `fraction` (bisection to 1e-12 relative).
  double time_to(double fraction) const {
    double lo = 0.0, hi = 20.0 * tau1();
    while (hi - lo > 1e-12 * hi) {
      const double mid = 0.5 * (lo + hi);
      (relative_flux(mid) < fraction ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  /// Time-harmonic flux linkage of the winding per ampere [H] at `frequency`: in the cylinder
  /// H = H0 J0(k r) / J0(k a), k^2 = -j omega mu sigma, H0 = N i / length (infinite cylinder,
  /// ideal solenoid), so its flux is 2 pi a mu H0 J1(k a) / (k J0(k a)); in the winding H falls
  /// linearly from H0 to 0 and each turn (uniform over the winding's width) links the flux
  /// inside it. Bessel functions of the complex argument by their power series (|k a| < 30).
  std::complex<double> harmonic_flux_linkage(double frequency) const {
    using C = std::complex<double>;
    auto bessel = [](int n, C z) {  // J_n(z) = sum (-1)^m (z/2)^(2m+n) / (m! (m+n)!)
      C term = std::pow(z / 2.0, n);
      for (int k = 1; k <= n; ++k) term /= double(k);
      C sum = term;
      for (int m = 1; m < 200; ++m) {
        term *= -(z * z / 4.0) / (double(m) * double(m + n));
        sum += term;
      }
      return sum;
    };
    const double omega = 2.0 * std::numbers::pi * frequency, mu = kMu0 * mu_r;
    const double h0 = turns / length;
    C phi_cylinder = std::numbers::pi * a * a * mu * h0;  // the limit omega -> 0
    if (omega > 0.0) {
      const C k = std::sqrt(C(0.0, -omega * mu * sigma));
      phi_cylinder =
          2.0 * std::numbers::pi * a * mu * h0 * bessel(1, k * a) / (k * bessel(0, k * a));
    }
    // Winding: Phi(rho) - Phi_cyl = mu0 h0 / w integral_a^rho (a + w - r) 2 pi r dr, averaged
    // over rho in [a, a + w] (closed form of the double integral).
    const double w = winding, b = a + w;
    // antiderivative in rho of integral_a^rho (b - r) r dr
    auto inner_integral = [&](double rho) {
      return b * (rho * rho * rho / 6.0 - a * a * rho / 2.0) -
             (rho * rho * rho * rho / 12.0 - a * a * a * rho / 3.0);
    };
    const double winding_flux =
        kMu0 * h0 / w * 2.0 * std::numbers::pi * (inner_integral(b) - inner_integral(a)) / w;
    return turns * (phi_cylinder + winding_flux);
  }

  /// Problem of regions {cylinder, winding}; `bh` non-empty makes the cylinder nonlinear.
  cases::Problem problem(std::vector<cases::BhPoint> bh = {}) const {
    cases::Problem p;
    p.symmetry = cases::Symmetry::axisymmetric;
    p.outer = cases::OuterBoundary::none;
    p.order = 2;
    p.geometry.source = "cylinder test";
    cases::Material iron{"iron", mu_r, std::move(bh), sigma, "test"};
    cases::Material winding_material{"winding", 1.0, {}, 0.0, "test"};
    p.materials = {iron, winding_material};
    p.circuits = {{"coil", 0.0}};
    mesh::RegionSeed cylinder, coil;
    cylinder.name = "cylinder";
    coil.name = "winding";
    p.geometry.regions = {cylinder, coil};
    p.regions = {{0, -1, 0.0}, {1, 0, turns}};
    return p;
  }
  /// P2 mesh: `radial` elements in the cylinder (graded towards r = a by `grading` per cell),
  /// 2 in the winding, one layer in z.
  mesh::Mesh mesh(int radial, double grading = 0.9) const {
    const auto r = join(graded(0.0, a, radial, grading), uniform(a, a + winding, 2));
    return structured_mesh(r, uniform(0.0, length, 1), 2,
                           [this](double rc, double) { return rc < a ? 0 : 1; });
  }
};

}  // namespace rheomag::test
