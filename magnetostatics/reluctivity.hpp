#pragma once
// The constitutive law H = nu(|B|^2) B of one material: linear (mu_r) or a B-H curve.

#include <optional>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics/bh_curve.hpp"

namespace rheomag::magnetostatics {

/// Reluctivity law of one material: nu(b2), d nu/d(b2) and the energy density, b2 = |B|^2.
class Reluctivity {
 public:
  /// Linear (1/(mu0 mu_r)) when `material.bh` is empty, else the B-H curve. Throws InputError
  /// naming the material on a bad table or a non-positive / non-finite mu_r.
  explicit Reluctivity(const cases::Material& material);

  /// True for a B-H curve (the problem is nonlinear).
  bool nonlinear() const { return curve_.has_value(); }
  /// Reluctivity nu [m/H] at b2 = |B|^2 [T^2].
  double nu(double b2) const { return curve_ ? curve_->nu(b2) : nu_linear_; }
  /// d nu/d(b2); 0 for a linear material.
  double dnu_db2(double b2) const { return curve_ ? curve_->dnu_db2(b2) : 0.0; }
  /// {nu(b2), dnu_db2(b2)} in one evaluation of the curve.
  std::pair<double, double> nu_and_dnu_db2(double b2) const {
    return curve_ ? curve_->nu_and_dnu_db2(b2) : std::pair{nu_linear_, 0.0};
  }
  /// Energy density integral_0^|B| H db [J/m^3] at b2 = |B|^2.
  double energy_density(double b2) const;

 private:
  double nu_linear_ = 0.0;
  std::optional<BhCurve> curve_;
};

/// One law per material of the problem, same order as Problem::materials.
std::vector<Reluctivity> build_reluctivities(const cases::Problem& problem);

}  // namespace rheomag::magnetostatics
