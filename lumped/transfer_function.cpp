// Transfer functions in controllable canonical form, integrated by the stiff integrator.

#include "lumped/transfer_function.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "lumped/ode.hpp"

namespace rheomag::lumped {

TransferFunction tf14_paper000() {
  // Table 7 of paper 000: zeros a..n (s^13 .. s^0), poles A..O (s^14 .. s^0).
  return {{-41.8, 5316.1, -127314.3, 21142462.0, 143409991.3, 365489941.0, 730969627.0,
           1111865214.0, 979829670.8, 702601785.7, 205538612.5, 77012779.0, 2555603.7, 776563.5},
          {1.0, 62.2, 5691.3, 247801.3, 6227203.6, 22415111.8, 60951145.0, 103813779.8, 153202135.3,
           128318971.5, 87979344.5, 26846224.5, 9998137.5, 292442.0, 103749.2}};
}

double dc_gain(const TransferFunction& tf) {
  if (tf.den.empty() || tf.den.back() == 0.0) throw InputError("transfer function: den(0) = 0");
  return tf.num.back() / tf.den.back();
}

namespace {

/// x' = A x + B u in controllable canonical form; y = C x.
class CanonicalForm : public OdeSystem {
 public:
  CanonicalForm(const TransferFunction& tf, const std::vector<double>& t,
                const std::vector<double>& u)
      : t_(t), u_(u) {
    const double lead = tf.den.front();
    n_ = tf.den.size() - 1;
    a_.resize(n_);
    for (std::size_t k = 0; k < n_; ++k) a_[k] = tf.den[n_ - k] / lead;  // a_0 .. a_{n-1}
  }
  std::size_t state_size() const override { return n_; }
  std::vector<double> state_scales() const override {
    // x_1 ~ u / a_0; each further state is one more derivative.
    std::vector<double> s(n_);
    for (std::size_t k = 0; k < n_; ++k) s[k] = 1.0 / std::abs(a_[0]);
    return s;
  }
  void derivatives(double t, const double* x, double* dxdt) const override {
    for (std::size_t k = 0; k + 1 < n_; ++k) dxdt[k] = x[k + 1];
    double acc = input(t);
    for (std::size_t k = 0; k < n_; ++k) acc -= a_[k] * x[k];
    dxdt[n_ - 1] = acc;
  }
  double input(double t) const {
    auto it = std::upper_bound(t_.begin(), t_.end(), t);
    if (it == t_.begin()) return u_.front();
    if (it == t_.end()) return u_.back();
    std::size_t k = static_cast<std::size_t>(it - t_.begin()) - 1;
    return u_[k] + (u_[k + 1] - u_[k]) * (t - t_[k]) / (t_[k + 1] - t_[k]);
  }

 private:
  const std::vector<double>& t_;
  const std::vector<double>& u_;
  std::size_t n_ = 0;
  std::vector<double> a_;
};

}  // namespace

std::vector<double> simulate_transfer_function(const TransferFunction& tf,
                                               const std::vector<double>& t,
                                               const std::vector<double>& u) {
  if (tf.den.size() < 2 || tf.den.front() == 0.0 || tf.num.size() >= tf.den.size())
    throw InputError("transfer function: need deg num < deg den and a non-zero leading pole");
  if (t.size() != u.size() || t.size() < 2)
    throw InputError("transfer function: t and u must have the same length >= 2");
  CanonicalForm sys(tf, t, u);
  IntegratorOptions opt;
  opt.abs_tol = 1e-9;
  opt.rel_tol = 1e-8;
  auto states = integrate_stiff(sys, std::vector<double>(sys.state_size(), 0.0), t, opt);
  const std::size_t n = tf.den.size() - 1, m = tf.num.size();
  const double lead = tf.den.front();
  std::vector<double> y(t.size(), 0.0);
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t k = 0; k < m; ++k) y[i] += tf.num[m - 1 - k] / lead * states[i][k];
  (void)n;
  return y;
}

}  // namespace rheomag::lumped
