// Composition of the lumped blocks into one OdeSystem per rig, and its simulation.

#include "lumped/rig_model.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "lumped/ode.hpp"
#include "lumped/ode_grid.hpp"
#include "lumped/smooth.hpp"

namespace rheomag::lumped {

bool parse_rig_kind(const std::string& name, RigKind& kind) {
  const std::optional<RigKind> found = kRigKindNames.find(name);
  if (found) kind = *found;
  return found.has_value();
}

std::string rig_kind_name(RigKind kind) {
  return std::string(kRigKindNames.name(kind));
}

std::vector<std::string> rig_drive_columns(const RigSpec& spec) {
  std::vector<std::string> cols;
  if (spec.kind != RigKind::coil_bench) cols.push_back("velocity");
  switch (spec.driver_mode) {
    case DriverMode::current_source:
      cols.push_back("current");
      break;
    case DriverMode::voltage:
      cols.push_back(spec.voltage_column);
      break;
    case DriverMode::current_pi:
      cols.push_back("current_cmd");
      break;
  }
  return cols;
}

std::string rig_output_column(const RigSpec& spec) {
  switch (spec.kind) {
    case RigKind::damper:
      return "force";
    case RigKind::coil_bench:
      return "current";
    default:
      return "pressure";
  }
}

namespace {

/// The drive signals a rig reads, by role.
enum class Drive { velocity, current, voltage, current_cmd };

/// Piecewise-linear drive signals with their segment slopes. Successive lookups are near each
/// other in time, so the last segment found is tried first (one instance per simulation).
struct DriveInputs {
  const std::vector<double>* t = nullptr;
  const std::vector<double>* columns[4] = {nullptr, nullptr, nullptr, nullptr};
  bool held[4] = {false, false, false, false};  ///< RigSpec::held_drives, by role
  mutable std::size_t hint = 0;
  /// Value and slope of drive `which` at time tt.
  std::pair<double, double> at(Drive which, double tt) const {
    const auto& v = *columns[static_cast<int>(which)];
    const auto& ts = *t;
    const std::size_t k = segment(tt);
    const double slope = (v[k + 1] - v[k]) / (ts[k + 1] - ts[k]);
    if (tt <= ts.front()) return {v.front(), slope};
    if (tt >= ts.back()) return {v.back(), slope};
    if (held[static_cast<int>(which)]) {
      const double ramp = kHeldStepFraction * (ts[k + 1] - ts[k]);
      const double from = ts[k + 1] - ramp;
      if (tt < from) return {v[k], 0.0};
      return {v[k] + (v[k + 1] - v[k]) * (tt - from) / ramp, (v[k + 1] - v[k]) / ramp};
    }
    return {v[k] + slope * (tt - ts[k]), slope};
  }
  /// Index k of the segment [t_k, t_k+1) holding tt (clamped to the first and last segment).
  std::size_t segment(double tt) const {
    const auto& ts = *t;
    const std::size_t last = ts.size() - 2;
    std::size_t k = std::min(hint, last);
    if (ts[k] <= tt && (k == last || tt < ts[k + 1])) return k;
    if (k < last && ts[k + 1] <= tt && (k + 1 == last || tt < ts[k + 2])) return hint = k + 1;
    auto it = std::upper_bound(ts.begin(), ts.end(), tt);
    k = it == ts.begin() ? 0 : std::min<std::size_t>(it - ts.begin() - 1, last);
    return hint = k;
  }
};

/// Every signal of the chain at one instant (the algebraic part y = g(x, u)).
struct RigSignals {
  double voltage = 0, current = 0, flux = 0, temperature = 20, field_current = 0;
  double valve_current = 0, flow_in = 0, flow = 0, pressure = 0, force = 0, velocity = 0;
  double fluid_temperature_rise = 0;
};

/// The composed rig as an OdeSystem; state indices are assigned to the enabled blocks.
class RigSystem : public OdeSystem {
 public:
  RigSystem(const RigSpec& spec, const DriveInputs& in) : s_(spec), in_(in) {
    const bool coil_dynamic = spec.driver_mode != DriverMode::current_source;
    if (coil_dynamic) {
      if (spec.magnetic_hysteresis) {
        i_current_ = add(1.0);
        i_flux_ = add(0.1);
      } else if (spec.coil.nonlinear()) {
        i_flux_ = add(0.1);
      } else if (spec.coil.inductance > 0.0) {
        i_current_ = add(1.0);
      }
      if (spec.driver_mode == DriverMode::current_pi) i_integral_ = add(0.01);
    } else if (spec.magnetic_hysteresis) {
      i_flux_ = add(0.1);  // Duhem between the imposed current and the field (paper 004 eq. 2)
    }
    if (spec.coil_heating) i_temperature_ = add(50.0);
    if ((spec.eddy_time_constant && *spec.eddy_time_constant > 0) || spec.predicted_eddy_lag)
      i_eddy_ = add(1.0);
    if (spec.mr_response_time && *spec.mr_response_time > 0) i_mr_ = add(1.0);
    if (spec.kind != RigKind::coil_bench) {
      if (spec.compressibility) {
        // Chamber states are stored fluid volumes, so the total is conserved exactly by the
        // integrator (pressures follow from ChamberBlock::pressure_at); scale: 1 MPa's worth.
        const double scale =
            spec.compressibility->stored_volume(spec.compressibility->precharge + 1e6);
        i_p1_ = add(scale);
        i_p2_ = add(scale);
        if (spec.inertance) i_flow_ = add(1e-5);
      }
      if (spec.fluid_heating) i_fluid_ = add(1.0);
    }
  }
  std::size_t state_size() const override { return scales_.size(); }
  std::vector<double> state_scales() const override { return scales_; }

