#pragma once
// What the Python objects Case and Solution hold: immutable, shared, so a Python object stays
// valid while a solve on another thread reads it.

#include <memory>
#include <string>

#include "case/case_file.hpp"
#include "magnetostatics/solve_problem.hpp"

namespace rheomag::python {

/// A loaded (or edited) case and the file it came from (named in messages).
struct CaseHandle {
  std::shared_ptr<const cases::Case> c;
  std::string path;
};

/// One magnetostatic solve of a case.
struct SolutionHandle {
  std::shared_ptr<const magnetostatics::SolveResult> solved;
  std::string case_name;
};

}  // namespace rheomag::python
