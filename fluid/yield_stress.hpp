#pragma once
// Field-dependent yield stress of an MR fluid: tau_y(|B|) from a table, a clamped polynomial or
// Carlson's volume-fraction model. All curves take |B| in tesla and return pascals.

#include <functional>
#include <limits>
#include <memory>
#include <variant>
#include <vector>

namespace rheomag::fluid {

/// Measured tau_y(B) samples interpolated monotonically (Fritsch-Carlson/Butland PCHIP via Boost;
/// linear for 2-3 points); constant beyond the last sample (saturation) and below the first.
class YieldStressTable {
 public:
  /// `b` strictly increasing [T], `tau` non-decreasing and >= 0 [Pa]; throws InputError otherwise.
  YieldStressTable(std::vector<double> b, std::vector<double> tau);
  /// Yield stress [Pa] at flux density magnitude |b| [T].
  double operator()(double b) const;
  /// The table's flux densities [T].
  const std::vector<double>& b() const { return b_; }
  /// The table's yield stresses [Pa].
  const std::vector<double>& tau() const { return tau_; }

 private:
  std::vector<double> b_, tau_;
  std::shared_ptr<const std::function<double(double)>> interpolant_;
};

/// tau_y(B) = sum_k c_k B^k [Pa], held constant beyond its validity limit: the first local
/// maximum for B > 0 (computed from the roots of the derivative) or a given `b_limit`.
class YieldStressPolynomial {
 public:
  /// `coefficients` in ascending powers [Pa/T^k]; `b_limit` caps the clamp point [T].
  explicit YieldStressPolynomial(std::vector<double> coefficients,
                                 double b_limit = std::numeric_limits<double>::infinity());
  /// Yield stress [Pa] at |b| [T], clamped beyond clamp_point().
  double operator()(double b) const;
  /// Flux density where the polynomial stops being used [T].
  double clamp_point() const { return clamp_b_; }
  /// The polynomial's coefficients [Pa/T^k], ascending.
  const std::vector<double>& coefficients() const { return coefficients_; }
  /// LORD MRF-132DG fit: 52.962B^4 - 176.51B^3 + 158.79B^2 + 13.708B + 0.1442 kPa.
  static YieldStressPolynomial mrf132dg();

 private:
  double evaluate(double b) const;
  std::vector<double> coefficients_;
  double clamp_b_ = 0.0;
};

/// Carlson's empirical model for carbonyl-iron MR fluids of particle volume fraction phi:
/// tau_y = 271700 C phi^1.5239 tanh(6.33e-6 H) [Pa, H in A/m] and
/// B = 1.91 phi^1.133 (1 - exp(-10.97 mu0 H)) + mu0 H [T], so tau_y(B) via H(B).
class CarlsonYieldStress {
 public:
  /// `volume_fraction` in (0, 0.6]; `carrier_factor` C (1.0 hydrocarbon, 1.16 water,
  /// 0.95 silicone oil).
  explicit CarlsonYieldStress(double volume_fraction, double carrier_factor = 1.0);
  /// Yield stress [Pa] at field strength |h| [A/m].
  double of_field_strength(double h) const;
  /// Flux density in the fluid [T] at field strength |h| [A/m].
  double flux_density(double h) const;
  /// Field strength [A/m] giving flux density |b| [T] (inverse of flux_density).
  double field_strength(double b) const;
  /// Yield stress [Pa] at flux density |b| [T].
  double operator()(double b) const { return of_field_strength(field_strength(b)); }
  /// Particle volume fraction.
  double volume_fraction() const { return phi_; }
  /// Carrier factor C.
  double carrier_factor() const { return c_; }

 private:
  double phi_, c_;
};

/// Zero yield stress (an unmagnetisable or Newtonian fluid).
struct NoYieldStress {
  /// Always 0 Pa.
  double operator()(double) const { return 0.0; }
};

/// Any yield-stress model, times a calibration scale factor (default 1).
class YieldStressCurve {
 public:
  using Model =
      std::variant<NoYieldStress, YieldStressTable, YieldStressPolynomial, CarlsonYieldStress>;
  /// A curve from any model, scaled by `scale` (> 0).
  YieldStressCurve(Model model = NoYieldStress{}, double scale = 1.0);
  /// Yield stress [Pa] at flux density b [T] (sign ignored).
  double operator()(double b) const;
  /// The same curve with a different calibration scale.
  YieldStressCurve scaled(double scale) const { return YieldStressCurve(model_, scale); }
  /// Calibration scale factor.
  double scale() const { return scale_; }
  /// The underlying model.
  const Model& model() const { return model_; }

 private:
  Model model_;
  double scale_ = 1.0;
};

}  // namespace rheomag::fluid
