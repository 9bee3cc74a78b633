#pragma once
// Phenomenological force/pressure models driven by motion (velocity or flow), position and a field
// input (current or command voltage): Bingham, LuGre valve model (paper 001 eqs. 8-9), modified
// Bouc-Wen (Spencer et al. 1997, with the first-order command filter), Maxwell (paper 004
// eqs. 8-9), Dahl, bi-viscous (Stanway et al. 1987), hyperbolic tangent (Kwok et al. 2006) and the
// physically based damper model (docs/damper-model.md). Right-hand sides are templates so Ceres
// Jets flow through them.
//
// Units are generic: Y = output (N or Pa), M = motion (m/s or m^3/s), X = position (m or m^3),
// U = field input (A or V). Every sign and |.| is regularised with width `eps` (in M), see
// smooth.hpp.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/quantity_domain.hpp"
#include "lumped/smooth.hpp"

namespace rheomag::lumped {

/// Which phenomenological model.
enum class PhenoKind { bingham, lugre, bouc_wen, maxwell, dahl, biviscous, tanh, damper };

/// Name and unit (with Y, M, X, U placeholders) of one model parameter.
struct PhenoParam {
  std::string name;
  std::string unit;
  bool field_term;  ///< multiplies the field input (held at 0 when there is none)
  /// Added after models were first written: absent from a model file or spec means 0, which is the
  /// model without it (output_smoothing: no smoothing; field_saturation: no saturation).
  bool optional = false;
};

/// The drive of a phenomenological model at one instant (data, never differentiated).
struct PhenoDrive {
  double position = 0.0;      ///< X
  double motion = 0.0;        ///< M
  double field = 0.0;         ///< U
  double acceleration = 0.0;  ///< [M/s] rate of the motion (damper model's fluid inertia)
};

/// Settings that are not fitted: regularisation width and LuGre's motion scale.
struct PhenoSettings {
  double eps = 1e-6;            ///< [M] width of the smooth sign/|.|
  double motion_scale = 1.0;    ///< [M] LuGre: viscous term uses (motion / motion_scale)^alpha
  double position_scale = 1.0;  ///< [X] tanh model: width of its smooth sign(position)
  double output_scale = 1.0;    ///< [Y] damper model: width of its smooth |force| is 1e-3 of it
  /// [U] damper model: the highest field the model was fitted on (its field column's largest
  /// value over the training samples). Above it the yield force continues along its tangent: a
  /// quadratic's curvature is identified between the levels only. Infinite (no limit) during a
  /// fit and in files written before it.
  double field_high = std::numeric_limits<double>::infinity();
  /// [Y, model orientation] The offset at which a tared recording (DriveSeries::rest_samples) has
  /// in motion the level its rest gives: the training recordings' mean level at rest. A tared
  /// output is shifted by the offset's difference from it, so the level in motion relative to the
  /// rest is fitted (a model without the device's static forces, e.g. no gas spring, needs it).
  /// NaN: the offset does not reach a tared output (the tare of model files written before).
  double rest_reference = std::numeric_limits<double>::quiet_NaN();
};

/// Parses "bingham" | "lugre" | "bouc-wen" | "maxwell" | "dahl" | "bi-viscous" | "tanh" |
/// "damper"; false if unknown.
bool parse_pheno_kind(const std::string& name, PhenoKind& kind);

/// The canonical name of a model ("bouc-wen", ...).
std::string pheno_name(PhenoKind kind);

/// Parameters of a model, in the order of the parameter vector.
const std::vector<PhenoParam>& pheno_params(PhenoKind kind);

/// The values parameter `index` of `kind` may physically take, the scale-free part of the fit's
/// bounds (identify/greybox.cpp): a sign (a yield force, a viscosity, a stiffness of the damper
/// model, a rate >= 0 or > 0) or a fixed interval (an exponent in [0.2, 2], output_smoothing in
/// [0, 0.25] of a drive period, a time constant). Any finite number where the fit allows either
/// sign (offsets, field terms). A model file is read only with every value in its domain.
Domain pheno_param_domain(PhenoKind kind, std::size_t index);

/// Number of internal states of a model.
std::size_t pheno_state_count(PhenoKind kind);

/// Index of output_smoothing, the last parameter of every model: the recording's moving average
/// over that fraction of the drive period (lumped/output_smoothing.hpp).
std::size_t pheno_smoothing_index(PhenoKind kind);

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
enum BiViscous { kVYield0, kVYield1, kVPost0, kVPost1, kVPre, kVOffset };
enum Tanh { kTVisc0, kTVisc1, kTStiff, kTForce0, kTForce1, kTShape, kTLag, kTOffset };
enum Damper {
  kDmYield0,
  kDmYield1,
  kDmYield2,
  kDmVisc0,
  kDmVisc1,
  kDmIndex,
  kDmPreVisc,
  kDmStiff,
  kDmStiffening,
  kDmSeal,
  kDmSeal1,
  kDmSealSlip,
  kDmInertance,
  kDmGas,
  kDmTau,
  kDmOffset,
  kDmSaturation,
  kDmSmoothing
};

/// Damper model: the field the valve sees, in current units, b = tanh(k u) / k with
/// k^2 = p[kDmSaturation] (1 / k is the current at which the gap flux saturates, as the circuit's
/// steel does); b = u for k = 0 (the model before field_saturation existed). Parametrised by k^2,
/// not k: b is even in k, so its slope in k vanishes at 0 while its slope in k^2 is -u^3 / 3, and a
/// fit started at no saturation can move away from it.
template <class T>
T damper_effective_field(const T* p, const T& u) {
  using std::sqrt;
  using std::tanh;
  const T& k2 = p[kDmSaturation];
  const T x2 = k2 * u * u;
  if (std::abs(value_of(x2)) < 1e-8) return u * (1.0 - x2 / 3.0);  // series, exact to 1e-17
  const T k = sqrt(k2);
  return tanh(k * u) / k;
}

/// Damper model: the valve map's coefficients at the field b the valve sees: its yield force, its
/// consistency in motion units and the inverse of its flow index. A step evaluates the valve at
/// several forces for each field, so these are computed once per field.
template <class T>
struct DamperValveLaw {
  T yield;               ///< F_y(b)
  T consistency_motion;  ///< c(b) m_ref
  T inverse_index;       ///< 1 / n
};

/// Damper model: the yield force F_y(b) = y0 + y1 b + y2 b^2 at the field b the valve sees for
/// the field state u; for u above the fitted levels (PhenoSettings::field_high) F_y continues
/// along its tangent there, F_y(b_h) + F_y'(b_h) (b - b_h). Above its levels a fitted quadratic
/// bends either way (ever faster growth, or a yield that falls as the field grows); the tangent
/// is the first-order guess. Below the lowest level the quadratic stays: an MR fluid's yield
/// grows as about b^2 from zero field, which is the curvature a quadratic keeps there.
template <class T>
T damper_yield(const T* p, const PhenoSettings& s, const T& u, const T& b) {
  if (!(value_of(u) > s.field_high)) return p[kDmYield0] + p[kDmYield1] * b + p[kDmYield2] * b * b;
  const T bh = damper_effective_field(p, T(s.field_high));
  return p[kDmYield0] + p[kDmYield1] * bh + p[kDmYield2] * bh * bh +
         (p[kDmYield1] + 2.0 * p[kDmYield2] * bh) * (b - bh);
}

/// Damper model: the valve map's coefficients at the field state u (DamperValveLaw; the valve
/// sees b = damper_effective_field(u)).
template <class T>
DamperValveLaw<T> damper_valve_law(const T* p, const PhenoSettings& s, const T& u) {
  const T b = damper_effective_field(p, u);
  return {damper_yield(p, s, u, b), (p[kDmVisc0] + p[kDmVisc1] * b) * s.motion_scale,
          1.0 / p[kDmIndex]};
}

/// Damper model: rate of the valve force f through the fluid/accumulator compliance, for the valve
/// law at the field the valve sees (damper_valve_law). The valve passes the motion g(F) of a
/// Herschel-Bulkley map with a pre-yield creep branch (inverse of
/// F = sign(m) (F_y(b) + c(b) m_ref (|m| / m_ref)^n), plus F / pre_visc); the compliance's
/// stiffness grows with the force (gas and entrained air stiffen with pressure).
template <class T>
T damper_force_rate_at(const T* p, const PhenoDrive& d, const PhenoSettings& s, const T& f,
                       const DamperValveLaw<T>& valve) {
  const double w = 1e-3 * s.output_scale;
  const T abs_f = smooth_abs(f, w);
  const T excess = smooth_ramp(abs_f - valve.yield, w);
  const T post = s.motion_scale *
                 positive_power(excess / valve.consistency_motion + 1e-12, valve.inverse_index);
  const T valve_motion = f / p[kDmPreVisc] + f / (abs_f + w) * post;
  return (p[kDmStiff] + p[kDmStiffening] * abs_f) * (d.motion - valve_motion);
}

/// Damper model: the valve force's rate (damper_force_rate_at) and its decay rate -d(rate)/df at
/// the same force, from one evaluation of the valve map.
template <class T>
struct DamperForceRate {
  T rate;   ///< df/dt
  T decay;  ///< -d(df/dt)/df
};

/// Damper model: damper_force_rate_at and its derivative in f, the decay rate that linearises the
/// exponential step. The derivative is taken in closed form through the same smoothed map (the
/// smoothed |f| and ramp, and the power's g x^g / x), so the map's power is taken once.
template <class T>
DamperForceRate<T> damper_force_rate_and_decay_at(const T* p, const PhenoDrive& d,
                                                  const PhenoSettings& s, const T& f,
                                                  const DamperValveLaw<T>& valve) {
  using std::sqrt;
  const double w = 1e-3 * s.output_scale;
  const T root_f = sqrt(f * f + w * w);  // smooth_abs(f, w) + w
  const T abs_f = root_f - w;
  const T dabs_f = f / root_f;
  const T over = abs_f - valve.yield;
  const T root_over = sqrt(over * over + w * w);
  const T excess = 0.5 * (over + root_over);  // smooth_ramp(over, w)
  const T dexcess = 0.5 * (1.0 + over / root_over) * dabs_f;
  const T base = excess / valve.consistency_motion + 1e-12;
  const T power = positive_power(base, valve.inverse_index);
  const T post = s.motion_scale * power;
  const T dpost =
      s.motion_scale * valve.inverse_index * power / base * dexcess / valve.consistency_motion;
  const T share = f / (abs_f + w);  // f / (|f| + w): its derivative is w^2 / (|f| + w)^3
  const T dshare = (w * w) / (root_f * root_f * root_f);
  const T valve_motion = f / p[kDmPreVisc] + share * post;
  const T dvalve_motion = 1.0 / p[kDmPreVisc] + dshare * post + share * dpost;
  const T stiffness = p[kDmStiff] + p[kDmStiffening] * abs_f;
  const T gap = d.motion - valve_motion;
  return {stiffness * gap, stiffness * dvalve_motion - p[kDmStiffening] * dabs_f * gap};
}

/// Damper model: rate of the valve force x[0] for state x (field state x[2]).
template <class T>
T damper_force_rate(const T* p, const PhenoDrive& d, const PhenoSettings& s, const T* x) {
  return damper_force_rate_at(p, d, s, x[0], damper_valve_law(p, s, x[2]));
}

/// Bouc-Wen: rate of the internal displacement y for state x = (y, z, u_filtered).
template <class T>
T bouc_wen_ydot(const T* p, const PhenoDrive& d, const T* x) {
  const T& u = x[2];
  T alpha = p[kWAlphaA] + p[kWAlphaB] * u;
  T c0 = p[kWC0A] + p[kWC0B] * u;
  T c1 = p[kWC1A] + p[kWC1B] * u;
  return (alpha * x[1] + c0 * d.motion + p[kWK0] * (d.position - x[0])) / (c0 + c1);
}

/// Bouc-Wen: rate of the hysteretic state z (n = 2) for the relative rate r across the element:
/// z' = -gamma |r| z |z| - beta r z^2 + A r.
template <class T>
T bouc_wen_zdot(const T* p, const PhenoSettings& s, const T& r, const T& z) {
  return -p[kWGamma] * smooth_abs(r, s.eps) * z * smooth_abs(z, 1e-12) - p[kWBeta] * r * z * z +
         p[kWA] * r;
}

/// Bouc-Wen: decay rates -dy'/dy and -dz'/dz (z' with y' substituted) at state x, in values; the
/// linearisation of the exponential step (clamped at 0 where the state grows).
inline std::array<double, 2> bouc_wen_decay_rates(const double* p, const PhenoDrive& d,
                                                  const double* x) {
  const double u = x[2];
  const double alpha = p[kWAlphaA] + p[kWAlphaB] * u;
  const double damping = (p[kWC0A] + p[kWC0B] * u) + (p[kWC1A] + p[kWC1B] * u);
  const double z = x[1];
  const double r = d.motion - bouc_wen_ydot(p, d, x);
  const double dzdot_dz_explicit =
      -2.0 * p[kWGamma] * std::abs(r) * std::abs(z) - 2.0 * p[kWBeta] * r * z;
  const double dzdot_dr =
      -p[kWGamma] * (r >= 0.0 ? 1.0 : -1.0) * z * std::abs(z) - p[kWBeta] * z * z + p[kWA];
  const double dr_dz = -alpha / damping;
  return {std::max(p[kWK0] / damping, 0.0), std::max(-(dzdot_dz_explicit + dzdot_dr * dr_dz), 0.0)};
}

/// phi(x) = (1 - exp(-x)) / x, with its series near 0 (x >= 0).
template <class T>
T phi1(const T& x) {
  using std::exp;
  if (value_of(x) < 1e-6) return 1.0 - 0.5 * x;
  return (1.0 - exp(-x)) / x;
}

}  // namespace pheno_detail

