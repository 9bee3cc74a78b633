// CachedCostFunction (identify/multistart_fit.hpp): the grey-box fits' wrapper that serves a
// repeated evaluation at the same parameters from its last result. Reference: the wrapped
// automatically differentiated function itself; the cached answers must be bit-identical and the
// wrapped function must run only when the point changes or a Jacobian is first asked for there.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "identify/multistart_fit.hpp"

using rheomag::identify::CachedCostFunction;

namespace {

/// r_i = exp(a t_i) - b at t_i = i / 4, counting its evaluations; fails when a > 10.
struct Exponential {
  int* calls;
  template <class T>
  bool operator()(const T* p, T* r) const {
    using std::exp;
    ++*calls;
    if (p[0] > T(10.0)) return false;
    for (int i = 0; i < 3; ++i) r[i] = exp(p[0] * (0.25 * i)) - p[1];
    return true;
  }
};

struct Evaluation {
  bool ok = false;
  std::array<double, 3> r{};
  std::array<double, 6> j{};
};

Evaluation evaluate(const ceres::CostFunction& f, std::array<double, 2> p, bool jacobian) {
  Evaluation e;
  const double* params[] = {p.data()};
  double* jac[] = {e.j.data()};
  e.ok = f.Evaluate(params, e.r.data(), jacobian ? jac : nullptr);
  return e;
}

TEST(CachedCost, RepeatsAreServedBitIdenticallyWithoutReevaluating) {
  int inner_calls = 0, reference_calls = 0;
  CachedCostFunction cached(
      new ceres::AutoDiffCostFunction<Exponential, 3, 2>(new Exponential{&inner_calls}));
  ceres::AutoDiffCostFunction<Exponential, 3, 2> reference(new Exponential{&reference_calls});
  const std::array<double, 2> p{0.3, 1.5}, q{-0.7, 0.2};

  const Evaluation r0 = evaluate(cached, p, false);  // residuals only: one evaluation
  EXPECT_EQ(inner_calls, 1);
  const Evaluation j0 = evaluate(cached, p, true);  // Jacobian not cached yet: evaluates
  EXPECT_EQ(inner_calls, 2);
  const Evaluation j1 = evaluate(cached, p, true);  // the line search's point accepted: cached
  const Evaluation r1 = evaluate(cached, p, false);
  EXPECT_EQ(inner_calls, 2);
  const Evaluation want = evaluate(reference, p, true);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(r0.r[i], want.r[i]);
    EXPECT_EQ(r1.r[i], want.r[i]);
    EXPECT_EQ(j1.r[i], want.r[i]);
  }
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(j0.j[k], want.j[k]);
    EXPECT_EQ(j1.j[k], want.j[k]);
  }

  const Evaluation jq = evaluate(cached, q, true);  // a new point: evaluates
  EXPECT_EQ(inner_calls, 3);
  const Evaluation want_q = evaluate(reference, q, true);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(jq.j[k], want_q.j[k]);
}

TEST(CachedCost, AFailedEvaluationStaysFailed) {
  int calls = 0;
  CachedCostFunction cached(
      new ceres::AutoDiffCostFunction<Exponential, 3, 2>(new Exponential{&calls}));
  EXPECT_FALSE(evaluate(cached, {20.0, 0.0}, true).ok);
  EXPECT_FALSE(evaluate(cached, {20.0, 0.0}, false).ok);
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(evaluate(cached, {1.0, 0.0}, false).ok);
  EXPECT_EQ(calls, 2);
}

}  // namespace
