#pragma once
// Free run of a phenomenological model (lumped/phenomenological.hpp) with given parameters on the
// drive columns of a recording: how a model reads a recording (GreyboxSetup), the drive series it
// sees, and the reported output (stiff integrator, fixed-step RK4 as the fallback). The grey-box
// fits of identify/ differentiate the same free run (lumped/pheno_free_run.hpp).

#include <string>
#include <vector>

#include "lumped/metrics.hpp"
#include "lumped/phenomenological.hpp"
#include "lumped/recording.hpp"

namespace rheomag::lumped {

/// [s] Largest RK4 substep of a model's free run unless a fit says otherwise.
inline constexpr double kPhenoMaxSubstep = 2.5e-4;

/// How a model reads a recording: which columns drive it and the fixed settings.
struct GreyboxSetup {
  PhenoKind kind = PhenoKind::bingham;
  std::string motion_column;    ///< "velocity" or "flow"
  std::string position_column;  ///< "displacement", or empty (integrated motion)
  std::string field_column;     ///< "command", "current", "current_cmd", or empty
  std::string output_column;    ///< "force" or "pressure"
  double orientation = 1.0;     ///< +1 or -1: model output is multiplied by this
  /// [s] The motion drive (velocity or flow) is read this much later than recorded, v(t + lead),
  /// on the recording's own samples (linear interpolation, the end values held beyond the ends),
  /// while the position, field and output stay as recorded: a velocity column that lags the
  /// displacement and force (a backward difference, a filter); 0: as recorded.
  double motion_lead = 0.0;
  PhenoSettings settings;
};

/// Drive and output samples of one recording as a model sees them.
struct DriveSeries {
  std::vector<double> t, position, motion, field, acceleration, y;
  double period = 0.0;        ///< [s] period of a periodic motion drive, else 0 (drive_period)
  bool mean_removed = false;  ///< the recording's output had its mean removed (output_mean_removed)
  /// Leading samples at rest (leading_rest; 0: none): the model's output is tared to the
  /// recording's mean output `rest_level` over them, as a load cell is zeroed before a test.
  std::size_t rest_samples = 0;
  double rest_level = 0.0;  ///< [output unit] the recording's mean output over the rest samples
  PhenoDrive at(std::size_t i) const { return {position[i], motion[i], field[i], acceleration[i]}; }
  /// Linear interpolation between sample i and i+1 at fraction w in [0, 1].
  PhenoDrive between(std::size_t i, double w) const {
    return {position[i] + w * (position[i + 1] - position[i]),
            motion[i] + w * (motion[i + 1] - motion[i]), field[i] + w * (field[i + 1] - field[i]),
            acceleration[i] + w * (acceleration[i + 1] - acceleration[i])};
  }
};

/// Leading samples of `rec` at rest (leading_rest of its motion) over which a model's output is
/// tared to the recording's (DriveSeries::rest_samples); 0 where the output had its mean removed
/// or is constant (a placeholder column, nothing measured to tare to).
std::size_t tared_rest(const Recording& rec, const GreyboxSetup& setup);

/// The drive and output of `rec` as `setup` reads them, keeping every `step`-th sample.
DriveSeries drive_series(const Recording& rec, const GreyboxSetup& setup, std::size_t step = 1);

/// Root mean square of `v` on the samples `r`.
double rms_on(const std::vector<double>& v, SampleRange r);

/// Model output for reports: rosenbrock4; if it gives up (parameters that make the model
/// extremely stiff), the fixed-step RK4 of the fit (stability-limited substeps) is used instead.
std::vector<double> simulate_for_report(const DriveSeries& d, const GreyboxSetup& setup,
                                        const std::vector<double>& params, double max_substep);

/// Free-run output of `setup` with parameter vector `params` on `rec` (stiff integrator); trailing
/// optional parameters left out (output_smoothing) are 0.
std::vector<double> simulate_pheno(const Recording& rec, const GreyboxSetup& setup,
                                   const std::vector<double>& params);

/// Reads the drive columns of `rec` that `setup` names; fills setup's columns from the sidecar.
GreyboxSetup greybox_setup_for(const Recording& rec, PhenoKind kind);

}  // namespace rheomag::lumped