  std::vector<double> initial_state() const {
    std::vector<double> x(scales_.size(), 0.0);
    const double t0 = in_.t->front();
    if (i_temperature_ >= 0) x[i_temperature_] = s_.coil_heating->ambient_c;
    // Electrical states start at the DC operating point of the first sample.
    RigSignals sig;
    if (s_.driver_mode == DriverMode::current_source) {
      sig.current = in_.at(Drive::current, t0).first;
    } else if (s_.driver_mode == DriverMode::voltage) {
      sig.current = s_.driver.gain * in_.at(Drive::voltage, t0).first /
                    s_.coil.resistance(temperature(x.data()));
    } else {
      sig.current = in_.at(Drive::current_cmd, t0).first;
      if (i_integral_ >= 0 && s_.driver.ki > 0)
        x[i_integral_] = sig.current * s_.coil.resistance(temperature(x.data())) / s_.driver.ki;
    }
    if (i_current_ >= 0) x[i_current_] = sig.current;
    if (i_flux_ >= 0)
      x[i_flux_] = s_.magnetic_hysteresis ? s_.magnetic_hysteresis->b1 *
                                                std::tanh(s_.magnetic_hysteresis->b2 * sig.current)
                                          : s_.coil.flux_of_current(sig.current);
    const double field = field_current(x.data(), sig.current);
    if (i_eddy_ >= 0) x[i_eddy_] = field;
    if (i_mr_ >= 0) x[i_mr_] = field;
    return x;
  }

  void derivatives(double t, const double* x, double* dxdt) const override {
    RigSignals sig;
    evaluate(t, x, dxdt, sig);
  }