/// The gains of a field filter u' = -r (u - v) over steps of length h, solved exactly: the half
/// and full step gains h phi1(h r) r. They depend on r and h only, so one simulation (one
/// parameter vector) keeps them and recomputes them only when its step length changes.
template <class T>
struct FieldFilterGains {
  double step = 0.0;  ///< [s] the h of `half` and `full` (0: not computed yet)
  T half{}, full{};
  /// Makes these the gains of step h for the rate rate() (the same at every call).
  template <class Rate>
  void update(double h, const Rate& rate) {
    if (h == step) return;
    const T r = rate();
    half = 0.5 * h * pheno_detail::phi1(T(0.5 * h) * r) * r;
    full = h * pheno_detail::phi1(T(h) * r) * r;
    step = h;
  }
};

/// One step of length h of the damper model from drive `a` (start) through `m` (midpoint):
/// exponential midpoint rule (second order, stable for any h): each state's rate is linearised
/// about the half-step predictor, and the linear equation is solved exactly over the step. The
/// valve force's fast mode (compliance stiffness / slope of the valve map) and the seal's
/// pre-sliding are stiff for an explicit method; this step is not limited by them. `gains` are the
/// field filter's of this simulation.
template <class T>
void damper_step(const T* p, const PhenoDrive& a, const PhenoDrive& m, const PhenoSettings& s,
                 double h, FieldFilterGains<T>& gains, T* x) {
  using namespace pheno_detail;
  // Field and seal: linear in their own state, solved exactly with the midpoint drive.
  const double abs_m = std::sqrt(m.motion * m.motion + s.eps * s.eps) - s.eps;
  gains.update(h, [&] { return T(1.0 / p[kDmTau]); });
  const T u0 = x[2];
  const T u_half = u0 + gains.half * (m.field - u0);
  x[2] = u0 + gains.full * (m.field - u0);
  const T rate_z = abs_m / p[kDmSealSlip];
  x[1] = x[1] + h * phi1(T(h) * rate_z) * (m.motion / p[kDmSealSlip] - rate_z * x[1]);
  // Valve force: predictor half step from the start, then the step linearised at the midpoint.
  // The field the valve sees, and the valve law at it, are computed once for each of the two
  // field states.
  const auto at = [&](const PhenoDrive& d, const T& f, const DamperValveLaw<T>& valve) {
    DamperForceRate<T> r = damper_force_rate_and_decay_at(p, d, s, f, valve);
    if (!(value_of(r.decay) > 0.0)) r.decay = T(0.0);  // a growing mode is not linearised
    return r;
  };
  const DamperValveLaw<T> valve0 = damper_valve_law(p, s, u0),
                          valve_half = damper_valve_law(p, s, u_half);
  const T f0 = x[0];
  const DamperForceRate<T> r0 = at(a, f0, valve0);
  const T f_half = f0 + 0.5 * h * phi1(T(0.5 * h) * r0.decay) * r0.rate;
  const DamperForceRate<T> rm = at(m, f_half, valve_half);
  x[0] = f0 + h * phi1(T(h) * rm.decay) * (rm.rate + rm.decay * (f_half - f0));
}

