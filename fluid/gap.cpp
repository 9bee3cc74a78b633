// Input checks shared by the gap-flow models.

#include "fluid/gap.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.hpp"

namespace rheomag::fluid {

namespace {

void require_positive(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s must be a finite number > 0, got %g", what, value);
    throw InputError(buf);
  }
}

}  // namespace

void validate(const SlitGeometry& g) {
  require_positive(g.gap, "slit gap");
  require_positive(g.width, "slit width");
  require_positive(g.length, "slit length");
}

void validate(const AnnulusGeometry& g) {
  require_positive(g.gap, "annular gap");
  require_positive(g.radius, "annulus mean radius");
  require_positive(g.length, "annulus length");
  if (!(g.gap < 2.0 * g.radius)) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "annular gap %g m does not fit around mean radius %g m (need gap < 2 radius)",
                  g.gap, g.radius);
    throw InputError(buf);
  }
}

void validate(const RadialGeometry& g) {
  require_positive(g.gap, "radial gap");
  require_positive(g.r_in, "radial gap inner radius r_in");
  require_positive(g.r_out, "radial gap outer radius r_out");
  if (!(g.r_out > g.r_in)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "radial gap needs r_out > r_in, got r_in = %g m, r_out = %g m",
                  g.r_in, g.r_out);
    throw InputError(buf);
  }
}

void validate_flow(double tau_y, double viscosity, double flow) {
  if (!(std::isfinite(tau_y) && tau_y >= 0.0)) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "yield stress must be a finite number >= 0 Pa, got %g", tau_y);
    throw InputError(buf);
  }
  require_positive(viscosity, "viscosity");
  require_positive(flow, "flow rate");
}

}  // namespace rheomag::fluid
