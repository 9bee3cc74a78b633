#pragma once
// The `valve-chain` grey-box model: the valve's static map from the fluid chain (FE case named in
// the recording's sidecar, tabulated once) with few physical parameters fitted to a recording:
// a yield-stress scale, a viscous scale, a first-order field lag (eddy currents + MR response)
// and, when a piston drives the flow through chambers, the hydraulic capacitance between them.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "identify/greybox.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"
#include "lumped/valve_chain_map.hpp"

namespace rheomag::identify {

/// Options of a valve-chain fit.
struct ValveChainFitOptions {
  std::optional<lumped::SampleRange> train;  ///< samples to fit on; whole recording if empty
  int starts = 3;             ///< multi-start: number of starting points (first = nominal)
  unsigned seed = 1;          ///< seed of the perturbed starting points
  int max_iterations = 50;    ///< Levenberg-Marquardt iterations per start
  double max_substep = 1e-3;  ///< [s] largest RK4 substep inside the fit
  int current_points = 6;     ///< currents of the chain table (0 .. max |current|)
  int flow_points = 12;       ///< flows of the chain table (log-spaced)
};

/// How the model reads a recording.
struct ValveChainSetup {
  std::shared_ptr<const lumped::ChainMapTable> map;
  std::string motion_column;  ///< "velocity" (piston, compliant chambers) or "flow" (valve flow)
  std::string field_column;   ///< "current" or "current_cmd"
  std::string output_column;  ///< "pressure" or "force"
  double piston_area = 0.0;   ///< [m^2] from the sidecar's [rig]
  double gas_force = 0.0;     ///< [N] force output only
  bool compliant = false;     ///< true: dp is a state, C dp/dt = A v - Q(dp)
  double eps_flow = 1e-9;     ///< [m^3/s] width of the smooth sign / plug switch
};

/// Result of fit_valve_chain (parameters: yield_scale, viscous_scale, field_time_constant,
/// hydraulic_capacitance; the last one fixed at 0 without compliance).
struct ValveChainFit {
  std::string model = "valve-chain";
  ValveChainSetup setup;
  std::vector<FittedParameter> params;
  std::vector<double> simulated;  ///< free-run output over the whole recording
  lumped::Metrics train;
  lumped::SampleRange train_range;
  double residual_sigma = 0.0;  ///< [output unit] rms residual on the training samples
  int starts_run = 0;
  int best_start = 0;
  bool converged = false;
};

/// The valve-chain model's parameters, named and in SI units, with `values` (fit order: yield
/// scale, viscous scale, field time constant [s], hydraulic capacitance [m^3/Pa]); the
/// capacitance is held (fixed, 0) unless `compliant`. Standard errors are left empty.
std::vector<FittedParameter> valve_chain_parameters(const std::array<double, 4>& values,
                                                    bool compliant);

/// Builds the setup of `rec`: drive columns, the chain table of the sidecar's [valve] case.
/// InputError when the sidecar names no valve case, lacks the piston area, or the drive has no
/// motion or current column.
ValveChainSetup valve_chain_setup_for(const lumped::Recording& rec,
                                      const ValveChainFitOptions& options);

/// Fits the valve-chain model to `rec` (bounded Ceres LM, multi-start, standard errors).
ValveChainFit fit_valve_chain(const lumped::Recording& rec,
                              const ValveChainFitOptions& options = {});

/// Free-run output [Pa or N] of `setup` with physical parameters `params` (order of the fit) on
/// `rec` (stiff integrator).
std::vector<double> simulate_valve_chain(const lumped::Recording& rec, const ValveChainSetup& setup,
                                         const std::vector<double>& params);

/// Free-run output of a fitted model on another recording of the same device.
std::vector<double> simulate_valve_chain(const lumped::Recording& rec, const ValveChainFit& fit);

}  // namespace rheomag::identify
