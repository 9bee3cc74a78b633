#pragma once
// Phenomenological force/pressure models driven by motion (velocity or flow), position and a field
// input (current or command voltage): Bingham, LuGre valve model (paper 001 eqs. 8-9), modified
// Bouc-Wen (Spencer et al. 1997, with the first-order command filter), Maxwell (paper 004
// eqs. 8-9) and Dahl. Right-hand sides are templates so Ceres Jets flow through them.
//
// Units are generic: Y = output (N or Pa), M = motion (m/s or m^3/s), X = position (m or m^3),
// U = field input (A or V). Every sign and |.| is regularised with width `eps` (in M), see
// smooth.hpp.

#include <cmath>
#include <string>
#include <vector>

#include "lumped/smooth.hpp"

namespace rheomag::lumped {

/// Which phenomenological model.
enum class PhenoKind { bingham, lugre, bouc_wen, maxwell, dahl };

/// Name and unit (with Y, M, X, U placeholders) of one model parameter.
struct PhenoParam {
  std::string name;
  std::string unit;
  bool field_term;  ///< multiplies the field input (held at 0 when there is none)
};

/// The drive of a phenomenological model at one instant (data, never differentiated).
struct PhenoDrive {
  double position = 0.0;  ///< X
  double motion = 0.0;    ///< M
  double field = 0.0;     ///< U
};

/// Settings that are not fitted: regularisation width and LuGre's motion scale.
struct PhenoSettings {
  double eps = 1e-6;          ///< [M] width of the smooth sign/|.|
  double motion_scale = 1.0;  ///< [M] LuGre: viscous term uses (motion / motion_scale)^alpha
};

/// Parses "bingham" | "lugre" | "bouc-wen" | "maxwell" | "dahl"; false if unknown.
bool parse_pheno_kind(const std::string& name, PhenoKind& kind);

/// The canonical name of a model ("bouc-wen", ...).
std::string pheno_name(PhenoKind kind);

/// Parameters of a model, in the order of the parameter vector.
const std::vector<PhenoParam>& pheno_params(PhenoKind kind);

/// Number of internal states of a model.
std::size_t pheno_state_count(PhenoKind kind);

/// Index of parameter `name` of `kind`, or -1.
int pheno_param_index(PhenoKind kind, const std::string& name);

/// Initial state at the first sample (hysteretic states at rest, filters at the input).
template <class T>
void pheno_initial_state(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s,
                         T* x);

/// State derivatives dx/dt.
template <class T>
void pheno_derivatives(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s,
                       const T* x, T* dxdt);

/// Model output (force or pressure) for state x.
template <class T>
T pheno_output(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s, const T* x);

// ---- implementation -------------------------------------------------------------------------

namespace pheno_detail {

// Parameter indices of each model (documented in pheno_params()).
enum Bingham { kBYield0, kBYield1, kBVisc0, kBVisc1, kBTransition, kBOffset };
enum LuGre { kLStiff0, kLStiff1, kLDamping, kLRate, kLVisc0, kLVisc1, kLExponent, kLOffset };
enum BoucWen {
  kWAlphaA,
  kWAlphaB,
  kWC0A,
  kWC0B,
  kWC1A,
  kWC1B,
  kWK0,
  kWK1,
  kWGamma,
  kWBeta,
  kWA,
  kWEta,
  kWOffset
};
enum Maxwell { kMTau, kMVisc, kMField0, kMField1, kMShape, kMOffset };
enum Dahl { kDVisc, kDForce0, kDForce1, kDSigma, kDStiff, kDOffset };

/// Bouc-Wen: rate of the internal displacement y for state x = (y, z, u_filtered).
template <class T>
T bouc_wen_ydot(const T* p, const PhenoDrive& d, const T* x) {
  const T& u = x[2];
  T alpha = p[kWAlphaA] + p[kWAlphaB] * u;
  T c0 = p[kWC0A] + p[kWC0B] * u;
  T c1 = p[kWC1A] + p[kWC1B] * u;
  return (alpha * x[1] + c0 * d.motion + p[kWK0] * (d.position - x[0])) / (c0 + c1);
}

}  // namespace pheno_detail

template <class T>
void pheno_initial_state(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s,
                         T* x) {
  using namespace pheno_detail;
  using std::tanh;
  switch (kind) {
    case PhenoKind::bingham:
      break;
    case PhenoKind::lugre:
    case PhenoKind::dahl:
      x[0] = T(0.0);
      break;
    case PhenoKind::bouc_wen:
      x[0] = T(d.position);
      x[1] = T(0.0);
      x[2] = T(d.field);
      break;
    case PhenoKind::maxwell:
      x[0] = p[kMVisc] * d.motion +
             (p[kMField0] + p[kMField1] * d.field) * tanh(p[kMShape] * d.motion);
      break;
  }
  (void)s;
}

template <class T>
void pheno_derivatives(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s,
                       const T* x, T* dxdt) {
  using namespace pheno_detail;
  using std::tanh;
  const double abs_m = std::sqrt(d.motion * d.motion + s.eps * s.eps) - s.eps;
  switch (kind) {
    case PhenoKind::bingham:
      break;
    case PhenoKind::lugre:  // z' = a0 (m - |m| z), z dimensionless (paper 001 eq. 9 rescaled)
      dxdt[0] = p[kLRate] * (d.motion - abs_m * x[0]);
      break;
    case PhenoKind::dahl:  // z' = sigma (m - |m| z)
      dxdt[0] = p[kDSigma] * (d.motion - abs_m * x[0]);
      break;
    case PhenoKind::bouc_wen: {
      T ydot = bouc_wen_ydot(p, d, x);
      T r = d.motion - ydot;  // relative rate across the Bouc-Wen element
      const T& z = x[1];
      dxdt[0] = ydot;
      // n = 2: z' = -gamma |r| z |z| - beta r |z|^2 + A r
      dxdt[1] = -p[kWGamma] * smooth_abs(r, s.eps) * z * smooth_abs(z, 1e-12) -
                p[kWBeta] * r * z * z + p[kWA] * r;
      dxdt[2] = -p[kWEta] * (x[2] - d.field);  // u' = -eta (u - v)
      break;
    }
    case PhenoKind::maxwell: {  // zeta F' + F = Rv m + R(u) tanh(c m)
      T fd = p[kMVisc] * d.motion +
             (p[kMField0] + p[kMField1] * d.field) * tanh(p[kMShape] * d.motion);
      dxdt[0] = (fd - x[0]) / p[kMTau];
      break;
    }
  }
}

template <class T>
T pheno_output(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s,
               const T* x) {
  using namespace pheno_detail;
  using std::tanh;
  switch (kind) {
    case PhenoKind::bingham:
      return (p[kBYield0] + p[kBYield1] * d.field) * tanh(d.motion / p[kBTransition]) +
             (p[kBVisc0] + p[kBVisc1] * d.field) * d.motion + p[kBOffset];
    case PhenoKind::lugre: {
      const double abs_m = std::sqrt(d.motion * d.motion + s.eps * s.eps) - s.eps;
      T zdot = p[kLRate] * (d.motion - abs_m * x[0]);
      T viscous =
          (p[kLVisc0] + p[kLVisc1] * d.field) *
          smooth_signed_power(T(d.motion / s.motion_scale), p[kLExponent], s.eps / s.motion_scale);
      return (p[kLStiff0] + p[kLStiff1] * d.field) * x[0] + p[kLDamping] * zdot + viscous +
             p[kLOffset];
    }
    case PhenoKind::dahl:
      return p[kDVisc] * d.motion + (p[kDForce0] + p[kDForce1] * d.field) * x[0] +
             p[kDStiff] * d.position + p[kDOffset];
    case PhenoKind::bouc_wen: {
      T c1 = p[kWC1A] + p[kWC1B] * x[2];
      return c1 * bouc_wen_ydot(p, d, x) + p[kWK1] * d.position + p[kWOffset];
    }
    case PhenoKind::maxwell:
      return x[0] + p[kMOffset];
  }
  return T(0.0);
}

}  // namespace rheomag::lumped