/// The same step computing its field filter gains first.
template <class T>
void damper_step(const T* p, const PhenoDrive& a, const PhenoDrive& m, const PhenoSettings& s,
                 double h, T* x) {
  FieldFilterGains<T> gains;
  damper_step(p, a, m, s, h, gains, x);
}

/// One step of length h of the modified Bouc-Wen model from drive `a` (start) through `m`
/// (midpoint): the exponential midpoint rule of damper_step (second order, stable for any h). The
/// stiff mode is z's relaxation through the dampers (rate A alpha / (c0 + c1)) and its hysteretic
/// saturation; each state's rate is linearised about the half-step predictor (decay rates in
/// values: any rate gives a consistent scheme, the true one makes it stable). `gains` are the
/// field filter's of this simulation.
template <class T>
void bouc_wen_step(const T* p, const PhenoDrive& a, const PhenoDrive& m, const PhenoSettings& s,
                   double h, FieldFilterGains<T>& gains, T* x) {
  using namespace pheno_detail;
  gains.update(h, [&] { return p[kWEta]; });
  constexpr std::size_t kParams = kWOffset + 1;
  std::array<double, kParams> pv{};
  for (std::size_t k = 0; k < kParams; ++k) pv[k] = value_of(p[k]);
  const auto rates = [&](const PhenoDrive& d, const T* state, T* dxdt) {
    dxdt[0] = bouc_wen_ydot(p, d, state);
    dxdt[1] = bouc_wen_zdot(p, s, T(d.motion) - dxdt[0], state[1]);
  };
  const auto decay = [&](const PhenoDrive& d, const T* state) {
    const double xv[3] = {value_of(state[0]), value_of(state[1]), value_of(state[2])};
    return bouc_wen_decay_rates(pv.data(), d, xv);
  };
  // Field filter: linear, solved exactly with the midpoint drive.
  const T u0 = x[2];
  const T u_half = u0 + gains.half * (m.field - u0);
  const T x0[3] = {x[0], x[1], u0};
  T f0[2], fm[2];
  rates(a, x0, f0);
  const std::array<double, 2> lambda0 = decay(a, x0);
  T half[3] = {x0[0], x0[1], u_half};
  for (int k = 0; k < 2; ++k) half[k] += 0.5 * h * phi1(0.5 * h * lambda0[k]) * f0[k];
  rates(m, half, fm);
  const std::array<double, 2> lambda_m = decay(m, half);
  for (int k = 0; k < 2; ++k)
    x[k] = x0[k] + h * phi1(h * lambda_m[k]) * (fm[k] + lambda_m[k] * (half[k] - x0[k]));
  x[2] = u0 + gains.full * (m.field - u0);
}

