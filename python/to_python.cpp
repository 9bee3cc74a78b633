// Conversions of rheomag's results to Python objects (python/bindings.hpp).

#include "core/finite_output.hpp"
#include "core/version.hpp"
#include "python/bindings.hpp"

namespace rheomag::python {

py::object to_python(const nlohmann::json& document) {
  nlohmann::json stamped = document;
  stamp_version(stamped);
  // The CLI's guard: a non-finite number is a ConvergenceError here too.
  const std::string text = finite_json_text(stamped, "the result");
  return py::module_::import("json").attr("loads")(text);
}

py::array_t<double> to_numpy(const std::vector<double>& values) {
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

ProgressCallback progress_to_python(const py::object& callback) {
  if (callback.is_none()) return {};
  // The callable is kept alive by the std::function's copy (released with the GIL held).
  auto holder = std::shared_ptr<py::object>(new py::object(callback), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return [holder](const ProgressEvent& e) {
    py::gil_scoped_acquire gil;
    py::dict event;
    event["stage"] = e.stage;
    event["done"] = e.done;
    event["total"] = e.total;
    event["elapsed"] = e.elapsed;
    event["detail"] = e.detail;
    try {
      (*holder)(event);
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("rheomag progress callback");
    }
  };
}

}  // namespace rheomag::python
