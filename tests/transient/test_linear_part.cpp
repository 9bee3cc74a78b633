// The transient step's cached linear part (triangles without a B-H curve and the mixed boundary
// edges, assembled once per run) against the fresh assembly of every triangle at every point:
// residual and step matrix equal to rounding (1e-12 relative to |K| |x|) on a saturating
// problem (the annular valve's CLI run gives the same t63, t90 and iterations, docs/transient.md).

#include <gtest/gtest.h>

#include "magnetostatics/solver.hpp"
#include "tests/transient/cylinder.hpp"
#include "transient/eddy.hpp"
#include "transient/step_system.hpp"

namespace {

using namespace rheomag;
using magnetostatics::ElementSet;
using magnetostatics::SparseMatrix;

Eigen::Map<const Eigen::VectorXd> values_of(const SparseMatrix& m) {
  return {m.valuePtr(), m.nonZeros()};
}

// The static solution at `current` (the steel saturated in part) as the state to assemble at.
Eigen::VectorXd state(magnetostatics::MagnetostaticSolver& statics, double current) {
  std::vector<double> currents;
  for (const cases::Circuit& c : statics.problem().circuits) currents.push_back(c.current);
  currents[0] = current;
  return statics.solve(currents).a;
}

// assemble(linear) + assemble(nonlinear) = assemble(all), residual and tangent.
void expect_sets_add_up(magnetostatics::MagnetostaticSolver& statics, const Eigen::VectorXd& a) {
  const auto& assembler = statics.assembler();
  ASSERT_TRUE(assembler.nonlinear());
  Eigen::VectorXd r_all, r_lin, r_nl;
  SparseMatrix k_all = assembler.pattern(), k_lin = k_all, k_nl = k_all;
  assembler.assemble(a, r_all, &k_all);
  assembler.assemble(a, r_lin, &k_lin, ElementSet::linear);
  assembler.assemble(a, r_nl, &k_nl, ElementSet::nonlinear);
  EXPECT_GT(values_of(k_lin).norm(), 0.0);
  EXPECT_GT(values_of(k_nl).norm(), 0.0);
  EXPECT_LE((r_lin + r_nl - r_all).norm(), 1e-12 * r_lin.norm());
  EXPECT_LE((values_of(k_lin) + values_of(k_nl) - values_of(k_all)).norm(),
            1e-12 * values_of(k_all).norm());
}

// One voltage-driven midpoint step (3 Gauss points) from the state at `from` towards the state
// at `to`: the step system with the cached linear part against the fresh assembly.
void expect_cached_equals_fresh(magnetostatics::MagnetostaticSolver& statics, double from,
                                double to) {
  const transient::EddyCoefficients eddy = transient::eddy_coefficients(statics.problem(), {});
  const auto& assembler = statics.assembler();
  const SparseMatrix damping = transient::eddy_matrix(assembler, eddy.sigma, eddy.kappa);
  const Eigen::VectorXd drive = statics.nodes_to_free(statics.circuit_source(0));
  const Eigen::VectorXd other = Eigen::VectorXd::Zero(drive.size());
  const std::vector<char> conducting(drive.size(), 0);
  const transient::LinearPart linear = transient::linear_part(statics);
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholesky;
  transient::StepOperators::Factor factor;
  transient::StepOperators fresh{&statics,    &damping, &drive,    &other,
                                 &conducting, nullptr,  &cholesky, &factor};
  transient::StepOperators cached = fresh;
  cached.linear = &linear;

  const Eigen::VectorXd x0 = statics.nodes_to_free(state(statics, from));
  const Eigen::VectorXd x1 = statics.nodes_to_free(state(statics, to));
  const double d = 0.5 * std::sqrt(0.6);
  transient::StepSystem::Setup setup;
  setup.x0 = x0;
  setup.i0 = from;
  setup.h = 1e-3;
  setup.voltage = true;
  setup.value = 2.0;
  setup.resistance = 0.5;
  setup.points = {{0.5 - d, 5.0 / 18.0}, {0.5, 8.0 / 18.0}, {0.5 + d, 5.0 / 18.0}};
  transient::StepSystem a(fresh, setup), b(cached, setup);
  Eigen::VectorXd x(x1.size() + 1);
  x << x1, 0.5 * (from + to);
  Eigen::VectorXd r_fresh, r_cached;
  ASSERT_GT(a.residual(x, r_fresh), 0.0);
  b.residual(x, r_cached);
  // Rounding scale of the residual's terms (it is a small difference of terms ~ |K| |x|).
  const double k_norm = values_of(a.step_matrix()).norm();
  const double scale = k_norm * x1.norm();
  EXPECT_LE((r_cached - r_fresh).norm(), 1e-12 * scale);
  EXPECT_LE((values_of(b.step_matrix()) - values_of(a.step_matrix())).norm(), 1e-12 * k_norm);
  EXPECT_NEAR(b.field_work(x), a.field_work(x), 1e-12 * scale * (x1 - x0).norm());
}

// The conducting cylinder with the saturating B-H curve (steel) in its linear winding.
TEST(TransientLinearPart, CylinderCachedEqualsFresh) {
  const test::Cylinder c;
  const cases::Problem problem = c.problem(test::kSaturatingBh);
  const mesh::Mesh mesh = c.mesh(12);
  magnetostatics::MagnetostaticSolver statics(problem, mesh);
  expect_sets_add_up(statics, state(statics, 4.0));
  expect_cached_equals_fresh(statics, 0.0, 4.0);
}

}  // namespace
