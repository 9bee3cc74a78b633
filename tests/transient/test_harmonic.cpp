// The time-harmonic limit: the conducting cylinder in a long solenoid at 10 and 50 Hz against
// the analytic Bessel solution and against FEMM's harmonic solver (xfemm).

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <numbers>

#include "magnetostatics/solver.hpp"
#include "tests/transient/cylinder.hpp"
#include "transient/harmonic.hpp"

namespace {

using namespace rheomag;
using Complex = std::complex<double>;

double degrees(Complex z) {
  return std::arg(z) * 180.0 / std::numbers::pi;
}

Complex rheomag_flux_linkage(const test::Cylinder& c, double frequency) {
  magnetostatics::MagnetostaticSolver statics(c.problem(), c.mesh(48));
  return transient::harmonic_response(statics, transient::eddy_coefficients(statics.problem(), {}),
                                      frequency)
      .flux_linkage;
}

// Peer: xfemm (FEMM 4.2's fsolver; public repository Reoptimize-Systems/xfemm, commit 35baec4)
// on the same geometry as a FEMM .fem model: axisymmetric, mm, cylinder r < 10, 0 < z < 2
// (mu_r 1000, Sigma 5 MS/m), winding 10 < r < 10.5 (10 turns, series circuit "coil", 1 A), no
// boundary condition (Neumann) but the axis, mesh size 0.05 mm (0.1 mm changes the values by
// < 1e-4); mo_getcircuitproperties("coil") flux linkage [Wb] at 1 A:
//   10 Hz: 4.461632667e-3 - 3.928101211e-3 j,   50 Hz: 1.988941193e-3 - 1.885822046e-3 j.
// Tolerances: |lambda| 0.1 %, phase 0.02 degrees (xfemm is P1 on its own mesh, rheomag P2 on 48
// graded elements in r; measured 2e-5 and 0.003 degrees). Analytic (infinite cylinder, Bessel
// series): 1e-4 and 0.005 degrees (measured 1e-7).
struct Reference {
  double frequency;
  Complex xfemm;
};

TEST(TransientHarmonic, CylinderMatchesBesselAndXfemmAt10And50Hz) {
  const test::Cylinder c;
  const Reference references[] = {{10.0, {4.461632667e-3, -3.928101211e-3}},
                                  {50.0, {1.988941193e-3, -1.885822046e-3}}};
  for (const Reference& ref : references) {
    const Complex fe = rheomag_flux_linkage(c, ref.frequency);
    const Complex exact = c.harmonic_flux_linkage(ref.frequency);
    std::cout.precision(7);
    std::cout << ref.frequency << " Hz: |lambda| rheomag " << std::abs(fe) << " Wb/A, phase "
              << degrees(fe) << " deg; Bessel " << std::abs(exact) << ", " << degrees(exact)
              << "; xfemm " << std::abs(ref.xfemm) << ", " << degrees(ref.xfemm) << "\n";
    EXPECT_NEAR(std::abs(fe) / std::abs(exact), 1.0, 1e-4) << ref.frequency;
    EXPECT_NEAR(degrees(fe), degrees(exact), 0.005) << ref.frequency;
    EXPECT_NEAR(std::abs(fe) / std::abs(ref.xfemm), 1.0, 1e-3) << ref.frequency;
    EXPECT_NEAR(degrees(fe), degrees(ref.xfemm), 0.02) << ref.frequency;
  }
}

// The zero-frequency limit is the static inductance, and the mean eddy power equals
// Re(j omega lambda) |i|^2 / 2 (the circuit's view of the same loss), 1e-9.
TEST(TransientHarmonic, StaticLimitAndLossAgree) {
  const test::Cylinder c;
  magnetostatics::MagnetostaticSolver statics(c.problem(), c.mesh(24));
  const auto eddy = transient::eddy_coefficients(statics.problem(), {});
  const auto dc = transient::harmonic_response(statics, eddy, 0.0);
  const double static_lambda = statics.solve({1.0}).flux_linkage[0];
  EXPECT_NEAR(dc.flux_linkage.real() / static_lambda, 1.0, 1e-9);
  EXPECT_EQ(dc.flux_linkage.imag(), 0.0);
  const auto ac = transient::harmonic_response(statics, eddy, 50.0);
  EXPECT_NEAR(ac.eddy_loss / (0.5 * ac.impedance.real()), 1.0, 1e-9);
  EXPECT_GT(ac.eddy_loss, 0.0);
  EXPECT_THROW(transient::harmonic_response(statics, eddy, -1.0), InputError);
}

}  // namespace
