// Exact mixed-mode (pressure + moving wall) Bingham / Herschel-Bulkley gap flow: the still-wall
// limit, every regime against closed forms derived independently here, the 1/r fall of the
// drag stress in an annulus, and bad input.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "core/error.hpp"
#include "fluid/annulus_bingham.hpp"
#include "fluid/herschel_bulkley.hpp"
#include "fluid/mixed_mode.hpp"
#include "fluid/slit_bingham.hpp"

using namespace rheomag::fluid;

namespace {

struct SlitReference {
  double flow_per_width = NAN;
  MixedRegime regime = MixedRegime::unyielded;
};

// Closed-form Bingham slit flow per unit width q(G, U) (wall y = 0 at U, wall y = h fixed,
// tau(y) = tau_0 - G y, yield band of half-width d = tau_y / G about tau = 0), derived regime by
// regime for G > 0 (G < 0 by the symmetry u -> -u):
//   fully yielded:        q = U h / 2 + G h^3 / (12 mu) (one sign of tau: the Newtonian profile)
//   plug on moving wall:  U > 0, H = sqrt(2 mu U / G), y2 = h - H in (0, 2d]:
//                         q = U y2 + G H^3 / (3 mu)
//   plug on fixed wall:   U < 0, y1 = sqrt(-2 mu U / G), y1 < h <= y1 + 2d:
//                         q = U y1 + G y1^3 / (3 mu)
//   floating plug:        w = h - 2d > 0, y1 = (w^2 - 2 mu U / G) / (2 w), y2 = y1 + 2d, both in
//                         (0, h): q = U y1 + G y1^3/(3 mu) + 2 d G (h - y2)^2/(2 mu)
//                                    + G (h - y2)^3 / (3 mu)
SlitReference slit_reference(double h, double mu, double tau_y, double g, double u) {
  if (g < 0.0) {
    SlitReference r = slit_reference(h, mu, tau_y, -g, -u);
    r.flow_per_width = -r.flow_per_width;
    // The mirror swaps nothing about which wall the plug is on.
    return r;
  }
  if (g == 0.0) return {u * h / 2.0, MixedRegime::fully_yielded};
  const double d = tau_y / g;
  const double newtonian = u * h / 2.0 + g * h * h * h / (12.0 * mu);
  // Fully yielded with tau > tau_y everywhere (tau_0 from the no-slip condition) or < -tau_y.
  if (tau_y + g * h / 2.0 - mu * u / h - g * h >= tau_y)
    return {newtonian, MixedRegime::fully_yielded};
  if (-tau_y + g * h / 2.0 - mu * u / h <= -tau_y) return {newtonian, MixedRegime::fully_yielded};
  if (u > 0.0) {
    const double big_h = std::sqrt(2.0 * mu * u / g), y2 = h - big_h;
    if (y2 > 0.0 && y2 <= 2.0 * d)
      return {u * y2 + g * big_h * big_h * big_h / (3.0 * mu), MixedRegime::plug_on_moving_wall};
  }
  if (u < 0.0) {
    const double y1 = std::sqrt(-2.0 * mu * u / g);
    if (y1 < h && y1 + 2.0 * d >= h)
      return {u * y1 + g * y1 * y1 * y1 / (3.0 * mu), MixedRegime::plug_on_fixed_wall};
  }
  const double w = h - 2.0 * d;
  const double y1 = (w * w - 2.0 * mu * u / g) / (2.0 * w), y2 = y1 + 2.0 * d;
  if (w > 0.0 && y1 > 0.0 && y2 < h) {
    const double h2 = h - y2;
    return {u * y1 + g * y1 * y1 * y1 / (3.0 * mu) + 2.0 * d * g * h2 * h2 / (2.0 * mu) +
                g * h2 * h2 * h2 / (3.0 * mu),
            MixedRegime::floating_plug};
  }
  return {};
}

std::string name(MixedRegime r) {
  return std::string(kMixedRegimeNames.name(r));
}

}  // namespace

