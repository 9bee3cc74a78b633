#include "transient/vtk_series.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <system_error>
#include <utility>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "magnetostatics/report.hpp"
#include "magnetostatics/results.hpp"

namespace rheomag::transient {

namespace {

/// J = -sigma dA/dt per triangle [A/m^2]: the element mean of dA/dt (P2: the mean of the edge
/// midpoints' values, the exact area mean of a quadratic; P1: of the vertices').
std::vector<double> eddy_current_density(const TransientSolver& solver,
                                         const Eigen::VectorXd& rate) {
  const mesh::Mesh& m = solver.statics().mesh();
  const std::vector<double>& sigma = solver.eddy().sigma;
  std::vector<double> j(m.triangles.size(), 0.0);
  if (rate.size() != static_cast<Eigen::Index>(m.nodes.size())) return j;
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    const auto& t = m.triangles[e];
    const double mean = m.order == 2 ? (rate[t[3]] + rate[t[4]] + rate[t[5]]) / 3.0
                                     : (rate[t[0]] + rate[t[1]] + rate[t[2]]) / 3.0;
    j[e] = -sigma[m.region[e]] * mean;
  }
  return j;
}

/// True for a state file name of a series (state_NNNNN.vtu).
bool is_state_file(const std::string& name) {
  if (name.size() != 15 || name.rfind("state_", 0) != 0 || name.substr(11) != ".vtu") return false;
  return std::all_of(name.begin() + 6, name.begin() + 11,
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

}  // namespace

VtkSeries::VtkSeries(std::filesystem::path dir, const TransientSolver& solver, int stride)
    : files_(std::move(dir), "--vtk-series"), solver_(solver), stride_(std::max(1, stride)) {}

void VtkSeries::write(const TransientState& s) {
  if (seen_++ % stride_ == 0) {
    kept_.reset();
    write_now(s);
  } else {
    kept_ = s;
  }
}

void VtkSeries::write_now(const TransientState& s) {
  const magnetostatics::MagnetostaticSolver& statics = solver_.statics();
  char name[32];
  std::snprintf(name, sizeof name, "state_%05d.vtu", count_++);
  magnetostatics::Solution solution;
  solution.currents.assign(statics.problem().circuits.size(), 0.0);
  for (std::size_t c = 0; c < solution.currents.size(); ++c)
    solution.currents[c] = statics.problem().circuits[c].current;
  solution.currents[0] = s.current;
  solution.a = s.a;
  for (int c = 0; c < static_cast<int>(solution.currents.size()); ++c)
    solution.flux_linkage.push_back(statics.circuit_source(c).dot(s.a));
  const auto results = magnetostatics::compute_results(statics, solution);
  mesh::VtuFields eddy;
  const bool axisymmetric = statics.problem().symmetry == cases::Symmetry::axisymmetric;
  eddy.add_cell_scalar(axisymmetric ? "J_phi" : "J_z", eddy_current_density(solver_, s.a_rate));
  files_.write(name, [&](const std::filesystem::path& to) {
    magnetostatics::write_results_vtu(to.string(), statics, solution, results, eddy);
  });
  collection_ << "    <DataSet timestep=\"" << s.time << "\" part=\"0\" file=\"" << name
              << "\"/>\n";
}

void VtkSeries::finish() {
  if (kept_) write_now(*kept_);
  kept_.reset();
  const std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n" +
      collection_.str() + "  </Collection>\n</VTKFile>\n";
  files_.write("series.pvd",
               [&](const std::filesystem::path& to) { write_file_atomically(to, pvd); });
  files_.commit([](const std::string& name) { return is_state_file(name); });
}

}  // namespace rheomag::transient
