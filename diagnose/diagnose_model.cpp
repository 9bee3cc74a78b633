// Baseline rig from a recording's sidecar and the parameter layout of candidate physics.

#include "diagnose/diagnose_model.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/error.hpp"
#include "coupling/rig_chain_map.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/current_path.hpp"
#include "diagnose/diagnose_noise.hpp"

namespace rheomag::diagnose {

using lumped::DriverMode;
using lumped::RigKind;
using lumped::RigSpec;

namespace {

bool has(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

}  // namespace

double median_interval(const std::vector<double>& t) {
  if (t.size() < 2) return 1.0;
  std::vector<double> dt(t.size() - 1);
  for (std::size_t k = 0; k + 1 < t.size(); ++k) dt[k] = t[k + 1] - t[k];
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

namespace {

/// True if `u` steps somewhere (step_intervals).
bool steps(const std::vector<double>& u) {
  return !step_intervals(u).empty();
}

}  // namespace

DiagnosisModel::DiagnosisModel(const lumped::Recording& rec, const ModelBaseline* fitted,
                               DriveSampling sampling, bool current_path)
    : rec_(rec), current_path_wanted_(current_path) {
  if (fitted) {
    from_fitted_model(*fitted);
    return;
  }
  const auto& meta = rec.meta;
  const std::string where = meta.sidecar_path.empty() ? std::string("sidecar") : meta.sidecar_path;
  auto include = [&](const std::string& name, double value, const std::string& unit,
                     const std::string& source) {
    includes_.push_back({name, value, unit, source});
  };
  if (!meta.rig.kind)
    throw InputError(where +
                     ": [rig] kind is not given; expected one of constant_velocity_pump, "
                     "bypass_cylinder, damper, coil_bench; the baseline needs the rig layout");
  base_.kind = *meta.rig.kind;
  const std::string kind_name = lumped::rig_kind_name(base_.kind);
  base_.description = meta.description;
  base_.grid_substeps = kDiagnosisGridSubsteps;
  // Driver: an imposed current, or a voltage-driven coil, or an (ideally tracked) current command.
  if (has(meta.drive, "current")) {
    base_.driver_mode = DriverMode::current_source;
  } else if (has(meta.drive, "voltage") || has(meta.drive, "command")) {
    base_.driver_mode = DriverMode::voltage;
    base_.voltage_column = has(meta.drive, "voltage") ? "voltage" : "command";
    auto gain = meta.rig.extra.find("driver_gain");
    base_.driver.gain = gain != meta.rig.extra.end() ? gain->second : 1.0;
    if (gain != meta.rig.extra.end())
      include("driver_gain", gain->second, "V/V", "sidecar [rig] driver_gain");
    if (!meta.coil.resistance)
      throw InputError(where +
                       ": [coil] resistance is missing; the baseline of a voltage-driven "
                       "coil needs it to turn voltage into current");
  } else if (has(meta.drive, "current_cmd")) {
    // Ideal current control: the coil current equals the command.
    base_.driver_mode = DriverMode::current_source;
    rec_.columns["current"] = rec.column("current_cmd");
  } else {
    // No coil input recorded: the field is taken as constant and the static map's top current
    // stands for it (the calibrated yield scale absorbs the actual level).
    if (meta.valve.yield_current.empty() && meta.valve.case_file.empty())
      throw InputError(where +
                       ": [recording] drive names no coil input (current, current_cmd, "
                       "voltage or command) and [valve] has no yield_current table");
    base_.driver_mode = DriverMode::current_source;
    rec_.columns["current"].assign(
        rec.t.size(), meta.valve.yield_current.empty() ? 1.0 : meta.valve.yield_current.back());
    constant_field_ = true;
  }
  const bool voltage_driven = base_.driver_mode == DriverMode::voltage;
  if (meta.coil.resistance) {
    base_.coil.resistance_20c = *meta.coil.resistance;
    include("coil_resistance", *meta.coil.resistance, "ohm",
            voltage_driven ? "sidecar [coil] resistance (turns voltage into current)"
                           : "sidecar [coil] resistance (no effect: the current is imposed)");
  }
  // Everything the sidecar states is in the baseline: a stated inductance makes the coil an
  // L-R circuit, and coil_inductance is then the inductance beyond it.
  base_.coil.inductance = 0.0;
  if (meta.coil.inductance && *meta.coil.inductance > 0.0) {
    if (voltage_driven) base_.coil.inductance = *meta.coil.inductance;
    include("coil_inductance", *meta.coil.inductance, "H",
            voltage_driven ? "sidecar [coil] inductance (L-R coil)"
                           : "sidecar [coil] inductance (no effect: the current is imposed)");
  }
  sample_interval_ = median_interval(rec.t);
  if (base_.kind != RigKind::coil_bench) {
    if (!has(meta.drive, "velocity"))
      throw InputError(where + ": [recording] drive must include velocity for a " + kind_name +
                       " rig");
    if (!meta.rig.piston_area)
      throw InputError(where +
                       ": [rig] piston_area is missing; the baseline needs it to turn "
                       "velocity into flow");
    base_.piston_area = *meta.rig.piston_area;
    include("piston_area", base_.piston_area, "m^2", "sidecar [rig] piston_area");
    for (double v : rec_.column("velocity"))
      peak_flow_ = std::max(peak_flow_, std::abs(v) * base_.piston_area);
    if (!meta.valve.yield_current.empty() && !meta.valve.yield_pressure.empty()) {
      if (!meta.valve.viscous_resistance)
        throw InputError(where + ": [valve] viscous_resistance is missing; the baseline needs it");
      base_.valve.yield_current = meta.valve.yield_current;
      base_.valve.yield_pressure = meta.valve.yield_pressure;
      base_.valve.viscous_resistance = *meta.valve.viscous_resistance;
      // A table states a Bingham line; the gap's real law bends below it (the exact slit law
      // has the line as its asymptote): the knee's shape is a nuisance where a yield shows and
      // the recorded output is the valve's own pressure drop. A damper's force adds the seals
      // and the gas, and there the knee trades with the viscous resistance (docs/diagnosis.md).
      knee_nuisance_ = *std::max_element(meta.valve.yield_pressure.begin(),
                                         meta.valve.yield_pressure.end()) > 0.0 &&
                       base_.kind != RigKind::damper;
      include("static_map", 0.0, "",
              "sidecar [valve] yield_current/yield_pressure/viscous_resistance (Bingham table, "
              "scale calibrated" +
                  std::string(knee_nuisance_ ? "; its knee between the line and the exact slit "
                                               "law calibrated"
                                             : "") +
                  ")" +
                  std::string(meta.valve.case_file.empty()
                                  ? ""
                                  : "; the table is used, [valve] case is not run"));
    } else if (!meta.valve.case_file.empty()) {
      chain_map(where);
    } else {
      throw InputError(where +
                       ": [valve] yield_current and yield_pressure (or an FE case) are "
                       "missing; the baseline needs the valve's static map");
    }
    if (meta.rig.chamber_volume) {
      chamber_volume_ = *meta.rig.chamber_volume;
      chamber_volume_given_ = true;
      stiff_or_compliant_chambers();
    }
    if (base_.kind == RigKind::damper) {
      base_.rod_area = meta.rig.rod_area.value_or(0.0);
      base_.gas_force = meta.rig.gas_force.value_or(0.0);
      if (meta.rig.gas_force)
        include("gas_force", *meta.rig.gas_force, "N",
                "sidecar [rig] gas_force (start of the calibrated force_offset)");
      if (meta.rig.rod_area)
        include("rod_area", *meta.rig.rod_area, "m^2",
                "sidecar [rig] rod_area (stated; the lumped damper's flow uses piston_area only)");
    }
  }
  output_ = lumped::rig_output_column(base_);
  if (meta.output != output_)
    throw InputError(where + ": [recording] output = \"" + meta.output + "\" but a " + kind_name +
                     " rig explains \"" + output_ + "\"");
  measured_ = rec_.column(output_);
  // [rig] orientation = -1: the output is recorded with the opposite sign (e.g. mrdamper).
  if (auto o = meta.rig.extra.find("orientation"); o != meta.rig.extra.end()) {
    if (o->second != 1.0 && o->second != -1.0)
      throw InputError(where + ": [rig] orientation must be 1 or -1");
    for (double& y : measured_) y *= o->second;
    include("orientation", o->second, "", "sidecar [rig] orientation");
  }
  drive_noise_and_filter();
  coil_drive_steps_ = !constant_field_ && steps(rec_.column(base_.driver_mode == DriverMode::voltage
                                                                ? base_.voltage_column
                                                                : std::string("current")));
  if (sampling == DriveSampling::held && can_hold()) hold_drives();
  // The pre-yield smoothness is a nuisance only where the flow reverses (beyond its noise).
  if (base_.kind != RigKind::coil_bench) {
    const auto& v = rec_.column("velocity");
    const auto [vmin, vmax] = std::minmax_element(v.begin(), v.end());
    const double floor = 5.0 * drive_noise_["velocity"];
    smoothing_nuisance_ =
        *vmin < -std::max(floor, 0.01 * *vmax) && *vmax > std::max(floor, 0.01 * -*vmin);
  }
  output_rms_ = spread(measured_);
}

double DiagnosisModel::spread(const std::vector<double>& y) {
  const double mean = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(y.size());
  double var = 0.0;
  for (double v : y) var += (v - mean) * (v - mean);
  return std::max(std::sqrt(var / static_cast<double>(y.size())), 1e-300);
}

void DiagnosisModel::repair_motion_glitches(const std::vector<std::string>& drives) {
  // A motion cannot leave its path for one sample and return: such a sample is the acquisition's
  // (a dropped or corrupted value), and an inertia reads it as a force spike thousands of times
  // its size, which pulls the inertia's fit towards 0. Repaired before noise and filter.
  for (const auto& c : drives) {
    if (!rec_.columns.count(c)) continue;
    auto glitches = lumped::find_motion_glitches(rec_, c);
    if (glitches.samples.empty()) continue;
    motion_glitch_notes_.push_back(
        lumped::describe_glitches(c, glitches, rec_.t) +
        "; each replaced by its neighbours' path before the diagnosis (the baseline and every "
        "candidate read the repaired motion)");
    rec_.columns[c] = lumped::without_glitches(rec_.column(c), glitches);
    motion_glitches_[c] = std::move(glitches);
  }
}

void DiagnosisModel::drive_noise_and_filter() {
  const std::vector<std::string> columns =
      fitted_ ? rec_.meta.drive : lumped::rig_drive_columns(base_);
  repair_motion_glitches(columns);
  for (const auto& c : columns) {
    const auto& u = rec_.column(c);
    if (!constant_field_ || c != "current") drive_noise_[c] = noise_sigma(u);
  }
  // A noisy velocity is smoothed before the model sees it: the inertance reads its slope, which
  // white noise of std s makes noisy by sqrt(2) s / dt (errors in variables).
  if (base_.kind != RigKind::coil_bench && rec_.columns.count("velocity")) {
    const auto& v = rec_.column("velocity");
    const auto [vmin, vmax] = std::minmax_element(v.begin(), v.end());
    if (drive_noise_["velocity"] > kNoisyDrive * (*vmax - *vmin)) {
      auto smooth = savitzky_golay(v, sample_interval_, kVelocityFilterHalfWidth);
      rec_.columns["velocity"] = std::move(smooth.values);
      velocity_filter_bandwidth_ = smooth.bandwidth;
    }
  }
  noisy_current_path();
}

void DiagnosisModel::noisy_current_path() {
  // The coil current as measured drives the baseline (its steps are the information); only a
  // state that remembers the current's path (a Duhem loop) is driven by its noise-robust path,
  // where white noise would otherwise reverse it at every sample and erase its memory.
  const std::string column = fitted_ ? field_column_ : std::string("current");
  const bool current = fitted_ ? column == "current" || column == "current_cmd"
                               : base_.driver_mode == DriverMode::current_source;
  if (!current_path_wanted_ || constant_field_ || !current || !rec_.columns.count(column)) return;
  const auto& i = rec_.column(column);
  const auto [lo, hi] = std::minmax_element(i.begin(), i.end());
  const double sigma = noise_sigma(i);
  if (!(sigma > kNoisyDrive * (*hi - *lo))) return;
  current_reversal_band_ = reversal_band(sigma, i.size());
  current_path_ = diagnose::current_path(i, current_reversal_band_);
}

lumped::Recording DiagnosisModel::simulate(const std::vector<const Candidate*>& effects,
                                           const std::vector<double>& values) const {
  const bool follows = std::any_of(effects.begin(), effects.end(),
                                   [](const Candidate* e) { return e->follows_current_path(); });
  if (!follows || current_path_.empty()) return lumped::simulate_rig(spec(effects, values), rec_);
  lumped::Recording r = rec_;
  r.columns["current"] = current_path_;
  return lumped::simulate_rig(spec(effects, values), r);
}

DiagnosisModel DiagnosisModel::held() const {
  DiagnosisModel m = *this;
  if (m.can_hold() && m.sampling_ != DriveSampling::held) m.hold_drives();
  return m;
}

void DiagnosisModel::hold_drives() {
  sampling_ = DriveSampling::held;
  base_.held_drives = {base_.driver_mode == DriverMode::voltage ? base_.voltage_column
                                                                : std::string("current")};
  // A motion sample recorded under the same convention stands for its interval too: the mean
  // over it, i.e. the motion at the interval's middle, half a sample after its time stamp.
  for (const char* c : {"velocity", "displacement"}) {
    auto it = rec_.columns.find(c);
    if (it == rec_.columns.end() || base_.kind == RigKind::coil_bench) continue;
    auto& v = it->second;
    for (std::size_t k = v.size() - 1; k > 0; --k) v[k] = 0.5 * (v[k] + v[k - 1]);
  }
}

void DiagnosisModel::chain_map(const std::string& where) {
  // The FE chain (field -> yield stress along the gaps -> exact gap flow), tabulated once over
  // the recording's current and flow range; its yield and viscous parts are calibrated.
  base_.valve.case_file = rec_.meta.valve.case_file;
  base_.valve.regularisation_flow = 1e-3 * std::max(peak_flow_, 1e-12);
  try {
    base_ = coupling::with_chain_map(base_, rec_);
  } catch (const InputError& e) {
    throw InputError(where + ": [valve] case = \"" + base_.valve.case_file +
                     "\" cannot be used as the baseline: " + e.what());
  } catch (const std::exception& e) {
    throw InputError(where + ": [valve] case = \"" + base_.valve.case_file +
                     "\" does not solve: " + e.what());
  }
  fe_chain_ = true;
  includes_.push_back({"static_map", 0.0, "",
                       "sidecar [valve] case = \"" + base_.valve.case_file +
                           "\" (FE chain tabulated on " +
                           std::to_string(base_.valve.chain->current.size()) + " currents x " +
                           std::to_string(base_.valve.chain->flow.size()) +
                           " flows; yield and viscous scales calibrated)"});
}

namespace {

/// Median time [s] after a velocity reversal for the motion to travel `stroke` [m] (0: none).
double plug_swing_time(const std::vector<double>& t, const std::vector<double>& velocity,
                       double stroke) {
  // The motion after each reversal is integrated until it has travelled `stroke`; the median over
  // the reversals is the time the chambers need to carry the valve from one yield to the other.
  std::vector<double> times;
  for (std::size_t k = 1; k < velocity.size(); ++k) {
    if ((velocity[k - 1] < 0.0) == (velocity[k] < 0.0)) continue;
    double travelled = 0.0;
    std::size_t j = k;
    for (; j < velocity.size() && travelled < stroke; ++j)
      travelled += std::abs(velocity[j]) * (t[j] - t[j - 1]);
    if (travelled >= stroke) times.push_back(t[j - 1] - t[k - 1]);
  }
  if (times.empty()) return 0.0;
  auto mid = times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2);
  std::nth_element(times.begin(), mid, times.end());
  return *mid;
}

}  // namespace

void DiagnosisModel::stiff_or_compliant_chambers() {
  // The oil's own compliance (bulk modulus 1.5 GPa) acts twice: it makes a lag R C_oil / 2
  // between the two chambers while the valve flows; and at a flow reversal, where the plug
  // holds, the piston must compress the oil by C_oil P (P the largest yield pressure) before the
  // valve yields the other way, so the force reverses that much stroke after the motion. Where
  // either is longer than a tenth of a sample the baseline is calibrated with and without it and
  // keeps the better (a real damper's force shows it; a simulator may keep the stated oil
  // stiff). Otherwise the fluid is stiff to within the sampling.
  lumped::ChamberBlock oil;
  oil.oil_volume = chamber_volume_;
  const double capacitance = oil.capacitance(oil.precharge);
  const double resistance =
      fe_chain_ ? base_.valve.chain->viscous_resistance : base_.valve.viscous_resistance;
  const double lag = 0.5 * resistance * capacitance;
  const std::vector<double>& yields =
      fe_chain_ ? base_.valve.chain->yield : base_.valve.yield_pressure;
  const double yield = yields.empty() ? 0.0 : *std::max_element(yields.begin(), yields.end());
  const double swing = plug_swing_time(rec_.t, rec_.column("velocity"),
                                       capacitance * std::abs(yield) / base_.piston_area);
  oil_compliance_lags_ =
      "lag " + std::to_string(1e3 * lag) + " ms, reversal " + std::to_string(1e3 * swing) + " ms";
  oil_compliance_optional_ = std::max(lag, swing) >= 0.1 * sample_interval_;
  includes_.push_back({"chamber_volume", chamber_volume_, "m^3",
                       "sidecar [rig] chamber_volume (oil compliance " + oil_compliance_lags_ +
                           (oil_compliance_optional_ ? ": calibrated, stiff fluid fitted better"
                                                     : " < 0.1 sample: stiff fluid") +
                           "; the compressibility candidate adds air to it)"});
}

DiagnosisModel DiagnosisModel::with_oil_compliance(double fit_gain) const {
  DiagnosisModel m = *this;
  if (base_.compressibility || fitted_ || base_.kind == RigKind::coil_bench) return m;
  lumped::ChamberBlock oil;
  oil.oil_volume = chamber_volume_;
  m.base_.compressibility = oil;
  for (auto& item : m.includes_)
    if (item.name == "chamber_volume") {
      std::ostringstream gain;
      gain.precision(3);
      gain << fit_gain;
      item.source =
          "sidecar [rig] chamber_volume (oil compliance simulated: " + oil_compliance_lags_ +
          "; calibrated, baseline FIT " + gain.str() + " points over stiff fluid)";
    }
  return m;
}

std::vector<ParamDef> DiagnosisModel::static_params() const {
  std::vector<ParamDef> p;
  if (fitted_) {
    // The model's own parameters are held; its output's level is calibrated (a drift of the
    // fluid, temperature or sensor gain between the two test days is not missing physics).
    p.push_back({"output_scale", 1.0, 0.5, 2.0, false, 1.0, "1"});
    const std::string unit = output_ == "force"      ? "N"
                             : output_ == "pressure" ? "Pa"
                             : output_ == "current"  ? "A"
                                                     : "";
    p.push_back(
        {"output_offset", 0.0, -10.0 * output_rms_, 10.0 * output_rms_, false, output_rms_, unit});
  } else if (base_.kind == RigKind::coil_bench) {
    const double r = base_.coil.resistance_20c;
    p.push_back({"coil_resistance", r, 0.2 * r, 5.0 * r, true, 1.0, "ohm"});
  } else {
    p.push_back({"yield_scale", 1.0, 0.05, 20.0, false, 1.0, "1"});
    if (fe_chain_) {
      p.push_back({"viscous_scale", 1.0, 1e-2, 1e2, true, 1.0, "1"});
    } else {
      const double rv = base_.valve.viscous_resistance;
      p.push_back({"viscous_resistance", rv, rv * 1e-2, rv * 1e2, true, 1.0, "Pa s/m^3"});
    }
    if (base_.kind == RigKind::damper)
      p.push_back({"force_offset", base_.gas_force, base_.gas_force - 10.0 * output_rms_,
                   base_.gas_force + 10.0 * output_rms_, false, output_rms_, "N"});
  }
  // Nuisances: a delay of up to two samples between the output and the drives (channel skew,
  // and a zero-order-held drive, which acts as half a sample), and the static map's pre-yield
  // smoothness (width of its plug switch, a fraction of the peak flow).
  // The held reading already puts the motion half a sample later: its delay range is shifted by
  // half a sample so that both conventions span the same timings of the recorded channels.
  const double dt = sample_interval_;
  const double shift = held_delay_shift() * dt;
  p.push_back({"delay", 0.0, -kMaxDelaySamples * dt + shift, kMaxDelaySamples * dt + shift, false,
               dt, "s"});
  if (smoothing_nuisance_) {
    const double q = peak_flow_;
    p.push_back({"preyield_flow",
                 std::clamp(base_.valve.regularisation_flow, 1e-5 * q, kMaxPreyieldFraction * q),
                 1e-5 * q, kMaxPreyieldFraction * q, true, 1.0, "m^3/s"});
  }
  if (knee_nuisance_) p.push_back({"slit_fraction", 0.0, 0.0, 1.0, false, 0.1, "1"});
  return p;
}

std::size_t DiagnosisModel::nuisance_count() const {
  return 1 + (smoothing_nuisance_ ? 1 : 0) + (knee_nuisance_ ? 1 : 0);
}

std::vector<ParamDef> DiagnosisModel::layout(const std::vector<const Candidate*>& effects) const {
  auto out = static_params();
  for (const Candidate* e : effects) {
    auto p = e->params(*this);
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

RigSpec DiagnosisModel::spec(const std::vector<const Candidate*>& effects,
                             const std::vector<double>& values) const {
  RigSpec s = base_;
  std::size_t k = 0;
  if (fitted_) {
    k = static_params().size();  // output scale and offset, delay: applied to the output
  } else if (s.kind == RigKind::coil_bench) {
    s.coil.resistance_20c = values.at(k++);
  } else {
    s.valve.yield_scale = values.at(k++);
    if (fe_chain_)
      s.valve.viscous_scale = values.at(k++);
    else
      s.valve.viscous_resistance = values.at(k++);
    if (s.kind == RigKind::damper) s.gas_force = values.at(k++);
  }
  if (!fitted_) {
    ++k;  // delay: applied to the output (predict)
    if (smoothing_nuisance_) s.valve.regularisation_flow = values.at(k++);
    if (knee_nuisance_) s.valve.slit_fraction = values.at(k++);
  }
  ParamReader reader(values, k);
  for (const Candidate* e : effects) e->switch_on(s, reader, *this);
  return s;
}

std::vector<double> DiagnosisModel::delayed(std::vector<double> y,
                                            const std::vector<double>& values) const {
  const double delay = values.at(static_params().size() - nuisance_count());
  if (delay == 0.0) return y;
  // y(t - delay) by linear interpolation between samples (held at the ends). The shifted times
  // increase with k, so one sweep finds each one's interval (no search per sample).
  const auto& t = rec_.t;
  const std::size_t n = t.size();
  std::vector<double> out(y.size());
  std::size_t upper = 0;  // first sample after the shifted time
  for (std::size_t k = 0; k < n; ++k) {
    const double tk = t[k] - delay;
    while (upper < n && t[upper] <= tk) ++upper;
    if (upper == 0) {
      out[k] = y.front();
    } else if (upper == n) {
      out[k] = y.back();
    } else {
      const std::size_t j = upper - 1;
      const double w = (tk - t[j]) / (t[j + 1] - t[j]);
      out[k] = (1.0 - w) * y[j] + w * y[j + 1];
    }
  }
  return out;
}

double DiagnosisModel::best_delay(const std::vector<double>& undelayed, std::vector<double> values,
                                  double& sse) const {
  const std::size_t j = delay_index();
  const double dt = sample_interval_;
  auto error = [&](double delay) {
    values[j] = delay;
    const auto y = delayed(undelayed, values);
    double s = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k) s += (measured_[k] - y[k]) * (measured_[k] - y[k]);
    return s;
  };
  constexpr int kSteps = 10;  // per sample interval
  const int m = static_cast<int>(kMaxDelaySamples) * kSteps;
  const int shift = static_cast<int>(std::lround(held_delay_shift() * kSteps));
  std::vector<double> e(static_cast<std::size_t>(2 * m + 1));
  std::size_t best = 0;
  for (int i = -m; i <= m; ++i) {
    const auto k = static_cast<std::size_t>(i + m);
    e[k] = error(dt * (i + shift) / kSteps);
    if (e[k] < e[best]) best = k;
  }
  double delay = dt * (static_cast<double>(best) - m + shift) / kSteps;
  sse = e[best];
  if (best > 0 && best + 1 < e.size()) {
    const double curvature = e[best - 1] - 2.0 * e[best] + e[best + 1];
    if (curvature > 0.0) {
      const double refined = delay + 0.5 * dt / kSteps * (e[best - 1] - e[best + 1]) / curvature;
      const double s = error(refined);
      if (s < sse) sse = s, delay = refined;
    }
  }
  return delay;
}

std::vector<double> DiagnosisModel::predict(const std::vector<const Candidate*>& effects,
                                            const std::vector<double>& values) const {
  if (fitted_) return delayed(predict_fitted(effects, values), values);
  auto sim = simulate(effects, values);
  return delayed(std::move(sim.columns.at(output_)), values);
}

std::vector<double> DiagnosisModel::predict_column(const std::vector<const Candidate*>& effects,
                                                   const std::vector<double>& values,
                                                   const std::string& column) const {
  // A fitted model simulates its output only: other columns are what was recorded.
  if (fitted_) return column == output_ ? predict(effects, values) : rec_.column(column);
  auto sim = simulate(effects, values);
  return delayed(std::move(sim.columns.at(column)), values);
}

}  // namespace rheomag::diagnose
