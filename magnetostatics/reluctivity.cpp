#include "magnetostatics/reluctivity.hpp"

#include <cmath>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::magnetostatics {

Reluctivity::Reluctivity(const cases::Material& material) {
  if (!material.bh.empty()) {
    curve_.emplace(material.bh, material.name, material.bh_interpolation);
    return;
  }
  if (!std::isfinite(material.mu_r) || material.mu_r <= 0.0) {
    std::ostringstream msg;
    msg << "material '" << material.name << "': mu_r = " << material.mu_r
        << "; expected a finite number > 0";
    throw InputError(msg.str());
  }
  nu_linear_ = kNu0 / material.mu_r;
}

double Reluctivity::energy_density(double b2) const {
  return curve_ ? curve_->energy_density(std::sqrt(b2)) : 0.5 * nu_linear_ * b2;
}

std::vector<Reluctivity> build_reluctivities(const cases::Problem& problem) {
  std::vector<Reluctivity> laws;
  laws.reserve(problem.materials.size());
  for (const cases::Material& m : problem.materials) laws.emplace_back(m);
  return laws;
}

}  // namespace rheomag::magnetostatics
