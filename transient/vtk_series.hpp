#pragma once
// A transient run's field as a ParaView time series: one .vtu per recorded state plus the .pvd
// collection that lists them with their times.

#include <filesystem>
#include <sstream>

#include "magnetostatics/solver.hpp"
#include "transient/transient_solver.hpp"

namespace rheomag::transient {

/// Writes every state as DIR/state_NNNNN.vtu plus DIR/series.pvd (ParaView's time series).
class VtkSeries {
 public:
  /// Creates `dir` (InputError naming --vtk-series if it cannot); `statics` gives mesh and
  /// circuits and must outlive the series.
  VtkSeries(std::filesystem::path dir, const magnetostatics::MagnetostaticSolver& statics);

  /// Writes one state's fields (first circuit at the state's current, the others at theirs).
  void write(const TransientState& s);

  /// Writes series.pvd listing every state written.
  void finish();

 private:
  std::filesystem::path dir_;
  const magnetostatics::MagnetostaticSolver& statics_;
  std::ostringstream collection_;
  int count_ = 0;
};

}  // namespace rheomag::transient
