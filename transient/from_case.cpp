#include "transient/from_case.hpp"

#include <utility>

#include "magnetostatics/solve_problem.hpp"
#include "transient/eddy.hpp"

namespace rheomag::transient {

namespace {

/// The transient solver on `statics` with the eddy coefficients of the case's remedies.
CaseTransient set_up(TransientCaseOptions case_options,
                     magnetostatics::MagnetostaticSolver& statics) {
  auto solver = std::make_unique<TransientSolver>(
      statics, eddy_coefficients(statics.problem(), case_options.remedies));
  return {std::move(case_options), nullptr, std::move(solver)};
}

}  // namespace

CaseTransient transient_from_case(const cases::Case& c) {
  // [transient] first: a bad table is reported before the case is meshed.
  TransientCaseOptions case_options = read_transient_case(c);
  auto statics = magnetostatics::make_solver(c.problem);
  CaseTransient out = set_up(std::move(case_options), *statics);
  out.statics = std::move(statics);
  return out;
}

CaseTransient transient_from_case(const cases::Case& c,
                                  magnetostatics::MagnetostaticSolver& statics) {
  return set_up(read_transient_case(c), statics);
}

TransientOptions step_options(Drive drive, double value, double duration) {
  TransientOptions options;
  options.drive = drive;
  options.value = value;
  options.duration = duration;
  return options;
}

}  // namespace rheomag::transient