/// The same step computing its field filter gains first.
template <class T>
void bouc_wen_step(const T* p, const PhenoDrive& a, const PhenoDrive& m, const PhenoSettings& s,
                   double h, T* x) {
  FieldFilterGains<T> gains;
  bouc_wen_step(p, a, m, s, h, gains, x);
}

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
    case PhenoKind::biviscous:
    case PhenoKind::tanh:
      break;
    case PhenoKind::damper:  // at rest: no valve force, seal centred, field settled
      x[0] = T(0.0);
      x[1] = T(0.0);
      x[2] = T(d.field);
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
      dxdt[0] = ydot;
      dxdt[1] = bouc_wen_zdot(p, s, r, x[1]);
      dxdt[2] = -p[kWEta] * (x[2] - d.field);  // u' = -eta (u - v)
      break;
    }
    case PhenoKind::maxwell: {  // zeta F' + F = Rv m + R(u) tanh(c m)
      T fd = p[kMVisc] * d.motion +
             (p[kMField0] + p[kMField1] * d.field) * tanh(p[kMShape] * d.motion);
      dxdt[0] = (fd - x[0]) / p[kMTau];
      break;
    }
    case PhenoKind::biviscous:
    case PhenoKind::tanh:
      break;
    case PhenoKind::damper:
      dxdt[0] = damper_force_rate(p, d, s, x);
      dxdt[1] = (d.motion - abs_m * x[1]) / p[kDmSealSlip];  // Dahl pre-sliding of the seals
      dxdt[2] = (d.field - x[2]) / p[kDmTau];                // field lag behind the drive
      break;
  }
}