// Reference: with U = 0 the mixed-mode solver must reproduce today's exact still-wall solutions
// (Buckingham-Reiner slit, Fredrickson-Bird annulus, Herschel-Bulkley slit) to 1e-10.
TEST(MixedMode, StillWallEqualsExactSlitAndAnnulus) {
  const SlitGeometry slit{1e-3, 0.05, 0.02};
  const AnnulusGeometry annulus{1e-3, 0.0195, 0.01};
  for (double q : {1e-8, 1e-6, 1e-4}) {
    for (double tau_y : {0.0, 500.0, 2e4}) {
      const GapRheology bingham{tau_y, 0.1, 1.0};
      const MixedModeDrop s = slit_mixed_mode(slit, bingham, 0.0, q);
      const GapPressureDrop s_ref = slit_bingham(slit, tau_y, 0.1, q);
      EXPECT_NEAR(s.drop.dp / s_ref.dp, 1.0, 1e-10) << q << " " << tau_y;
      EXPECT_NEAR(s.drop.dp_viscous / s_ref.dp_viscous, 1.0, 1e-10);
      EXPECT_NEAR(s.drop.plug_fraction, s_ref.plug_fraction, 1e-10);
      EXPECT_NEAR(s.drop.bingham_number, s_ref.bingham_number, 1e-10 * s_ref.bingham_number);
      const MixedModeDrop a = annulus_mixed_mode(annulus, bingham, 0.0, q);
      const GapPressureDrop a_ref = annulus_bingham(annulus, tau_y, 0.1, q);
      EXPECT_NEAR(a.drop.dp / a_ref.dp, 1.0, 1e-10) << q << " " << tau_y;
      EXPECT_NEAR(a.drop.dp_viscous / a_ref.dp_viscous, 1.0, 1e-10);
      EXPECT_NEAR(a.drop.plug_fraction, a_ref.plug_fraction, 1e-9);
      // Still wall, forward flow: a floating plug (symmetric in the slit), or none at tau_y = 0.
      EXPECT_EQ(s.regime, tau_y > 0 ? MixedRegime::floating_plug : MixedRegime::fully_yielded);
      EXPECT_EQ(a.regime, tau_y > 0 ? MixedRegime::floating_plug : MixedRegime::fully_yielded);
      for (double n : {0.5, 1.6}) {
        const MixedModeDrop h = slit_mixed_mode(slit, GapRheology{tau_y, 0.3, n}, 0.0, q);
        EXPECT_NEAR(h.drop.dp / herschel_bulkley_slit(slit, tau_y, 0.3, n, q).dp, 1.0, 1e-10)
            << "n = " << n;
      }
    }
  }
}

// Reference: the regime-by-regime closed forms above (derived from the stress line and the
// no-slip conditions, not from the solver). On a grid of G and U covering every regime, the
// forward flow must match to 1e-14 (1 + tau_y h/(mu |U|)) (relative to |Q| + |U| h b), the inverse
// must return G L to 1e-8 of the yield drop 2 tau_y L / h, and the solver's regime must be the one
// the closed form is valid in. Each of the four moving-wall regimes must occur.
TEST(MixedMode, BinghamSlitRegimesMatchClosedForms) {
  const SlitGeometry s{1e-3, 0.05, 0.02};
  const double mu = 0.1;
  std::set<MixedRegime> seen;
  for (double tau_y : {20.0, 2e4}) {
    const GapRheology f{tau_y, mu, 1.0};
    for (double gs : {-3.0, -1.0, -0.6, -0.2, 0.0, 0.3, 0.9, 1.2, 5.0})
      for (double u : {-47.0, -0.5, -0.005, 0.001, 0.1, 1.3, 47.0}) {
        const double g = gs * 2.0 * tau_y / s.gap;
        const SlitReference ref = slit_reference(s.gap, mu, tau_y, g, u);
        ASSERT_FALSE(std::isnan(ref.flow_per_width)) << "no regime for G " << g << " U " << u;
        const double q_ref = ref.flow_per_width * s.width;
        const double q = slit_mixed_mode_flow(s, f, u, g * s.length);
        // tau - tau_y is resolved to eps tau_y: relative accuracy ~ eps (1 + tau_y h / (mu |U|)).
        const double bi_u = tau_y * s.gap / (mu * std::abs(u));
        EXPECT_NEAR(q, q_ref,
                    1e-14 * (1.0 + bi_u) * (std::abs(q_ref) + std::abs(u) * s.gap * s.width))
            << "G " << g << " U " << u;
        const MixedModeDrop inv = slit_mixed_mode(s, f, u, q_ref);
        EXPECT_NEAR(inv.drop.dp, g * s.length, 1e-8 * 2.0 * tau_y * s.length / s.gap)
            << "G " << g << " U " << u;
        EXPECT_EQ(name(inv.regime), name(ref.regime)) << "G " << g << " U " << u;
        seen.insert(inv.regime);
      }
  }
  EXPECT_EQ(seen.size(), 4u);  // fully yielded, plug on either wall, floating
}

