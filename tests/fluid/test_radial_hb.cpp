// Radial (disk) Bingham gap and Herschel-Bulkley slit, against independent numerical references.

#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "fluid/herschel_bulkley.hpp"
#include "fluid/newtonian.hpp"
#include "fluid/radial_bingham.hpp"
#include "fluid/slit_bingham.hpp"

using namespace rheomag::fluid;

namespace {

/// Plug fraction from the trigonometric (Viete) solution of delta^3 - 3 a delta + 2 = 0,
/// a = 1 + 4/Bi: delta = 2 sqrt(a) cos(acos(-a^-1.5)/3 - 2 pi/3). Independent of the library's
/// bracketed solver.
double viete_plug_fraction(double bi) {
  const double a = 1.0 + 4.0 / bi;
  return 2.0 * std::sqrt(a) *
         std::cos(std::acos(-std::pow(a, -1.5)) / 3.0 - 2.0 * std::numbers::pi / 3.0);
}

/// Independent reference for the radial gap: integrate dp/dr as an ODE with the adaptive
/// Dormand-Prince 5(4) stepper of Boost.Odeint (tolerances 1e-13), plug fraction from Viete.
template <class Tau>
double radial_reference(const RadialGeometry& g, Tau tau_of_r, double mu, double q) {
  using State = std::array<double, 1>;
  auto rhs = [&](const State&, State& dpdr, double r) {
    const double tau = tau_of_r(r);
    const double bi = 2.0 * std::numbers::pi * r * g.gap * g.gap * tau / (mu * q);
    const double d = viete_plug_fraction(bi);
    dpdr[0] =
        6.0 * mu * q / (std::numbers::pi * r * std::pow(g.gap, 3)) + (3.0 - d * d) * tau / g.gap;
  };
  State p{0.0};
  namespace ode = boost::numeric::odeint;
  ode::integrate_adaptive(ode::make_controlled<ode::runge_kutta_dopri5<State>>(1e-13, 1e-13), rhs,
                          p, g.r_in, g.r_out, 1e-5);
  return p[0];
}

}  // namespace

// Reference: odeint/Viete integration of the same dp/dr (different quadrature and cubic solver);
// agreement within 1e-8 relative for uniform and radius-dependent yield stress.
TEST(RadialBingham, MatchesIndependentOdeIntegration) {
  const RadialGeometry g{0.8e-3, 5e-3, 25e-3};
  const double mu = 0.1;
  for (double q : {1e-6, 1e-4, 3e-3}) {
    for (double tau0 : {1e3, 3e4}) {
      auto tau_of_r = [&](double r) { return tau0 * (0.3 + r / g.r_out); };
      const auto lib = radial_bingham(g, tau_of_r, mu, q);
      const double ref = radial_reference(g, tau_of_r, mu, q);
      EXPECT_NEAR(lib.dp / ref, 1.0, 1e-8) << "q=" << q << " tau0=" << tau0;
      const auto uniform = radial_bingham(g, tau0, mu, q);
      const double ref_uniform = radial_reference(
          g, [&](double) { return tau0; }, mu, q);
      EXPECT_NEAR(uniform.dp / ref_uniform, 1.0, 1e-8);
    }
  }
}

// Reference: radial Poiseuille dp = 6 mu Q ln(r_out/r_in)/(pi h^3) written out (1e-14).
TEST(RadialBingham, ViscousOnlyLimitIsRadialPoiseuille) {
  const RadialGeometry g{1e-3, 4e-3, 20e-3};
  const auto r = radial_bingham(g, 0.0, 0.2, 1e-5);
  const double ref = 6.0 * 0.2 * 1e-5 * std::log(5.0) / (std::numbers::pi * 1e-9);
  EXPECT_NEAR(r.dp / ref, 1.0, 1e-14);
  EXPECT_EQ(r.dp_yield, 0.0);
}

// Reference: a narrow ring (r_out - r_in = r/200) is a slit of width 2 pi r_mean and length
// r_out - r_in; the difference is O(((r_out - r_in)/r)^2) ~ 1e-5, tolerance 1e-4.
TEST(RadialBingham, NarrowRingIsASlit) {
  const RadialGeometry g{1e-3, 0.02, 0.0201};
  const double rm = 0.5 * (g.r_in + g.r_out);
  for (double tau : {0.0, 2e3, 4e4}) {
    const auto radial = radial_bingham(g, tau, 0.1, 1e-6);
    const auto slit = slit_bingham(
        SlitGeometry{g.gap, 2.0 * std::numbers::pi * rm, g.r_out - g.r_in}, tau, 0.1, 1e-6);
    EXPECT_NEAR(radial.dp / slit.dp, 1.0, 1e-4);
    EXPECT_NEAR(radial.plug_fraction, slit.plug_fraction, 1e-12);
  }
}

