// Python: Case.solve_3d — the case revolved about z (with its [[feature]] cuts) and solved in 3D,
// the dict of `rheomag solve CASE --3d --json`, built by the same library functions.

#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "magnetostatics3d/report3d.hpp"
#include "magnetostatics3d/solve3d.hpp"
#include "python/bindings.hpp"
#include "python/handles.hpp"

namespace rheomag::python {

namespace {

namespace m3 = rheomag::magnetostatics3d;

py::object solve_3d(const CaseHandle& h, std::optional<double> current, const std::string& mesher,
                    const std::string& linear_solver, bool full,
                    const std::optional<std::string>& max_memory, const std::string& vtk,
                    const py::object& progress) {
  const cases::Problem problem = problem_at_current(h, current);
  const m3::Mesher3d kind = m3::kMesher3dNames.parse(mesher, "mesher");
  m3::Solve3dOptions options =
      kind == m3::Mesher3d::swept ? m3::swept_options() : m3::Solve3dOptions{};
  options.force_full = full;
  options.linear = m3::kLinearSolver3dNames.parse(linear_solver, "linear_solver");
  if (max_memory) options.max_memory = parse_memory_size(*max_memory, "max_memory");
  options.progress = progress_to_python(progress);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const m3::Solve3dResult solved =
        m3::solve_problem_3d(problem, m3::read_features(*h.c), options);
    if (!vtk.empty()) m3::write_results_vtu_3d(vtk, solved);
    j = m3::results_json_3d(solved.results);
    j["case"] = h.c->name;
    j["mesh_seconds"] = solved.mesh_seconds;
    if (!vtk.empty()) j["vtk"] = vtk;
  }
  return to_python(j);
}

}  // namespace

void bind_solve_3d(py::class_<CaseHandle>& c) {
  c.def("solve_3d", &solve_3d, py::kw_only(), py::arg("current") = py::none(),
        py::arg("mesher") = "tetgen", py::arg("linear_solver") = "cholmod", py::arg("full") = false,
        py::arg("max_memory") = py::none(), py::arg("vtk") = "", py::arg("progress") = py::none(),
        "3D magnetostatic solve (GIL released) of the case revolved about z with its [[feature]] "
        "cuts (slots, holes, ports, eccentricity; docs/magnetostatics3d.md), at the case's "
        "currents or every circuit at `current` [A]: a wedge when the body is axisymmetric, a "
        "half model when the features allow. mesher 'tetgen' or 'swept', linear_solver "
        "'cholmod' or 'ams', full=True meshes the whole revolution, max_memory ('2G') refuses a "
        "larger mesh before meshing, vtk writes the .vtu. Returns the dict of `rheomag solve "
        "CASE --3d --json`; progress(event: dict) at each stage. ConvergenceError when Newton "
        "fails.");
}

}  // namespace rheomag::python
