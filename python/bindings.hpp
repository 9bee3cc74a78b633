#pragma once
// The pieces of the Python module rheomag (python/module.cpp): each bind_* adds one group of
// classes and functions to the module; the helpers convert results to Python objects.

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "python/handles.hpp"

namespace rheomag::python {

namespace py = pybind11;

/// Adds Case (load, with_, keys, solve) to the module; returns the class for bind_chain.
py::class_<CaseHandle> bind_case(py::module_& m);

/// Adds Solution, Gap and Mesh (numpy results of one solve) to the module.
void bind_solution(py::module_& m);

/// Adds the steady chain and the transient: Case.valve, Case.damper, Case.brake, Case.transient.
void bind_chain(py::class_<CaseHandle>& case_class);

/// The case's problem with every circuit at `current` [A] when given (InputError for a
/// non-finite current or a case without circuits), else as the case has it.
cases::Problem problem_at_current(const CaseHandle& h, std::optional<double> current);

/// Adds Case.solve_3d: the case revolved about z and solved in 3D (magnetostatics3d).
void bind_solve_3d(py::class_<CaseHandle>& case_class);

/// Adds Recording and fit, fit_family, simulate, diagnose.
void bind_identify(py::module_& m);

/// A JSON document as Python dicts, lists, floats, ints, strings (via Python's json module, so
/// every number is the double nlohmann holds), with "version" added to an object.
py::object to_python(const nlohmann::json& document);

/// A copy of `values` as a 1-D numpy float64 array.
py::array_t<double> to_numpy(const std::vector<double>& values);

/// A C++ progress callback calling the Python callable `callback` (with the GIL) with a dict
/// {stage, done, total, elapsed, detail}; empty for None. An exception the callable raises is
/// reported as unraisable (printed) and the computation goes on.
ProgressCallback progress_to_python(const py::object& callback);

}  // namespace rheomag::python