TEST(RadialBingham, BadInputThrows) {
  EXPECT_THROW(radial_bingham(RadialGeometry{1e-3, 0.02, 0.01}, 1.0, 0.1, 1e-6),
               rheomag::InputError);
  EXPECT_THROW(radial_bingham(RadialGeometry{1e-3, 0.02, 0.02}, 1.0, 0.1, 1e-6),
               rheomag::InputError);
  EXPECT_THROW(radial_bingham(RadialGeometry{0.0, 0.01, 0.02}, 1.0, 0.1, 1e-6),
               rheomag::InputError);
  EXPECT_THROW(radial_bingham(RadialGeometry{1e-3, 0.01, 0.02}, 1.0, 0.1, 0.0),
               rheomag::InputError);
}

// Reference: the exact Bingham slit (library's plug-fraction cubic); HB with n = 1 must agree
// within 1e-10 over Bi from ~0.1 to ~1e5.
TEST(HerschelBulkley, FlowIndexOneIsBingham) {
  const SlitGeometry g{1e-3, 0.06, 0.015};
  for (double tau : {0.0, 50.0, 5e3, 5e4}) {
    for (double q : {1e-7, 1e-5, 1e-3}) {
      const auto hb = herschel_bulkley_slit(g, tau, 0.12, 1.0, q);
      const auto bingham = slit_bingham(g, tau, 0.12, q);
      EXPECT_NEAR(hb.dp / bingham.dp, 1.0, 1e-10) << "tau=" << tau << " q=" << q;
      EXPECT_NEAR(hb.plug_fraction, bingham.plug_fraction, 1e-10);
      EXPECT_NEAR(hb.dp_viscous / bingham.dp_viscous, 1.0, 1e-12);
    }
  }
}

// Reference: Q = 2 b int_{y0}^{h/2} y ((G y - tau_y)/K)^(1/n) dy by tanh-sinh quadrature at the
// computed dp (shear-thinning n = 0.6 and thickening n = 1.4): must give back Q within 1e-9.
TEST(HerschelBulkley, PressureDropReproducesFlowByQuadrature) {
  const SlitGeometry g{0.7e-3, 0.04, 0.02};
  const double k = 0.8, q = 4e-6;
  for (double n : {0.6, 1.4}) {
    for (double tau : {0.0, 2e3, 3e4}) {
      const auto r = herschel_bulkley_slit(g, tau, k, n, q);
      const double grad = r.dp / g.length, y0 = tau / grad;
      auto integrand = [&](double y) {
        return y * std::pow(std::max(grad * y - tau, 0.0) / k, 1.0 / n);
      };
      boost::math::quadrature::tanh_sinh<double> quadrature;
      const double q_back = 2.0 * g.width * quadrature.integrate(integrand, y0, 0.5 * g.gap);
      EXPECT_NEAR(q_back / q, 1.0, 1e-9) << "n=" << n << " tau=" << tau;
      EXPECT_NEAR(herschel_bulkley_slit_flow(g, tau, k, n, 0.5 * grad * g.gap) / q, 1.0, 1e-12);
    }
  }
}

TEST(HerschelBulkley, BadInputThrows) {
  const SlitGeometry g{1e-3, 0.06, 0.015};
  EXPECT_THROW(herschel_bulkley_slit(g, 1.0, 0.1, 0.0, 1e-6), rheomag::InputError);
  EXPECT_THROW(herschel_bulkley_slit(g, 1.0, 0.0, 1.0, 1e-6), rheomag::InputError);
  EXPECT_THROW(herschel_bulkley_slit(g, 1.0, 0.1, 1.0, -1e-6), rheomag::InputError);
}

// Reference: Hagen-Poiseuille 128 mu Q L/(pi D^4) and K rho V^2/2 written out.
TEST(Newtonian, PipeAndMinorLoss) {
  EXPECT_NEAR(pipe_poiseuille_dp(4e-3, 0.1, 0.1, 1e-6) /
                  (128.0 * 0.1 * 1e-6 * 0.1 / (std::numbers::pi * std::pow(4e-3, 4))),
              1.0, 1e-14);
  const double area = std::numbers::pi * 4e-6;
  EXPECT_NEAR(minor_loss_dp(0.5, 3000.0, 1e-5, area), 0.5 * 0.5 * 3000.0 * std::pow(1e-5 / area, 2),
              1e-9);
  EXPECT_THROW(pipe_poiseuille_dp(-1.0, 0.1, 0.1, 1e-6), rheomag::InputError);
  // atanh(x) - x series against the direct difference where the latter is accurate.
  EXPECT_NEAR(atanh_minus_x(0.3) / (std::atanh(0.3) - 0.3), 1.0, 1e-12);
  EXPECT_NEAR(atanh_minus_x(1e-4) / (1e-12 / 3.0), 1.0, 1e-7);
}