// Reference: Herschel-Bulkley slit, plug on the moving wall (derived here): for y > y2 the
// stress is -tau_y - G (y - y2), so u = (G/K)^m [H^(m+1) - (y - y2)^(m+1)] / (m + 1), H = h - y2,
// U = (G/K)^m H^(m+1)/(m+1) and q = U y2 + (G/K)^m H^(m+2)/(m+2), valid for 0 < y2 <= 2 tau_y/G.
// The solver must give back G L to 1e-9 of 2 tau_y L/h, the plug edge and the regime.
TEST(MixedMode, HerschelBulkleySlitPlugOnMovingWall) {
  const SlitGeometry s{1e-3, 0.05, 0.02};
  for (double n : {0.4, 0.8, 1.5}) {
    const double m = 1.0 / n, k = 0.5, tau_y = 1e4;
    const double g = 0.6 * 2.0 * tau_y / s.gap;  // below the yield gradient
    for (double y2_frac : {0.2, 0.5, 0.9}) {
      const double y2 = y2_frac * s.gap, big_h = s.gap - y2;
      const double u = std::pow(g / k, m) * std::pow(big_h, m + 1.0) / (m + 1.0);
      const double q =
          s.width * (u * y2 + std::pow(g / k, m) * std::pow(big_h, m + 2.0) / (m + 2.0));
      const MixedModeDrop r = slit_mixed_mode(s, GapRheology{tau_y, k, n}, u, q);
      EXPECT_NEAR(r.drop.dp, g * s.length, 1e-9 * 2.0 * tau_y * s.length / s.gap) << n;
      EXPECT_EQ(r.regime, MixedRegime::plug_on_moving_wall) << n << " " << y2_frac;
      EXPECT_NEAR(r.plug_end, y2, 1e-9 * s.gap);
      EXPECT_NEAR(slit_mixed_mode_flow(s, GapRheology{tau_y, k, n}, u, g * s.length), q,
                  1e-11 * std::abs(q));
    }
  }
}

// Reference: reversing both the wall and the flow reverses the pressure drop (u -> -u is a
// symmetry of the equations), in a slit and an annulus, Bingham and Herschel-Bulkley (1e-9).
TEST(MixedMode, ReversingWallAndFlowReversesPressureDrop) {
  const AnnulusGeometry a{1e-3, 0.006, 0.02};
  const SlitGeometry s{1e-3, 0.03, 0.02};
  for (double n : {1.0, 0.7})
    for (double u : {-0.3, 0.05})
      for (double q : {-2e-6, 1e-7, 3e-6}) {
        const GapRheology f{1.5e4, 0.2, n};
        const double fwd = annulus_mixed_mode(a, f, u, q).drop.dp;
        EXPECT_NEAR(annulus_mixed_mode(a, f, -u, -q).drop.dp, -fwd, 1e-9 * std::abs(fwd));
        const double sf = slit_mixed_mode(s, f, u, q).drop.dp;
        EXPECT_NEAR(slit_mixed_mode(s, f, -u, -q).drop.dp, -sf, 1e-9 * std::abs(sf));
      }
}

