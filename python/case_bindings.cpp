// Python: rheomag.Case — load, typed edits through the case key API, magnetostatic solve.

#include <cmath>
#include <optional>

#include "case/case_key.hpp"
#include "core/error.hpp"
#include "python/bindings.hpp"
#include "python/handles.hpp"

namespace rheomag::python {

namespace {

/// A Python value as a key value: bool, int, float or str (file units are applied by the caller).
cases::KeyValue key_value(const py::handle& value, const std::string& key) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) return value.cast<long long>();
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  throw InputError("Case.with_: key '" + key + "': expected a number, a bool or a string, got " +
                   std::string(py::str(value.get_type().attr("__name__"))));
}

/// A key's value in SI (a length of a "mm" case in metres), as Python returns it.
py::object si_value(const cases::KeyValue& value, const cases::CaseKey& key) {
  if (const auto* d = std::get_if<double>(&value)) return py::float_(*d * key.si_per_unit);
  if (const auto* i = std::get_if<long long>(&value)) {
    if (key.si_per_unit != 1.0) return py::float_(static_cast<double>(*i) * key.si_per_unit);
    return py::int_(*i);
  }
  if (const auto* b = std::get_if<bool>(&value)) return py::bool_(*b);
  return py::str(std::get<std::string>(value));
}

/// Reads a case or FEMM model and passes the reader's warnings (e.g. a B-H table smoothed as
/// FEMM does) to Python's warnings module.
CaseHandle load(const std::string& path) {
  std::shared_ptr<const cases::Case> c;
  {
    py::gil_scoped_release release;
    c = std::make_shared<const cases::Case>(cases::load_case(path));
  }
  for (const std::string& w : c->problem.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, ("rheomag: " + w).c_str(), 1) != 0)
      throw py::error_already_set();  // warnings filtered as errors
  return {c, path};
}

/// Case.with_: edits given in SI for template lengths (divided by the case's length unit here),
/// other keys as the case file writes them.
CaseHandle with_edits(const CaseHandle& base, const py::dict& edits) {
  std::vector<cases::CaseEdit> list;
  for (const auto& [k, v] : edits) {
    const std::string key = py::str(k);
    cases::CaseEdit edit{cases::resolve_case_key(*base.c, key, base.path + ": Case.with_"),
                         key_value(v, key)};
    if (edit.key.si_per_unit != 1.0) {
      if (const auto* d = std::get_if<double>(&edit.value)) edit.value = *d / edit.key.si_per_unit;
      if (const auto* i = std::get_if<long long>(&edit.value))
        edit.value = static_cast<double>(*i) / edit.key.si_per_unit;
    }
    list.push_back(std::move(edit));
  }
  py::gil_scoped_release release;
  return {std::make_shared<const cases::Case>(cases::with(*base.c, list)), base.path};
}

SolutionHandle solve(const CaseHandle& h, std::optional<double> current) {
  const cases::Problem problem = problem_at_current(h, current);
  py::gil_scoped_release release;
  return {
      std::make_shared<const magnetostatics::SolveResult>(magnetostatics::solve_problem(problem)),
      h.c->name};
}

}  // namespace

cases::Problem problem_at_current(const CaseHandle& h, std::optional<double> current) {
  cases::Problem problem = h.c->problem;
  if (current) {
    if (!std::isfinite(*current)) throw InputError("current: expected a finite current in A");
    if (problem.circuits.empty())
      throw InputError(h.path + ": current given but the case has no circuit");
    for (cases::Circuit& circuit : problem.circuits) circuit.current = *current;
  }
  return problem;
}

py::class_<CaseHandle> bind_case(py::module_& m) {
  return py::class_<CaseHandle>(
             m, "Case",
             "A rheomag case (TOML case file or FEMM .fem model), immutable; edits "
             "return a new Case.")
      .def_static("load", &load, py::arg("path"),
                  "Reads a case file (.toml) or FEMM model (.fem); ValueError on bad input, a "
                  "UserWarning for what the reader changed (a B-H table smoothed as FEMM does).")
      .def_property_readonly("name", [](const CaseHandle& h) { return h.c->name; })
      .def_property_readonly("description", [](const CaseHandle& h) { return h.c->description; })
      .def_property_readonly("path", [](const CaseHandle& h) { return h.path; })
      .def(
          "keys", [](const CaseHandle& h) { return cases::value_keys(*h.c); },
          "Every value key of the case (dotted, template defaults included), sorted.")
      .def(
          "__getitem__",
          [](const CaseHandle& h, const std::string& key) {
            const cases::CaseKey k = cases::resolve_case_key(*h.c, key, h.path);
            return si_value(cases::case_value(*h.c, k), k);
          },
          py::arg("key"), "The value of a key (template lengths in metres).")
      .def("with_", &with_edits, py::arg("edits"),
           "A copy with the edits {key: value} applied through the case key API, e.g. "
           "{'geometry.gap_width': 0.8e-3, 'geometry.turns': 400}: template lengths in metres, "
           "other keys as the case file writes them.")
      .def("solve", &solve, py::arg("current") = py::none(),
           "Magnetostatic solve (GIL released) at the case's currents, or every circuit at "
           "`current` [A]; returns a Solution. ConvergenceError when Newton fails.")
      .def("__repr__", [](const CaseHandle& h) { return "<rheomag.Case '" + h.c->name + "'>"; });
}

}  // namespace rheomag::python
