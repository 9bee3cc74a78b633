#pragma once
// A case set up for transient runs, in one place: its [transient] table, the static solver of
// its problem and the transient solver with the eddy coefficients of its remedies.

#include <memory>

#include "case/case_file.hpp"
#include "magnetostatics/solver.hpp"
#include "transient/case_options.hpp"
#include "transient/transient_options.hpp"
#include "transient/transient_solver.hpp"

namespace rheomag::transient {

/// A case's transient set-up. `solver` runs on `statics` (owned here) or on the caller's solver.
struct CaseTransient {
  TransientCaseOptions case_options;                             ///< the case's [transient] table
  std::unique_ptr<magnetostatics::MagnetostaticSolver> statics;  ///< null when borrowed
  std::unique_ptr<TransientSolver> solver;
};

/// Reads [transient], meshes the case's problem (magnetostatics::make_solver, no solve) and sets
/// the transient solver up on it. InputError for a bad [transient] table or a case without circuit.
CaseTransient transient_from_case(const cases::Case& c);

/// The same on the caller's static solver of the case (kept alive by the caller).
CaseTransient transient_from_case(const cases::Case& c,
                                  magnetostatics::MagnetostaticSolver& statics);

/// Options of one step of the first circuit: `drive` to `value` (A or V) over `duration` [s],
/// every other setting at its default.
TransientOptions step_options(Drive drive, double value, double duration);

}  // namespace rheomag::transient