// Reference: below the yield pressure drop 2 tau_y L / h a still-walled gap carries nothing,
// but a moving wall drags fluid along: at dp = 0.3 x yield the flow has the sign of U and the
// plug rides on the moving wall (U > 0, dp > 0) or sits on the fixed wall (U < 0, dp > 0); and a
// flow smaller than the drag flow needs an adverse (negative) pressure drop.
TEST(MixedMode, MovingWallDragsBelowYieldAndCanNeedAdversePressure) {
  const AnnulusGeometry a{1e-3, 0.01, 0.02};
  const GapRheology f{2e4, 0.1, 1.0};
  const double dp_yield = 2.0 * f.tau_y * a.length / a.gap;
  const double q_up = annulus_mixed_mode_flow(a, f, 0.1, 0.3 * dp_yield);
  EXPECT_GT(q_up, 0.0);
  EXPECT_EQ(annulus_mixed_mode(a, f, 0.1, q_up).regime, MixedRegime::plug_on_moving_wall);
  const double q_down = annulus_mixed_mode_flow(a, f, -0.1, 0.3 * dp_yield);
  EXPECT_LT(q_down, 0.0);
  EXPECT_EQ(annulus_mixed_mode(a, f, -0.1, q_down).regime, MixedRegime::plug_on_fixed_wall);
  // Drag flow at dp = 0; half of it needs dp < 0.
  const double q_drag = annulus_mixed_mode_flow(a, f, 0.1, 0.0);
  EXPECT_GT(q_drag, 0.0);
  EXPECT_LT(annulus_mixed_mode(a, f, 0.1, 0.5 * q_drag).drop.dp, 0.0);
  EXPECT_GT(annulus_mixed_mode(a, f, 0.1, 2.0 * q_drag).drop.dp, 0.0);
}

// Reference: pure drag (dp = 0) in an annulus, derived here: tau(r) = -tau_w R_i / r falls as
// 1/r, the fluid rests beyond r_y = tau_w R_i / tau_y, u(r) = [tau_w R_i ln(r_y/r) -
// tau_y (r_y - r)] / mu, U = u(R_i), Q = (2 pi / mu)[tau_w R_i (r_y^2/4 - R_i^2 ln(r_y/R_i)/2 -
// R_i^2/4) - tau_y (r_y (r_y^2 - R_i^2)/2 - (r_y^3 - R_i^3)/3)]. The solver must return dp = 0
// (1e-9 of the yield drop), the wall stress (1e-9) and a plug on the fixed wall.
TEST(MixedMode, AnnulusDragStressFallsAsOneOverR) {
  const double ri = 0.005, h = 1e-3, mu = 0.1, tau_y = 2e4, len = 0.02;
  const AnnulusGeometry a{h, ri + h / 2, len};
  for (double ry_frac : {0.2, 0.6}) {
    const double ry = ri + ry_frac * h, tau_w = tau_y * ry / ri;
    const double u = (tau_w * ri * std::log(ry / ri) - tau_y * (ry - ri)) / mu;
    const double q =
        2.0 * std::numbers::pi / mu *
        (tau_w * ri * (ry * ry / 4.0 - ri * ri * std::log(ry / ri) / 2.0 - ri * ri / 4.0) -
         tau_y * (ry * (ry * ry - ri * ri) / 2.0 - (ry * ry * ry - ri * ri * ri) / 3.0));
    const MixedModeDrop r = annulus_mixed_mode(a, GapRheology{tau_y, mu, 1.0}, u, q);
    EXPECT_NEAR(r.drop.dp, 0.0, 1e-9 * 2.0 * tau_y * len / h);
    EXPECT_NEAR(r.moving_wall_stress, -tau_w, 1e-9 * tau_w);
    EXPECT_EQ(r.regime, MixedRegime::plug_on_fixed_wall);
    EXPECT_NEAR(r.plug_start, ry - ri, 1e-9 * h);
    EXPECT_NEAR(r.moving_wall_force, -tau_w * 2.0 * std::numbers::pi * ri * len, 1e-9 * tau_w);
  }
}

