// Exact mixed-mode (Couette-Poiseuille) flow of a Bingham / Herschel-Bulkley fluid in a slit or
// an annulus with the inner wall moving (docs/fluid.md, "Mixed mode", has the derivation).
//
// x in [0, h] is the distance from the moving wall. The axial momentum balance with the
// pressure gradient G = dp/L (dp = upstream - downstream, > 0 pushes along the flow) gives the
// shear stress from its value tau_w at the moving wall:
//   slit      tau(x) = tau_w - G x
//   annulus   tau(r) = (tau_w R_i - G (r^2 - R_i^2)/2) / r,   r = R_i + x      (the 1/r fall)
// and the law gives the shear rate du/dx = sign(tau) ((|tau| - tau_y)/K)^(1/n) where
// |tau| > tau_y, 0 elsewhere (plug). No slip: u(0) = U, u(h) = 0, so
//   (1)  int_0^h du/dx dx = -U
// fixes tau_w (the left side increases with tau_w), and integrating Q = int u dA by parts with
// A(x) the flow area between the moving wall and x (slit b x, annulus pi (r^2 - R_i^2)):
//   (2)  Q = -int_0^h A(x) du/dx dx.
// Q increases with G, so the G that carries a given Q is found by a bracketed root search around
// the tau_w search. The regime is not assumed: the stresses where |tau| = tau_y are the roots of
// a linear (slit) or quadratic (annulus) equation, |tau| is quasi-convex in x in both cases so
// the unyielded set is one interval, and its position (touching the moving wall, the fixed wall,
// neither or both) names the regime. The integrals over each yielded interval are evaluated by
// double-exponential (tanh-sinh) quadrature, which keeps full accuracy at the yield surfaces
// where du/dx ~ distance^(1/n).

#include "fluid/mixed_mode.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace rheomag::fluid {

namespace {

/// Iteration cap of the root searches in the moving-wall gap.
constexpr boost::uintmax_t kMixedRootIterations = 200;

/// The stress field and flow area of one gap, measured from the moving wall.
struct GapShape {
  double h = 0.0;      ///< gap [m]
  double width = 0.0;  ///< slit width b [m] (slit only)
  double r_in = 0.0;   ///< inner (moving) wall radius [m]; 0 for a slit
  bool annulus = false;

  double stress(double x, double tau_w, double gradient) const {
    if (!annulus) return tau_w - gradient * x;
    return (tau_w * r_in - 0.5 * gradient * x * (2.0 * r_in + x)) / (r_in + x);
  }
  double area_below(double x) const {
    return annulus ? std::numbers::pi * x * (2.0 * r_in + x) : width * x;
  }
  double total_area() const { return area_below(h); }
  double moving_wall_area_per_length() const {
    return annulus ? 2.0 * std::numbers::pi * r_in : width;
  }
};

/// Real roots of a2 x^2 + a1 x + a0 = 0 strictly inside (0, h), appended to `out`.
void roots_inside(double a2, double a1, double a0, double h, std::vector<double>& out) {
  auto keep = [&](double x) {
    if (std::isfinite(x) && x > 0.0 && x < h) out.push_back(x);
  };
  if (a2 == 0.0) {
    if (a1 != 0.0) keep(-a0 / a1);
    return;
  }
  const double disc = a1 * a1 - 4.0 * a2 * a0;
  if (disc < 0.0) return;
  // Numerically stable pair (no cancellation in -a1 +- sqrt(disc)).
  const double q = -0.5 * (a1 + std::copysign(std::sqrt(disc), a1));
  if (q != 0.0) {
    keep(q / a2);
    keep(a0 / q);
  } else {
    keep(0.0);
  }
}

/// The shear-rate integrals of one gap at one (tau_w, G).
struct Integrals {
  double velocity_drop = 0.0;  ///< int du/dx dx = u(h) - u(0)
  double flow = 0.0;           ///< -int A du/dx dx
};

class MixedSolver {
 public:
  MixedSolver(GapShape shape, GapRheology fluid, double wall_velocity)
      : s_(shape), f_(fluid), u_(wall_velocity), m_(1.0 / fluid.flow_index) {}

  double shear_rate(double tau) const {
    const double excess = std::abs(tau) - f_.tau_y;
    if (!(excess > 0.0)) return 0.0;
    const double rate = m_ == 1.0 ? excess / f_.consistency : std::pow(excess / f_.consistency, m_);
    return std::copysign(rate, tau);
  }

  /// Points in (0, h) where |tau| = tau_y, sorted, with 0 and h at the ends.
  std::vector<double> breakpoints(double tau_w, double g) const {
    std::vector<double> pts{0.0};
    for (double sign : {1.0, -1.0}) {
      const double t = sign * f_.tau_y;
      if (s_.annulus) {
        // tau_w R_i - G x (2 R_i + x)/2 = t (R_i + x)
        roots_inside(-0.5 * g, -g * s_.r_in - t, (tau_w - t) * s_.r_in, s_.h, pts);
      } else {
        roots_inside(0.0, -g, tau_w - t, s_.h, pts);
      }
    }
    pts.push_back(s_.h);
    std::sort(pts.begin(), pts.end());
    return pts;
  }

