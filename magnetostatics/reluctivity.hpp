#pragma once
// The constitutive law H(B) of one material: linear (mu_r, or mu_r along r and z: anisotropic)
// or a B-H curve, H = nu(|B|^2) B.

#include <array>
#include <optional>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics/bh_curve.hpp"

namespace rheomag::magnetostatics {

/// Reluctivity law of one material: nu(b2), d nu/d(b2) and the energy density, b2 = |B|^2.
class Reluctivity {
 public:
  /// Linear (1/(mu0 mu_r), or per axis from `material.mu_r_axes`) when `material.bh` is empty,
  /// else the B-H curve. Throws InputError naming the material on a bad table, a non-positive /
  /// non-finite mu_r, or axes given with a B-H table.
  explicit Reluctivity(const cases::Material& material);

  /// True for a B-H curve (the problem is nonlinear).
  bool nonlinear() const { return curve_.has_value(); }
  /// True for a linear anisotropic material, H = diag(nu_r, nu_z) B: nu(b2) is then nu_r only,
  /// and a caller wants nu_axes(), h(), energy_density(b_r, b_z) or apparent_mu_r().
  bool anisotropic() const { return nu_z_ != nu_linear_; }
  /// Reluctivities along r (x) and z (y) [m/H] of a linear material (equal when isotropic).
  std::array<double, 2> nu_axes() const { return {nu_linear_, nu_z_}; }
  /// Reluctivity nu [m/H] at b2 = |B|^2 [T^2] of an isotropic law.
  double nu(double b2) const { return curve_ ? curve_->nu(b2) : nu_linear_; }
  /// d nu/d(b2); 0 for a linear material.
  double dnu_db2(double b2) const { return curve_ ? curve_->dnu_db2(b2) : 0.0; }
  /// {nu(b2), dnu_db2(b2)} in one evaluation of the curve.
  std::pair<double, double> nu_and_dnu_db2(double b2) const {
    return curve_ ? curve_->nu_and_dnu_db2(b2) : std::pair{nu_linear_, 0.0};
  }
  /// Energy density integral_0^|B| H db [J/m^3] at b2 = |B|^2.
  double energy_density(double b2) const;
  /// Energy density [J/m^3] at the flux density (b_r, b_z) [T], isotropic or anisotropic.
  double energy_density(double b_r, double b_z) const;
  /// Field H = (H_r, H_z) [A/m] at the flux density (b_r, b_z) [T] (a magnet's -H_c m not in).
  std::array<double, 2> h(double b_r, double b_z) const;
  /// Relative permeability along B, |B| / (mu0 |H|); an anisotropic law's mu_r along r at B = 0.
  double apparent_mu_r(double b_r, double b_z) const;

 private:
  double nu_linear_ = 0.0;  ///< linear: nu along r (x), the only one when isotropic
  double nu_z_ = 0.0;       ///< linear: nu along z (y)
  std::optional<BhCurve> curve_;
};

/// One law per material of the problem, same order as Problem::materials.
std::vector<Reluctivity> build_reluctivities(const cases::Problem& problem);

}  // namespace rheomag::magnetostatics
