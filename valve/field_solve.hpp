#pragma once
// The FE field of a device case: mesh and solver set up once, then one solve per coil current.
// Shared by the valve, damper and brake chains.

#include <memory>

#include "case/case_file.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::valve {

/// Meshes `c` (its domain closed as `rheomag solve` does) and prepares the solver; no solve.
std::unique_ptr<magnetostatics::MagnetostaticSolver> make_device_solver(const cases::Case& c);

/// A field solved at one current of circuit 0 (the other circuits at their case currents).
struct DeviceField {
  magnetostatics::Solution solution;
  magnetostatics::Results results;
};

/// Solves the field with circuit 0 at `current` [A] (InputError if it is not finite).
DeviceField solve_at_current(magnetostatics::MagnetostaticSolver& solver, double current);

}  // namespace rheomag::valve
