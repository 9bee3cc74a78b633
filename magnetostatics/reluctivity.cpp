#include "magnetostatics/reluctivity.hpp"

#include <cmath>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::magnetostatics {

namespace {

/// 1 / (mu0 mu_r), or InputError naming the material and what is wrong with `mu_r`.
double linear_reluctivity(const cases::Material& material, double mu_r, const char* key) {
  if (!std::isfinite(mu_r) || mu_r <= 0.0) {
    std::ostringstream msg;
    msg << "material '" << material.name << "': " << key << " = " << mu_r
        << "; expected a finite number > 0";
    throw InputError(msg.str());
  }
  return kNu0 / mu_r;
}

}  // namespace

Reluctivity::Reluctivity(const cases::Material& material) {
  if (!material.bh.empty()) {
    if (material.mu_r_axes)
      throw InputError("material '" + material.name +
                       "': a B-H table and permeabilities along r and z; expected one of them");
    curve_.emplace(material.bh, material.name, material.bh_interpolation);
    return;
  }
  if (material.mu_r_axes) {
    nu_linear_ = linear_reluctivity(material, (*material.mu_r_axes)[0], "mu_r along r (x)");
    nu_z_ = linear_reluctivity(material, (*material.mu_r_axes)[1], "mu_r along z (y)");
    return;
  }
  nu_linear_ = nu_z_ = linear_reluctivity(material, material.mu_r, "mu_r");
}

double Reluctivity::energy_density(double b2) const {
  return curve_ ? curve_->energy_density(std::sqrt(b2)) : 0.5 * nu_linear_ * b2;
}

double Reluctivity::energy_density(double b_r, double b_z) const {
  if (!anisotropic()) return energy_density(b_r * b_r + b_z * b_z);
  return 0.5 * (nu_linear_ * b_r * b_r + nu_z_ * b_z * b_z);
}

std::array<double, 2> Reluctivity::h(double b_r, double b_z) const {
  if (anisotropic()) return {nu_linear_ * b_r, nu_z_ * b_z};
  const double n = nu(b_r * b_r + b_z * b_z);
  return {n * b_r, n * b_z};
}

double Reluctivity::apparent_mu_r(double b_r, double b_z) const {
  if (!anisotropic()) return kNu0 / nu(b_r * b_r + b_z * b_z);
  const auto [h_r, h_z] = h(b_r, b_z);
  const double h_norm = std::hypot(h_r, h_z);
  return h_norm > 0.0 ? kNu0 * std::hypot(b_r, b_z) / h_norm : kNu0 / nu_linear_;
}

std::vector<Reluctivity> build_reluctivities(const cases::Problem& problem) {
  std::vector<Reluctivity> laws;
  laws.reserve(problem.materials.size());
  for (const cases::Material& m : problem.materials) laws.emplace_back(m);
  return laws;
}

}  // namespace rheomag::magnetostatics