  /// The algebraic signals at (t, x); writes x' too when dxdt is not null.
  void evaluate(double t, const double* x, double* dxdt, RigSignals& sig) const {
    std::vector<double> scratch;
    if (!dxdt) {
      scratch.resize(scales_.size());
      dxdt = scratch.data();
    }
    std::fill(dxdt, dxdt + scales_.size(), 0.0);
    const double temp = temperature(x);
    sig.temperature = temp;
    const double resistance = s_.coil.resistance(temp);
    // Driver and coil.
    double voltage = 0.0;
    if (s_.driver_mode == DriverMode::current_source) {
      const auto [current, rate] = in_.at(Drive::current, t);
      sig.current = current;
      voltage = sig.current * resistance;
      if (i_flux_ >= 0) {  // Duhem: dlambda/dt = di/dt * dlambda/di along sign(di/dt)
        dxdt[i_flux_] = rate * s_.magnetic_hysteresis->incremental_inductance(
                                   current, x[i_flux_], rate > 0 ? 1.0 : -1.0);
        sig.flux = x[i_flux_];
      }
    } else {
      double current = 0.0;
      if (i_current_ >= 0)
        current = x[i_current_];
      else if (i_flux_ >= 0)
        current = s_.coil.current_of_flux(x[i_flux_]);
      if (s_.driver_mode == DriverMode::voltage) {
        voltage = s_.driver.gain * in_.at(Drive::voltage, t).first;
      } else {
        const double command = in_.at(Drive::current_cmd, t).first;
        const double error = i_current_ >= 0 || i_flux_ >= 0 ? command - current : 0.0;
        const double raw = s_.driver.kp * error + s_.driver.ki * x[i_integral_];
        voltage = s_.driver.saturate(raw);
        // Back-calculation acts only beyond the limit, so the loop has no steady error inside it.
        const double limited = std::clamp(raw, -s_.driver.voltage_limit, s_.driver.voltage_limit);
        dxdt[i_integral_] = error + (limited - raw) / std::max(s_.driver.kp, 1e-12);
      }
      if (i_current_ < 0 && i_flux_ < 0) current = voltage / resistance;  // resistive coil
      sig.current = current;
      const double excess = voltage - current * resistance;  // = dlambda/dt
      if (s_.magnetic_hysteresis) {
        // Paper 004 eqs. 1-3: sign(di/dt) = sign(u - iR) while dlambda/di > 0.
        const double direction = smooth_sign(excess, 1e-3 * std::max(std::abs(voltage), 1e-3));
        const double slope =
            s_.magnetic_hysteresis->incremental_inductance(current, x[i_flux_], direction);
        dxdt[i_current_] = excess / slope;
        dxdt[i_flux_] = excess;
      } else if (i_flux_ >= 0) {
        dxdt[i_flux_] = excess;
      } else if (i_current_ >= 0) {
        dxdt[i_current_] = excess / s_.coil.inductance;
      }
      if (i_flux_ >= 0) sig.flux = x[i_flux_];
    }
    if (!s_.magnetic_hysteresis && s_.coil.inductance > 0 && !s_.coil.nonlinear())
      sig.flux = s_.coil.inductance * sig.current;
    sig.voltage = voltage;
    if (i_temperature_ >= 0)
      dxdt[i_temperature_] = s_.coil_heating->rate(sig.current * sig.current * resistance, temp);
    // Field chain: magnetising current -> eddy lag -> MR response lag.
    sig.field_current = field_current(x, sig.current);
    double field = sig.field_current;
    if (i_eddy_ >= 0) {
      const double tau =
          s_.predicted_eddy_lag ? s_.predicted_eddy_lag->at(field) : *s_.eddy_time_constant;
      dxdt[i_eddy_] = (field - x[i_eddy_]) / tau;
      field = x[i_eddy_];
    }
    if (i_mr_ >= 0) {
      dxdt[i_mr_] = (field - x[i_mr_]) / *s_.mr_response_time;
      field = x[i_mr_];
    }
    sig.valve_current = field;
    if (s_.kind == RigKind::coil_bench) return;
    // Hydraulics.
    const auto [velocity, acceleration] = in_.at(Drive::velocity, t);
    sig.velocity = velocity;
    sig.flow_in = s_.piston_area * velocity;
    const double viscous = i_fluid_ >= 0 ? s_.fluid_heating->viscous_factor(x[i_fluid_]) : 1.0;
    double valve_drop = 0.0;  // the valve's own pressure drop, whose dp Q heats the fluid
    if (!s_.compressibility) {
      sig.flow = sig.flow_in;
      sig.pressure = valve_drop = s_.valve.pressure_drop(sig.flow, field, viscous);
      if (s_.inertance) sig.pressure += *s_.inertance * s_.piston_area * acceleration;
    } else {
      const double p1 = s_.compressibility->pressure_at(x[i_p1_]);
      const double p2 = s_.compressibility->pressure_at(x[i_p2_]);
      sig.pressure = valve_drop = p1 - p2;
      if (i_flow_ >= 0) {
        sig.flow = x[i_flow_];
        valve_drop = s_.valve.pressure_drop(sig.flow, field, viscous);
        dxdt[i_flow_] = (sig.pressure - valve_drop) / *s_.inertance;
      } else {
        sig.flow = s_.valve.flow(sig.pressure, field, viscous);
      }
      dxdt[i_p1_] = sig.flow_in - sig.flow;
      dxdt[i_p2_] = sig.flow - sig.flow_in;
    }
    if (i_fluid_ >= 0) {
      sig.fluid_temperature_rise = x[i_fluid_];
      dxdt[i_fluid_] = s_.fluid_heating->rate(valve_drop * sig.flow, x[i_fluid_]);
    }
    sig.force = s_.piston_area * sig.pressure + s_.gas_force;
    if (s_.coulomb_force)
      sig.force += *s_.coulomb_force * smooth_sign(velocity, s_.friction_velocity);
  }