// Reference: a slit of width 2 pi R models an annulus only when the drag stress's 1/r fall
// across the gap, tau_w h / R, is small against the viscous stress mu U / h. Pure drag, h/R =
// 0.1: with tau_y = 20 Pa (tau_y h/R << mu U/h = 100 Pa) the drag flows agree to 2 h/R; with
// tau_y = 20 kPa the annulus carries less than a third of the slit's drag flow (the outer part of
// the gap is a plug resting on the fixed wall), while under a large pressure drop the two agree
// again (within h/R) because the pressure-driven stress dominates.
TEST(MixedMode, SlitIsNotAMovingAnnulusAtLargeYieldStress) {
  const double h = 1e-3, r = 0.01, len = 0.02, u = 0.1;
  const AnnulusGeometry a{h, r, len};
  const SlitGeometry s{h, 2.0 * std::numbers::pi * r, len};
  const GapRheology weak{20.0, 0.1, 1.0}, strong{2e4, 0.1, 1.0};
  EXPECT_NEAR(annulus_mixed_mode_flow(a, weak, u, 0.0) / slit_mixed_mode_flow(s, weak, u, 0.0), 1.0,
              2.0 * h / r);
  const double ratio =
      annulus_mixed_mode_flow(a, strong, u, 0.0) / slit_mixed_mode_flow(s, strong, u, 0.0);
  EXPECT_LT(ratio, 1.0 / 3.0);
  EXPECT_EQ(annulus_mixed_mode(a, strong, u, annulus_mixed_mode_flow(a, strong, u, 0.0)).regime,
            MixedRegime::plug_on_fixed_wall);
  EXPECT_EQ(slit_mixed_mode(s, strong, u, slit_mixed_mode_flow(s, strong, u, 0.0)).regime,
            MixedRegime::fully_yielded);
  const double q = 1e-5;
  EXPECT_NEAR(
      annulus_mixed_mode(a, strong, u, q).drop.dp / slit_mixed_mode(s, strong, u, q).drop.dp, 1.0,
      h / r);
}

// Reference: Newtonian mixed mode (tau_y = 0) in closed form, slit dp = 12 mu L (Q - b U h/2) /
// (b h^3); dp_viscous equals dp then, and dp_viscous of a Bingham gap is this value (1e-10).
TEST(MixedMode, NewtonianCouettePoiseuille) {
  const SlitGeometry s{0.8e-3, 0.04, 0.015};
  const double mu = 0.2;
  for (double u : {-0.4, 0.2})
    for (double q : {-1e-6, 0.0, 5e-6}) {
      const double ref = 12.0 * mu * s.length * (q - s.width * u * s.gap / 2.0) /
                         (s.width * s.gap * s.gap * s.gap);
      const MixedModeDrop r = slit_mixed_mode(s, GapRheology{3e3, mu, 1.0}, u, q);
      EXPECT_NEAR(r.drop.dp_viscous, ref, 1e-10 * std::abs(ref) + 1e-9);
      EXPECT_NEAR(r.drop.dp_yield, r.drop.dp - r.drop.dp_viscous, 1e-9 * std::abs(r.drop.dp));
    }
}

// Bad input: gap <= 0, viscosity <= 0, tau_y < 0, n out of range, no flow with a still wall ->
// InputError; negative wall velocity and flow are directions, not errors.
TEST(MixedMode, BadInput) {
  const SlitGeometry s{1e-3, 0.05, 0.02};
  const GapRheology f{1e4, 0.1, 1.0};
  EXPECT_THROW(slit_mixed_mode(SlitGeometry{0.0, 0.05, 0.02}, f, 0.1, 1e-6), rheomag::InputError);
  EXPECT_THROW(annulus_mixed_mode(AnnulusGeometry{-1e-3, 0.01, 0.02}, f, 0.1, 1e-6),
               rheomag::InputError);
  EXPECT_THROW(slit_mixed_mode(s, GapRheology{1e4, -0.1, 1.0}, 0.1, 1e-6), rheomag::InputError);
  EXPECT_THROW(slit_mixed_mode(s, GapRheology{-1.0, 0.1, 1.0}, 0.1, 1e-6), rheomag::InputError);
  EXPECT_THROW(slit_mixed_mode(s, GapRheology{1e4, 0.1, 5.0}, 0.1, 1e-6), rheomag::InputError);
  EXPECT_THROW(slit_mixed_mode(s, f, 0.0, -1e-6), rheomag::InputError);
  EXPECT_THROW(slit_mixed_mode(s, f, NAN, 1e-6), rheomag::InputError);
  EXPECT_NO_THROW(slit_mixed_mode(s, f, -0.1, -1e-6));
  EXPECT_NO_THROW(slit_mixed_mode(s, f, 0.1, 0.0));
}
