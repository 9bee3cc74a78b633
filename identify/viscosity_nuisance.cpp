// The per-recording viscosity factor of a family fit: which parameters it scales, its fit to one
// recording and its centring.

#include "identify/viscosity_nuisance.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "lumped/blocks.hpp"
#include "lumped/metrics.hpp"

namespace rheomag::identify {

bool scales_with_viscosity(lumped::PhenoKind kind, std::size_t index) {
  const auto& params = lumped::pheno_params(kind);
  if (index >= params.size()) return false;
  const std::string& n = params[index].name;
  static const char* const names[] = {"viscous",
                                      "viscous_per_field",
                                      "c0_a",
                                      "c0_b",
                                      "c1_a",
                                      "c1_b",
                                      "post_yield",
                                      "post_yield_per_field",
                                      "pre_yield",
                                      "consistency",
                                      "consistency_per_field",
                                      "pre_yield_viscous"};
  // LuGre's "viscous" is a force (its sigma2 term times a normalised velocity): it scales too.
  for (const char* name : names)
    if (n == name) return true;
  return false;
}

GreyboxFit with_viscosity_factor(const GreyboxFit& fit, double factor) {
  GreyboxFit scaled = fit;
  for (std::size_t k = 0; k < scaled.params.size(); ++k)
    if (scales_with_viscosity(fit.setup.kind, k)) scaled.params[k].value *= factor;
  return scaled;
}

double fit_viscosity_factor(const lumped::Recording& rec, const GreyboxFit& fit,
                            const ViscosityNuisance& bounds) {
  if (!(bounds.lower > 0.0) || !(bounds.upper >= bounds.lower))
    throw InputError("viscosity nuisance: expected bounds 0 < lower <= upper, got " +
                     std::to_string(bounds.lower) + ":" + std::to_string(bounds.upper));
  const auto& y = rec.column(rec.meta.output);
  const auto misfit = [&](double log_factor) {
    const auto model = simulate_greybox(rec, with_viscosity_factor(fit, std::exp(log_factor)));
    const double f = lumped::fit_percent(y, model);
    return std::isfinite(f) ? -f : HUGE_VAL;
  };
  // Golden-section search on [ln lower, ln upper].
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = std::log(bounds.lower), b = std::log(bounds.upper);
  double c = b - golden * (b - a), d = a + golden * (b - a);
  double fc = misfit(c), fd = misfit(d);
  while (b - a > 1e-3) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - golden * (b - a), fc = misfit(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + golden * (b - a), fd = misfit(d);
    }
  }
  return std::exp(0.5 * (a + b));
}

void centre_viscosity_factors(std::vector<double>& factors, GreyboxFit& fit) {
  if (factors.empty()) return;
  double log_mean = 0.0;
  for (double f : factors) log_mean += std::log(f) / static_cast<double>(factors.size());
  const double mean = std::exp(log_mean);
  for (double& f : factors) f /= mean;
  fit = with_viscosity_factor(fit, mean);
}

double viscosity_temperature_offset(double factor) {
  return -std::log(factor) / lumped::kFluidViscosityTemperatureSlope;
}

}  // namespace rheomag::identify