  Integrals integrate(double tau_w, double g, bool with_flow) const {
    const std::vector<double> pts = breakpoints(tau_w, g);
    Integrals out;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const double a = pts[i], b = pts[i + 1];
      if (!(b > a)) continue;
      if (shear_rate(s_.stress(0.5 * (a + b), tau_w, g)) == 0.0) continue;  // plug
      auto rate = [&](double x) { return shear_rate(s_.stress(x, tau_w, g)); };
      out.velocity_drop += integrate_piece(rate, a, b);
      if (with_flow)
        out.flow -= integrate_piece([&](double x) { return s_.area_below(x) * rate(x); }, a, b);
    }
    return out;
  }

  /// Moving-wall stress tau_w that satisfies the no-slip condition (1) at gradient G.
  const GapShape& shape() const { return s_; }

  double wall_stress(double g) const {
    auto residual = [&](double tau_w) { return integrate(tau_w, g, false).velocity_drop + u_; };
    const double scale = f_.tau_y + f_.consistency * std::pow(std::abs(u_) / s_.h, 1.0 / m_) +
                         std::abs(g) * s_.h * (1.0 + s_.h / std::max(s_.r_in, s_.h)) + 1e-300;
    return bracket_and_solve(residual, -scale, scale, "moving-wall stress");
  }

  double flow_at(double g) const { return integrate(wall_stress(g), g, true).flow; }

  /// Pressure gradient G that carries `flow`.
  double gradient_for(double flow) const {
    const double area = s_.total_area();
    const double v = std::abs(flow) / area + std::abs(u_);
    const double scale =
        (2.0 * f_.tau_y + 12.0 * f_.consistency * std::pow(v / s_.h, f_.flow_index)) / s_.h;
    return bracket_and_solve([&](double g) { return flow_at(g) - flow; }, -scale, scale,
                             "pressure gradient");
  }

 private:
  template <class F>
  double bracket_and_solve(F f, double lo, double hi, const char* what) const {
    double f_lo = f(lo), f_hi = f(hi);
    for (int k = 0; f_lo > 0.0; ++k) {
      if (k > 400)
        throw ConvergenceError(std::string("mixed-mode gap: ") + what + " not bracketed");
      hi = lo, f_hi = f_lo;
      lo *= 2.0;
      f_lo = f(lo);
    }
    for (int k = 0; f_hi < 0.0; ++k) {
      if (k > 400)
        throw ConvergenceError(std::string("mixed-mode gap: ") + what + " not bracketed");
      lo = hi, f_lo = f_hi;
      hi *= 2.0;
      f_hi = f(hi);
    }
    if (f_lo == 0.0) return lo;
    if (f_hi == 0.0) return hi;
    // Converged at a few ulps of the root, or at 1e-15 of the bracket for a root at 0.
    const double width = hi - lo;
    auto tol = [width](double a, double b) {
      const double gap = std::abs(b - a);
      return gap <= 8.0 * std::numeric_limits<double>::epsilon() *
                        std::max(std::abs(a), std::abs(b)) ||
             gap <= 1e-15 * width;
    };
    boost::uintmax_t iterations = kMixedRootIterations;
    auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, tol, iterations);
    if (iterations >= kMixedRootIterations)
      throw ConvergenceError(std::string("mixed-mode gap: ") + what + " did not converge");
    return 0.5 * (a + b);
  }

  /// Bingham: the integrand is a polynomial (slit) or analytic away from r = 0 (annulus) on a
  /// yielded piece, so fixed 20-point Gauss-Legendre is exact to rounding; Herschel-Bulkley:
  /// tanh-sinh, which handles the (distance)^(1/n) behaviour at a yield surface.
  template <class F>
  double integrate_piece(F f, double a, double b) const {
    if (m_ == 1.0) return boost::math::quadrature::gauss<double, 20>::integrate(f, a, b);
    return quad_.integrate(f, a, b, 1e-13);
  }

  GapShape s_;
  GapRheology f_;
  double u_;
  double m_;
  // tanh_sinh::integrate is not a const member (its trailing "const" qualifies the return type).
  mutable boost::math::quadrature::tanh_sinh<double> quad_;
};

