// The exact slit law against a Bingham line: the plug fraction in closed form, its inverse by
// Newton from an upper bound of the root.

#include "lumped/slit_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace rheomag::lumped {

double slit_plug_at_flow(double rho) {
  if (!(rho > 0.0)) return 1.0;
  // Depressed cubic with p = -3 (1 + rho), q = 2: three real roots; the one in (0, 1] is
  // 2 sqrt(1 + rho) cos(theta / 3 - 2 pi / 3), theta = acos(-(1 + rho)^(-3/2)).
  const double s = 1.0 + rho;
  const double theta = std::acos(-1.0 / (s * std::sqrt(s)));
  return 2.0 * std::sqrt(s) * std::cos(theta / 3.0 - 2.0 * std::numbers::pi / 3.0);
}

double knee_flow(double excess, double intercept, double resistance, double k) {
  if (!(excess > 0.0)) return 0.0;
  if (!(intercept > 0.0) || k == 0.0) return excess / resistance;
  // In u = 1 - delta: R Q / p_b = u^2 (3 - u) / (3 (1 - u)), and the equation times 3 (1 - u) is
  // h(u) = u^2 (3 - u) + k u (1 - u) (2 - u) - 3 (1 - u) e, increasing and convex on [0, 1]:
  // h'(u) = (1 - k)(6u - 3u^2) + 2k + 3e > 0, h''(u) = 6 (1 - k)(1 - u) >= 0. Newton from any
  // u with h(u) >= 0 falls monotonically onto the root. Such starts, from lower bounds of h:
  // sqrt(1.5 e) (h >= 2u^2 - 3e (1 - u)); 1 - 1/(3e + 2) (h >= (1 - w)^2 2 - 3 w e, w = 1 - u);
  // below u = 1/2, the root of 2u^2 + 0.75 k u - 3e (there (1 - u)(2 - u) >= 0.75).
  const double e = excess / intercept;
  // Far above the onset (a yield tiny against the pressure) the plug is gone: delta ~ 2 / (3 e)
  // and its square is below double precision against 1.
  if (!(e < 1e12)) return (excess - k * intercept / 3.0) / resistance;
  double u = std::min(std::sqrt(1.5 * e), 1.0 - 1.0 / (3.0 * e + 2.0));
  const double small = (std::sqrt(0.5625 * k * k + 24.0 * e) - 0.75 * k) / 4.0;
  if (small <= 0.5) u = std::min(u, small);
  for (int it = 0;; ++it) {
    const double h = u * u * (3.0 - u) + k * u * (1.0 - u) * (2.0 - u) - 3.0 * (1.0 - u) * e;
    const double dh = (1.0 - k) * (6.0 * u - 3.0 * u * u) + 2.0 * k + 3.0 * e;
    const double step = h / dh;
    u -= step;
    if (std::abs(step) <= 1e-13 * u) break;
    if (it == 60 || !std::isfinite(u))
      throw ConvergenceError("knee_flow: the slit law's plug fraction did not converge");
  }
  // Q from the form that has no cancellation at this u: the slit's own relation while the plug
  // fills most of the gap, the excess less the knee's yield part once it is thin.
  if (u < 0.5) return intercept * u * u * (3.0 - u) / (3.0 * (1.0 - u) * resistance);
  return (excess - k * intercept * u * (2.0 - u) / 3.0) / resistance;
}

}  // namespace rheomag::lumped
