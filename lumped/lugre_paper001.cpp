// Paper 001 (Imaduddin et al.) eqs. 8-9 with Table 3, simulated with the stiff integrator.

#include "lumped/lugre_paper001.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "lumped/ode.hpp"
#include "lumped/smooth.hpp"

namespace rheomag::lumped {

namespace {

constexpr double kMlPerM3 = 1e6;   // Q: m^3/s -> ml/s
constexpr double kPaPerBar = 1e5;  // dp: bar -> Pa
constexpr double kEpsFlow = 1e-3;  // [ml/s] regularisation of |Q| and sgn(Q)|Q|^alpha

/// Piecewise-linear sample of a signal at time tt.
double sample_at(const std::vector<double>& t, const std::vector<double>& v, double tt) {
  auto it = std::upper_bound(t.begin(), t.end(), tt);
  if (it == t.begin()) return v.front();
  if (it == t.end()) return v.back();
  const std::size_t i = static_cast<std::size_t>(it - t.begin()) - 1;
  return v[i] + (v[i + 1] - v[i]) * (tt - t[i]) / (t[i + 1] - t[i]);
}

/// Eq. 9 in the paper's units: z' = Q - a0 |Q| z (z in ml, Q in ml/s).
class LuGrePaper001Ode : public OdeSystem {
 public:
  LuGrePaper001Ode(const std::vector<double>& t, const std::vector<double>& q_ml,
                   const std::vector<double>& current)
      : t_(t), q_(q_ml), i_(current) {}
  std::size_t state_size() const override { return 1; }
  void derivatives(double tt, const double* x, double* dxdt) const override {
    const double q = sample_at(t_, q_, tt);
    const LuGrePaper001Params p = lugre_paper001_params(sample_at(t_, i_, tt));
    dxdt[0] = q - p.a0 * smooth_abs(q, kEpsFlow) * x[0];
  }
  std::vector<double> state_scales() const override { return {1.0}; }

 private:
  const std::vector<double>& t_;
  const std::vector<double>& q_;
  const std::vector<double>& i_;
};

}  // namespace

LuGrePaper001Params lugre_paper001_params(double current) {
  const double i = std::clamp(current, 0.0, 1.0);
  const double i2 = i * i, i3 = i2 * i, i4 = i3 * i, i5 = i4 * i;
  LuGrePaper001Params p;
  p.A = -1.1612 * i3 + 1.397 * i2 + 0.3613 * i + 0.0391;
  p.B = -22.33 * i5 + 181.31 * i4 - 324.92 * i3 + 192.26 * i2 + 7.37 * i + 2.035;
  p.C = 2.268 * i3 + 0.6812 * i2 + 1.1267 * i + 0.0683;
  p.alpha = 3.6414 * i4 - 9.1188 * i3 + 8.032 * i2 - 3.247 * i + 1.2009;
  p.a0 = 1.0;
  return p;
}

std::vector<double> simulate_lugre_paper001(const std::vector<double>& t,
                                            const std::vector<double>& flow,
                                            const std::vector<double>& current) {
  if (t.size() < 2 || flow.size() != t.size() || current.size() != t.size())
    throw InputError("lugre-paper001: needs at least 2 samples of flow and current");
  std::vector<double> q_ml(flow);
  for (double& q : q_ml) q *= kMlPerM3;
  const LuGrePaper001Ode ode(t, q_ml, current);
  IntegratorOptions opt;
  opt.abs_tol = 1e-9;
  opt.rel_tol = 1e-8;
  const auto states = integrate_stiff(ode, {0.0}, t, opt);
  std::vector<double> dp(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    const LuGrePaper001Params p = lugre_paper001_params(current[k]);
    const double z = states[k][0];
    dp[k] = kPaPerBar * ((p.A + p.B) * z + p.C * smooth_signed_power(q_ml[k], p.alpha, kEpsFlow));
  }
  return dp;
}

}  // namespace rheomag::lumped
