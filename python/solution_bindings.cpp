// Python: rheomag.Solution, Gap and Mesh — one magnetostatic solve with numpy arrays.

#include <cmath>
#include <cstdio>

#include "magnetostatics/line_integral.hpp"
#include "magnetostatics/report.hpp"
#include "python/bindings.hpp"
#include "python/handles.hpp"

namespace rheomag::python {

namespace {

/// One fluid gap: its statistics (the CLI's JSON entry) and |B|, B_n along its mid-line.
struct GapView {
  py::dict stats;  ///< results_json's gaps[k]
  magnetostatics::LineField line;
};

/// The mesh with per-element fields.
struct MeshView {
  std::shared_ptr<const magnetostatics::SolveResult> solved;
};

/// The CLI's `solve --json` object (without version; to_python adds it).
nlohmann::json solution_json(const SolutionHandle& s) {
  nlohmann::json j = magnetostatics::results_json(*s.solved->solver, s.solved->results);
  j["case"] = s.case_name;
  j["mesh_seconds"] = s.solved->mesh_seconds;
  return j;
}

/// The first circuit's value `get`, None without a circuit or when gauge-dependent.
template <typename Get>
py::object first_circuit(const SolutionHandle& s, Get get) {
  const auto& circuits = s.solved->results.circuits;
  if (circuits.empty() || !circuits.front().gauge_free) return py::none();
  return py::float_(get(circuits.front()));
}

std::vector<GapView> gaps(const SolutionHandle& s) {
  const nlohmann::json j = magnetostatics::results_json(*s.solved->solver, s.solved->results);
  const py::list stats = to_python(j.at("gaps")).cast<py::list>();
  std::vector<GapView> out;
  for (std::size_t k = 0; k < s.solved->results.gaps.size(); ++k) {
    const magnetostatics::GapResult& g = s.solved->results.gaps[k];
    char spec[200];
    std::snprintf(spec, sizeof spec, "%.17g,%.17g:%.17g,%.17g", g.line_start.r, g.line_start.z,
                  g.line_end.r, g.line_end.z);
    magnetostatics::LineField line;
    {
      py::gil_scoped_release release;
      line = magnetostatics::line_field(*s.solved->solver, s.solved->solution, spec,
                                        magnetostatics::kGapLineSamples);
    }
    out.push_back({stats[k].cast<py::dict>(), std::move(line)});
  }
  return out;
}

/// One column of a gap's mid-line samples.
template <typename Field>
py::array_t<double> line_column(const GapView& g, Field field) {
  std::vector<double> values;
  for (const magnetostatics::LineSample& sample : g.line.samples) values.push_back(field(sample));
  return to_numpy(values);
}

/// Rows x columns of doubles from a row-major vector.
py::array_t<double> matrix(const std::vector<double>& values, py::ssize_t columns) {
  py::array_t<double> a = to_numpy(values);
  return a.reshape({static_cast<py::ssize_t>(values.size()) / columns, columns});
}

}  // namespace

void bind_solution(py::module_& m) {
  py::class_<GapView>(m, "Gap", "Flux density in one fluid gap [T] and along its mid-line.")
      .def_property_readonly("name", [](const GapView& g) { return py::object(g.stats["name"]); })
      .def_property_readonly("kind", [](const GapView& g) { return py::object(g.stats["kind"]); })
      .def_property_readonly(
          "B_avg", [](const GapView& g) { return py::object(g.stats["B_avg"]); },
          "|B| averaged over the gap's area [T]")
      .def_property_readonly(
          "B_max_midline", [](const GapView& g) { return py::object(g.stats["B_max_midline"]); },
          "largest |B| along the gap's mid-line [T] (docs/quantities.md)")
      .def_property_readonly(
          "B_max_area", [](const GapView& g) { return py::object(g.stats["B_max_area"]); },
          "largest |B| anywhere in the gap, at the pole corners [T] (docs/quantities.md)")
      .def_property_readonly(
          "Bn_avg", [](const GapView& g) { return py::object(g.stats["Bn_avg"]); },
          "|B_n| (normal to the walls) averaged over the area [T]")
      .def_property_readonly(
          "stats", [](const GapView& g) { return g.stats; }, "the CLI's JSON entry of the gap")
      .def_property_readonly(
          "s", [](const GapView& g) { return line_column(g, [](auto& p) { return p.s; }); },
          "distance along the mid-line [m]")
      .def_property_readonly(
          "r", [](const GapView& g) { return line_column(g, [](auto& p) { return p.r; }); })
      .def_property_readonly(
          "z", [](const GapView& g) { return line_column(g, [](auto& p) { return p.z; }); })
      .def_property_readonly(
          "B", [](const GapView& g) { return line_column(g, [](auto& p) { return p.b; }); },
          "|B| along the mid-line [T]")
      .def_property_readonly(
          "B_n", [](const GapView& g) { return line_column(g, [](auto& p) { return p.b_n; }); },
          "B across the mid-line (its normal) [T]")
      .def("__repr__", [](const GapView& g) {
        return "<rheomag.Gap '" + g.stats["name"].cast<std::string>() + "'>";
      });

  py::class_<MeshView>(m, "Mesh", "The mesh (r, z in metres) with B per element.")
      .def_property_readonly("order",
                             [](const MeshView& v) { return v.solved->solver->mesh().order; })
      .def_property_readonly(
          "nodes",
          [](const MeshView& v) {
            std::vector<double> xy;
            for (const mesh::Point& p : v.solved->solver->mesh().nodes) {
              xy.push_back(p.r);
              xy.push_back(p.z);
            }
            return matrix(xy, 2);
          },
          "(nodes, 2) array of r, z [m] (planar: x, y)")
      .def_property_readonly(
          "triangles",
          [](const MeshView& v) {
            const mesh::Mesh& mesh = v.solved->solver->mesh();
            const auto n = static_cast<py::ssize_t>(mesh.nodes_per_triangle());
            py::array_t<int> a({static_cast<py::ssize_t>(mesh.triangles.size()), n});
            auto out = a.mutable_unchecked<2>();
            for (py::ssize_t t = 0; t < a.shape(0); ++t)
              for (py::ssize_t k = 0; k < n; ++k) out(t, k) = mesh.triangles[t][k];
            return a;
          },
          "(elements, 3 or 6) node indices (P2: three vertices, then the mid-side nodes)")
      .def_property_readonly(
          "region", [](const MeshView& v) { return v.solved->solver->mesh().region; },
          "region index per element")
      .def_property_readonly("region_names",
                             [](const MeshView& v) {
                               std::vector<std::string> names;
                               for (const auto& r : v.solved->solver->problem().geometry.regions)
                                 names.push_back(r.name);
                               return names;
                             })
      .def_property_readonly(
          "B",
          [](const MeshView& v) {
            const auto& r = v.solved->results;
            std::vector<double> b;
            for (std::size_t e = 0; e < r.element_br.size(); ++e) {
              b.push_back(r.element_br[e]);
              b.push_back(r.element_bz[e]);
            }
            return matrix(b, 2);
          },
          "(elements, 2) element-average B_r, B_z [T] (planar: B_x, B_y)")
      .def_property_readonly(
          "B_abs", [](const MeshView& v) { return to_numpy(v.solved->results.element_b); },
          "|B| per element [T]");

  py::class_<SolutionHandle>(m, "Solution", "A magnetostatic solve (SI units).")
      .def_property_readonly(
          "flux_linkage",
          [](const SolutionHandle& s) {
            return first_circuit(s, [](auto& c) { return c.flux_linkage; });
          },
          "first circuit's flux linkage [Wb]")
      .def_property_readonly(
          "inductance",
          [](const SolutionHandle& s) {
            return first_circuit(s, [](auto& c) { return c.inductance; });
          },
          "first circuit's secant inductance [H]")
      .def_property_readonly(
          "incremental_inductance",
          [](const SolutionHandle& s) {
            return first_circuit(s, [](auto& c) { return c.incremental_inductance; });
          },
          "first circuit's dlambda/dI [H]")
      .def_property_readonly(
          "energy", [](const SolutionHandle& s) { return s.solved->results.energy; },
          "stored magnetic energy [J]")
      .def_property_readonly("coenergy",
                             [](const SolutionHandle& s) { return s.solved->results.coenergy; })
      .def_property_readonly(
          "newton_iterations",
          [](const SolutionHandle& s) { return s.solved->results.newton_iterations; })
      .def_property_readonly("gaps", &gaps, "the fluid gaps (list of Gap)")
      .def_property_readonly(
          "mesh", [](const SolutionHandle& s) { return MeshView{s.solved}; },
          "the mesh with numpy nodes, triangles and B per element")
      .def(
          "json", [](const SolutionHandle& s) { return to_python(solution_json(s)); },
          "the dict of `rheomag solve --json` (same keys and numbers)");
}

}  // namespace rheomag::python
