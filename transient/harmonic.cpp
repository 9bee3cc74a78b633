#include "transient/harmonic.hpp"

#include <Eigen/SparseLU>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"

namespace rheomag::transient {

HarmonicResponse harmonic_response(magnetostatics::MagnetostaticSolver& statics,
                                   const EddyCoefficients& eddy, double frequency,
                                   double bias_current) {
  using Complex = std::complex<double>;
  using ComplexMatrix = Eigen::SparseMatrix<Complex, Eigen::ColMajor, int>;
  const cases::Problem& problem = statics.problem();
  if (problem.circuits.empty())
    throw InputError(problem.geometry.source + ": the case has no circuit to drive");
  if (!(frequency >= 0.0) || !std::isfinite(frequency))
    throw InputError(problem.geometry.source + ": frequency must be finite and >= 0 Hz");
  std::vector<double> currents;
  for (const cases::Circuit& c : problem.circuits) currents.push_back(c.current);
  currents[0] = bias_current;
  const magnetostatics::Solution bias = statics.solve(currents);

  const auto& assembler = statics.assembler();
  magnetostatics::SparseMatrix tangent = assembler.pattern();
  Eigen::VectorXd residual;
  assembler.assemble(bias.a, residual, &tangent);
  const magnetostatics::SparseMatrix eddy_matrix =
      assembler.region_matrix(eddy.sigma, false) + assembler.region_matrix(eddy.kappa, true);
  // The stored lower triangles as full symmetric matrices (complex symmetric, not Hermitian).
  const magnetostatics::SparseMatrix k = tangent.selfadjointView<Eigen::Lower>();
  const magnetostatics::SparseMatrix m = eddy_matrix.selfadjointView<Eigen::Lower>();
  const double omega = 2.0 * std::numbers::pi * frequency;
  const ComplexMatrix system = k.cast<Complex>() + Complex(0.0, omega) * m.cast<Complex>();

  Eigen::SparseLU<ComplexMatrix> lu;
  lu.compute(system);
  if (lu.info() != Eigen::Success)
    throw ConvergenceError(problem.geometry.source + ": sparse LU of the time-harmonic system at " +
                           std::to_string(frequency) + " Hz failed: " + lu.lastErrorMessage());
  const Eigen::VectorXd f = statics.nodes_to_free(statics.circuit_source(0));
  const Eigen::VectorXcd a = lu.solve(f.cast<Complex>());
  if (lu.info() != Eigen::Success || !a.allFinite())
    throw ConvergenceError(problem.geometry.source + ": time-harmonic solve at " +
                           std::to_string(frequency) + " Hz failed");
  HarmonicResponse out;
  out.frequency = frequency;
  out.flux_linkage = f.cast<Complex>().dot(a);  // dot conjugates its first argument (real here)
  out.impedance = Complex(0.0, omega) * out.flux_linkage;
  // Mean power of the eddy currents J = -j omega sigma A: (omega^2 / 2) a^H M a.
  out.eddy_loss = 0.5 * omega * omega * a.dot(m.cast<Complex>() * a).real();
  return out;
}

}  // namespace rheomag::transient
