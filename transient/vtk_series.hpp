#pragma once
// A transient run's field as a ParaView time series: one .vtu per recorded state plus the .pvd
// collection that lists them with their times.

#include <filesystem>
#include <optional>
#include <sstream>

#include "core/output_set.hpp"
#include "magnetostatics/solver.hpp"
#include "transient/transient_solver.hpp"

namespace rheomag::transient {

/// Writes the first state, every `stride`-th after it and the last one as DIR/state_NNNNN.vtu
/// plus DIR/series.pvd (ParaView's time series). Each state has the static fields of
/// write_results_vtu and the eddy-current density J_phi (J_z planar) = -sigma dA/dt as a cell
/// array [A/m^2] (the element's mean of dA/dt over the last step; 0 in stranded coils). The
/// files are staged and replace the folder's previous series as a set in finish(): a run that
/// fails or is interrupted leaves the old series whole.
class VtkSeries {
 public:
  /// Creates `dir` (InputError naming --vtk-series if it cannot); `solver` gives mesh, circuits
  /// and conductivities and must outlive the series. `stride` >= 1.
  VtkSeries(std::filesystem::path dir, const TransientSolver& solver, int stride = 1);

  /// Writes one state's fields (first circuit at the state's current, the others at theirs) when
  /// it is due; keeps it otherwise, in case it is the last.
  void write(const TransientState& s);

  /// Writes the last state if it was kept, then series.pvd listing every state written, and
  /// moves the set into the folder (removing the previous series' states beyond the new ones).
  void finish();

  /// Number of .vtu files written so far.
  int files() const { return count_; }

 private:
  void write_now(const TransientState& s);

  OutputSet files_;
  const TransientSolver& solver_;
  int stride_ = 1;
  int seen_ = 0;
  std::optional<TransientState> kept_;
  std::ostringstream collection_;
  int count_ = 0;
};

}  // namespace rheomag::transient
