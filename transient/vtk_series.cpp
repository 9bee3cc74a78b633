#include "transient/vtk_series.hpp"

#include <cstdio>
#include <system_error>
#include <utility>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "magnetostatics/report.hpp"
#include "magnetostatics/results.hpp"

namespace rheomag::transient {

VtkSeries::VtkSeries(std::filesystem::path dir, const magnetostatics::MagnetostaticSolver& statics)
    : dir_(std::move(dir)), statics_(statics) {
  std::error_code error;
  std::filesystem::create_directories(dir_, error);
  if (error) throw InputError("--vtk-series: cannot create " + dir_.string());
}

void VtkSeries::write(const TransientState& s) {
  char name[32];
  std::snprintf(name, sizeof name, "state_%05d.vtu", count_++);
  magnetostatics::Solution solution;
  solution.currents.assign(statics_.problem().circuits.size(), 0.0);
  for (std::size_t c = 0; c < solution.currents.size(); ++c)
    solution.currents[c] = statics_.problem().circuits[c].current;
  solution.currents[0] = s.current;
  solution.a = s.a;
  for (int c = 0; c < static_cast<int>(solution.currents.size()); ++c)
    solution.flux_linkage.push_back(statics_.circuit_source(c).dot(s.a));
  const auto results = magnetostatics::compute_results(statics_, solution);
  magnetostatics::write_results_vtu((dir_ / name).string(), statics_, solution, results);
  collection_ << "    <DataSet timestep=\"" << s.time << "\" part=\"0\" file=\"" << name
              << "\"/>\n";
}

void VtkSeries::finish() {
  write_file_atomically(dir_ / "series.pvd",
                        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                        "version=\"0.1\">\n  <Collection>\n" +
                            collection_.str() + "  </Collection>\n</VTKFile>\n");
}

}  // namespace rheomag::transient
