// The per-recording viscosity factor of a family fit: which parameters it scales, its fit to one
// recording and its centring.

#include "identify/viscosity_nuisance.hpp"

#include <boost/math/tools/minima.hpp>
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
  // Brent's minimisation on [ln lower, ln upper] to about 0.1 % in the factor (10 bits).
  const auto best = boost::math::tools::brent_find_minima(misfit, std::log(bounds.lower),
                                                          std::log(bounds.upper), 10);
  return std::exp(best.first);
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