 private:
  int add(double scale) {
    scales_.push_back(scale);
    return static_cast<int>(scales_.size()) - 1;
  }
  double temperature(const double* x) const {
    return i_temperature_ >= 0 ? x[i_temperature_] : 20.0;
  }
  /// Current that magnetises the core: the coil current, or flux / (flux per ampere) with Duhem.
  double field_current(const double* x, double current) const {
    if (s_.magnetic_hysteresis && i_flux_ >= 0 && s_.magnetic_hysteresis->flux_per_ampere > 0)
      return x[i_flux_] / s_.magnetic_hysteresis->flux_per_ampere;
    return current;
  }

  const RigSpec& s_;
  const DriveInputs& in_;
  std::vector<double> scales_;
  int i_current_ = -1, i_flux_ = -1, i_integral_ = -1, i_temperature_ = -1, i_eddy_ = -1,
      i_mr_ = -1, i_p1_ = -1, i_p2_ = -1, i_flow_ = -1, i_fluid_ = -1;
};

/// Steps per sample interval of the fixed grid: spec.grid_substeps, and grid_edge_substeps where a
/// drive input changes by more than 5 % of its range within one interval (a current or command
/// edge, whose transient and ramp a single step would smear) and by more than ten times its
/// median change per interval (so that a drive's noise, e.g. on a constant velocity, is no edge).
std::vector<int> grid_of(const RigSpec& spec, const DriveInputs& in) {
  const auto& t = *in.t;
  // Compliance and inertance together make an LC circuit that rings at kHz with oil: one step
  // per sample would damp that ringing away, grid_edge_substeps everywhere follow it.
  const int base = spec.compressibility && spec.inertance
                       ? std::max(spec.grid_substeps, spec.grid_edge_substeps)
                       : spec.grid_substeps;
  std::vector<int> steps(t.size() - 1, base);
  for (const auto* column : in.columns) {
    if (!column) continue;
    const auto [lo, hi] = std::minmax_element(column->begin(), column->end());
    std::vector<double> change(t.size() - 1);
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      change[k] = std::abs((*column)[k + 1] - (*column)[k]);
    const auto mid = change.begin() + static_cast<std::ptrdiff_t>(change.size() / 2);
    std::nth_element(change.begin(), mid, change.end());
    const double jump = std::max(0.05 * (*hi - *lo), 10.0 * *mid);
    if (!(jump > 0.0)) continue;
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      if (std::abs((*column)[k + 1] - (*column)[k]) > jump)
        steps[k] = std::max(base, spec.grid_edge_substeps);
  }
  return steps;
}

}  // namespace

Recording simulate_rig(const RigSpec& spec_in, const Recording& drive) {
  if (drive.t.size() < 2) throw InputError("simulate: the drive needs at least 2 samples");
  DriveInputs in;
  in.t = &drive.t;
  if (spec_in.kind != RigKind::coil_bench)
    in.columns[static_cast<int>(Drive::velocity)] = &drive.column("velocity");
  switch (spec_in.driver_mode) {
    case DriverMode::current_source:
      in.columns[static_cast<int>(Drive::current)] = &drive.column("current");
      break;
    case DriverMode::voltage:
      in.columns[static_cast<int>(Drive::voltage)] = &drive.column(spec_in.voltage_column);
      break;
    case DriverMode::current_pi:
      in.columns[static_cast<int>(Drive::current_cmd)] = &drive.column("current_cmd");
      break;
  }
  for (const auto& column : spec_in.held_drives) {
    if (column == "velocity") in.held[static_cast<int>(Drive::velocity)] = true;
    if (column == "current") in.held[static_cast<int>(Drive::current)] = true;
    if (column == spec_in.voltage_column) in.held[static_cast<int>(Drive::voltage)] = true;
    if (column == "current_cmd") in.held[static_cast<int>(Drive::current_cmd)] = true;
  }
  if (spec_in.inertance && *spec_in.inertance <= 0)
    throw InputError("simulate: inertance must be > 0");
  if (spec_in.kind != RigKind::coil_bench && !spec_in.valve.case_file.empty() &&
      !spec_in.valve.chain)
    throw InputError("simulate: the valve names the FE case " + spec_in.valve.case_file +
                     " but carries no tabulated map (coupling::with_chain_map fills it)");
  const RigSpec& spec = spec_in;
  RigSystem system(spec, in);
  IntegratorOptions opt;
  opt.abs_tol = 1e-7;
  opt.rel_tol = 1e-6;
  // A Duhem state driven by an imposed current moves only while the current ramps between two
  // samples: steps no longer than half a sample interval so that no ramp is stepped over.
  if (spec.magnetic_hysteresis && spec.driver_mode == DriverMode::current_source) {
    double spacing = drive.t.back() - drive.t.front();
    for (std::size_t k = 1; k < drive.t.size(); ++k)
      spacing = std::min(spacing, drive.t[k] - drive.t[k - 1]);
    opt.max_step = 0.5 * spacing;
  }
  auto states = spec.grid_substeps > 0
                    ? integrate_on_grid(system, system.initial_state(), drive.t, grid_of(spec, in))
                    : integrate_stiff(system, system.initial_state(), drive.t, opt);

  Recording rec;
  rec.t = drive.t;
  for (const auto& c : rig_drive_columns(spec)) rec.columns[c] = drive.column(c);
  if (drive.columns.count("displacement") && spec.kind != RigKind::coil_bench)
    rec.columns["displacement"] = drive.column("displacement");
  std::vector<double> current, voltage, flux, temp, flow, pressure, force, fluid_rise;
  for (std::size_t k = 0; k < drive.t.size(); ++k) {
    RigSignals sig;
    system.evaluate(drive.t[k], states[k].data(), nullptr, sig);
    current.push_back(sig.current);
    voltage.push_back(sig.voltage);
    flux.push_back(sig.flux);
    temp.push_back(sig.temperature);
    flow.push_back(sig.flow);
    pressure.push_back(sig.pressure);
    force.push_back(sig.force);
    fluid_rise.push_back(sig.fluid_temperature_rise);
  }
  rec.columns["current"] = current;
  if (spec.driver_mode != DriverMode::current_source) {
    rec.columns["voltage"] = voltage;
    if (spec.magnetic_hysteresis || spec.coil.nonlinear() || spec.coil.inductance > 0)
      rec.columns["flux_linkage"] = flux;
  }
  if (spec.coil_heating) rec.columns["temperature"] = temp;
  if (spec.kind != RigKind::coil_bench) {
    rec.columns["flow"] = flow;
    rec.columns["pressure"] = pressure;
    if (spec.kind == RigKind::damper) rec.columns["force"] = force;
    if (spec.fluid_heating) rec.columns["fluid_temperature_rise"] = fluid_rise;
  }
  // Sensor noise, seeded.
  std::mt19937 rng(spec.noise_seed);
  for (const auto& [column, sigma] : spec.sensor_noise) {
    auto it = rec.columns.find(column);
    if (it == rec.columns.end())
      throw InputError("simulate: [sensor_noise] " + column + " is not a column this rig writes");
    if (!(sigma >= 0)) throw InputError("simulate: [sensor_noise] " + column + " must be >= 0");
    std::normal_distribution<double> noise(0.0, sigma);
    for (double& v : it->second) v += noise(rng);
  }
  rec.meta.description = spec.description;
  rec.meta.drive = rig_drive_columns(spec);
  rec.meta.output = rig_output_column(spec);
  rec.meta.rig.kind = spec.kind;
  if (spec.kind != RigKind::coil_bench) {
    rec.meta.rig.piston_area = spec.piston_area;
    if (spec.compressibility) rec.meta.rig.chamber_volume = spec.compressibility->oil_volume;
  }
  if (spec.kind == RigKind::damper) {
    rec.meta.rig.rod_area = spec.rod_area;
    rec.meta.rig.gas_force = spec.gas_force;
  }
  if (spec.kind != RigKind::coil_bench) rec.meta.valve.case_file = spec.valve.case_file;
  if (spec.kind != RigKind::coil_bench && !spec.valve.yield_current.empty()) {
    rec.meta.valve.yield_current = spec.valve.yield_current;
    rec.meta.valve.yield_pressure = spec.valve.yield_pressure;
    rec.meta.valve.viscous_resistance = spec.valve.viscous_resistance;
  }
  rec.meta.coil.resistance = spec.coil.resistance_20c;
  if (spec.coil.inductance > 0) rec.meta.coil.inductance = spec.coil.inductance;
  return rec;
}

}  // namespace rheomag::lumped