void validate_mixed(const GapRheology& fluid, double wall_velocity, double flow) {
  if (!(std::isfinite(fluid.tau_y) && fluid.tau_y >= 0.0))
    throw InputError("yield stress must be a finite number >= 0 Pa, got " +
                     std::to_string(fluid.tau_y));
  if (!(std::isfinite(fluid.consistency) && fluid.consistency > 0.0))
    throw InputError("viscosity (consistency K) must be a finite number > 0, got " +
                     std::to_string(fluid.consistency));
  if (!(fluid.flow_index >= 0.1 && fluid.flow_index <= 3.0))
    throw InputError("Herschel-Bulkley flow index n must be in [0.1, 3], got " +
                     std::to_string(fluid.flow_index));
  if (!std::isfinite(wall_velocity))
    throw InputError("wall velocity must be a finite number (m/s, either sign)");
  if (!std::isfinite(flow)) throw InputError("flow rate must be a finite number (m^3/s)");
  if (wall_velocity == 0.0 && !(flow > 0.0))
    throw InputError("with a still wall the flow rate must be > 0 (a moving wall allows any sign)");
}

MixedModeDrop solve(const GapShape& shape, double length, const GapRheology& fluid,
                    double wall_velocity, double flow) {
  validate_mixed(fluid, wall_velocity, flow);
  const MixedSolver solver(shape, fluid, wall_velocity);
  const double g = solver.gradient_for(flow);
  const double tau_w = solver.wall_stress(g);
  MixedModeDrop out;
  out.wall_velocity = wall_velocity;
  out.drop.dp = g * length;
  GapRheology plain = fluid;
  plain.tau_y = 0.0;
  out.drop.dp_viscous = fluid.tau_y == 0.0
                            ? out.drop.dp
                            : MixedSolver(shape, plain, wall_velocity).gradient_for(flow) * length;
  out.drop.dp_yield = out.drop.dp - out.drop.dp_viscous;
  out.moving_wall_stress = tau_w;
  out.fixed_wall_stress = shape.stress(shape.h, tau_w, g);
  out.moving_wall_force = tau_w * shape.moving_wall_area_per_length() * length;
  // The plug: the pieces between consecutive |tau| = tau_y points where the fluid is at rest.
  double start = shape.h, end = 0.0;
  if (fluid.tau_y > 0.0) {
    const std::vector<double> pts = solver.breakpoints(tau_w, g);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      if (!(pts[i + 1] > pts[i])) continue;
      if (solver.shear_rate(shape.stress(0.5 * (pts[i] + pts[i + 1]), tau_w, g)) != 0.0) continue;
      start = std::min(start, pts[i]);
      end = std::max(end, pts[i + 1]);
    }
  }
  if (end > start) {
    out.plug_start = start;
    out.plug_end = end;
    out.drop.plug_fraction = (end - start) / shape.h;
    const bool at_moving = start == 0.0, at_fixed = end == shape.h;
    out.regime = at_moving && at_fixed ? MixedRegime::unyielded
                 : at_moving           ? MixedRegime::plug_on_moving_wall
                 : at_fixed            ? MixedRegime::plug_on_fixed_wall
                                       : MixedRegime::floating_plug;
  } else {
    out.regime = MixedRegime::fully_yielded;
  }
  const double v = std::max(std::abs(flow) / shape.total_area(), std::abs(wall_velocity));
  out.drop.bingham_number =
      fluid.tau_y / (fluid.consistency * std::pow(v / shape.h, fluid.flow_index));
  return out;
}

GapShape slit_shape(const SlitGeometry& g) {
  validate(g);
  return GapShape{g.gap, g.width, 0.0, false};
}

GapShape annulus_shape(const AnnulusGeometry& g) {
  validate(g);
  return GapShape{g.gap, 0.0, g.inner(), true};
}

}  // namespace

MixedModeDrop slit_mixed_mode(const SlitGeometry& g, const GapRheology& fluid, double wall_velocity,
                              double flow) {
  return solve(slit_shape(g), g.length, fluid, wall_velocity, flow);
}

MixedModeDrop annulus_mixed_mode(const AnnulusGeometry& g, const GapRheology& fluid,
                                 double wall_velocity, double flow) {
  return solve(annulus_shape(g), g.length, fluid, wall_velocity, flow);
}

double slit_mixed_mode_flow(const SlitGeometry& g, const GapRheology& fluid, double wall_velocity,
                            double dp) {
  validate_mixed(fluid, wall_velocity, 1.0);
  if (!std::isfinite(dp)) throw InputError("pressure drop must be finite");
  return MixedSolver(slit_shape(g), fluid, wall_velocity).flow_at(dp / g.length);
}

double annulus_mixed_mode_flow(const AnnulusGeometry& g, const GapRheology& fluid,
                               double wall_velocity, double dp) {
  validate_mixed(fluid, wall_velocity, 1.0);
  if (!std::isfinite(dp)) throw InputError("pressure drop must be finite");
  return MixedSolver(annulus_shape(g), fluid, wall_velocity).flow_at(dp / g.length);
}

}  // namespace rheomag::fluid
