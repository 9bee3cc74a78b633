// The Python module rheomag._rheomag: the error mapping and every group of bindings.

#include <pybind11/pybind11.h>

#include "core/blas_threads.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "python/bindings.hpp"

PYBIND11_MODULE(_rheomag, m) {
  namespace py = pybind11;
  m.doc() = "rheomag: FE design of MR valves, dampers and brakes (SI units; docs/python.md)";
  m.attr("__version__") = rheomag::version_text();
  // As the CLI: single-threaded OpenBLAS (unless OPENBLAS_NUM_THREADS says otherwise), so the
  // results equal the CLI's to the last digit and parallel Python threads do not oversubscribe.
  rheomag::prefer_single_threaded_blas();
  // Bad input: ValueError with the CLI's message (what the CLI prints after "rheomag: error: ").
  // A solver that did not converge (and a non-finite result): rheomag.ConvergenceError.
  static py::exception<rheomag::ConvergenceError> convergence(m, "ConvergenceError",
                                                              PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const rheomag::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const rheomag::ConvergenceError& e) {
      convergence(e.what());
    }
  });
  rheomag::python::bind_solution(m);
  auto case_class = rheomag::python::bind_case(m);
  rheomag::python::bind_chain(case_class);
  rheomag::python::bind_solve_3d(case_class);
  rheomag::python::bind_identify(m);
}