template <class T>
T pheno_output(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s,
               const T* x) {
  using namespace pheno_detail;
  using std::abs;
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
    case PhenoKind::biviscous: {  // pre-yield c_pre m below the yield motion, else Bingham
      const T yield = p[kVYield0] + p[kVYield1] * d.field;
      const T post = p[kVPost0] + p[kVPost1] * d.field;
      const T yield_motion = yield / (p[kVPre] - post);
      const T out = abs(T(d.motion)) <= yield_motion
                        ? p[kVPre] * d.motion
                        : post * d.motion + (d.motion > 0.0 ? yield : -yield);
      return out + p[kVOffset];
    }
    case PhenoKind::tanh:  // c m + k x + F(u) tanh(beta m + delta sign(x)) + f0
      return (p[kTVisc0] + p[kTVisc1] * d.field) * d.motion + p[kTStiff] * d.position +
             (p[kTForce0] + p[kTForce1] * d.field) *
                 tanh(p[kTShape] * d.motion +
                      p[kTLag] * smooth_sign(T(d.position), 1e-2 * s.position_scale)) +
             p[kTOffset];
    case PhenoKind::damper:
      return x[0] + (p[kDmSeal] + p[kDmSeal1] * abs(damper_effective_field(p, x[2]))) * x[1] +
             p[kDmInertance] * d.acceleration + p[kDmGas] * d.position + p[kDmOffset];
  }
  return T(0.0);
}

}  // namespace rheomag::lumped
