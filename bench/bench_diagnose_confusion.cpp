// Confusion-matrix benchmark of `rheomag diagnose` (issues 5 and 13): random virtual-rig
// recordings, each with one concealed effect, a pair of them, or none; random parameters,
// excitation, noise level, sidecar map error and rig kind. With --nuisances 1 (the default) the
// recordings also carry what real recorders add and is not physics: noise on the drive columns
// (0.1-0.5 % of their spread), held or smooth drive sampling (held: the coil drive steps at the
// samples, the motion is recorded as the mean over the interval each sample begins), a channel
// skew of 0-1 sample, a
// pre-yield smoothing of 0.5-3 % of the peak flow, and a sidecar stating the true coil
// inductance on half the clean voltage-driven draws. The diagnosis sees only the recording.
// Prints one line per draw as it finishes, then the matrix truth x first named effect, the share
// named right, the share with any false finding and the share whose final FIT is within 2 points
// of the achievable ceiling (the truth driven by the recorded, noisy inputs).
// Not a Google Benchmark (it takes minutes):
//   bench_diagnose_confusion [--draws N] [--seed S] [--threads T] [--only NAME] [--index I]
//                            [--csv FILE] [--nuisances 0|1] [--visible 0|1] [--ringing-start 0|1]
//                            [--current-path 0|1] [--align-delay 0|1] [--align-margin M]
// --current-path 0 drives the Duhem candidate by the noisy current's samples instead of its path
// estimate (DiagnoseOptions::current_path), to compare the two on the same draws.
// --align-delay 0 keeps the final fit's output delay where the data do not require it
// (DiagnoseOptions::align_delay; for comparison); --align-margin M keeps it only where it
// lowers BIC by more than M (DiagnoseOptions::align_delay_margin, default 2).
// --ringing-start 0 starts the fluid_inertia candidate from its decade grid alone, without the
// inertances the residual's ringing gives (DiagnoseOptions::ringing_start; for comparison).
// --visible 1 (the default) makes every concealed effect at least barely visible: the part of
// its signature on the recording (truth with it minus truth without it, same drives and
// nuisances) that the baseline's calibration cannot reproduce must have an rms of at least the
// output noise rms; an effect below that is redrawn larger (see make_visible).
// RHEOMAG_CONFUSION_NOTES=1 prints each diagnosis's candidate scores and notes.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Dense>

#include "diagnose/candidates/magnetic_hysteresis.hpp"
#include "diagnose/diagnose_run.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"
#include "lumped/signals.hpp"

namespace {

using namespace rheomag;
using lumped::DriverMode;
using lumped::RigKind;

const std::vector<std::string> kTruths = {
    "none",          "compressibility", "fluid_inertia", "magnetic_hysteresis",
    "eddy_currents", "coil_inductance", "coil_heating",  "mr_response_time",
    "friction",      "pre_yield",       "pair"};

/// The two field lags are one block in series: either name counts for either.
std::string effect_class(const std::string& name) {
  return name == "eddy_currents" || name == "mr_response_time" ? "field_lag" : name;
}

/// One random draw: the truth spec, its drive and a description of what was drawn.
struct Draw {
  std::string truth;
  std::vector<std::string> effects;  ///< concealed effects (two for a pair)
  int index = 0;
  lumped::RigSpec spec;
  lumped::Recording drive;
  double noise_fraction = 0.0;  ///< noise std / output std
  bool nuisances = true;        ///< drive noise, held sampling, skew, stated inductance
  bool held = false;         ///< coil drive held between samples, motion recorded as interval means
  double skew = 0.0;         ///< [samples] drive channels sampled this much later
  double drive_noise = 0.0;  ///< drive noise std / drive std
  bool state_inductance = false;  ///< the sidecar states the true inductance
  double map_error = 0.1;         ///< sidecar map off by up to this factor
  std::string description;
  unsigned seed = 0;       ///< the draw's own seed (a redraw takes the next one)
  int enlarged = 0;        ///< effects whose size was redrawn larger to become visible
  int redrawn = 0;         ///< whole draws redrawn because an effect stayed invisible
  std::string visibility;  ///< each effect's signature rms / output noise rms
};

/// Outcome of one diagnosed draw.
struct Outcome {
  std::string truth, named, all_named, description, visibility;
  std::string notes;  ///< candidate scores and notes (RHEOMAG_CONFUSION_NOTES set)
  int enlarged = 0, redrawn = 0;
  bool ambiguous = false, truth_in_ambiguous = false;
  bool right = false;          ///< every concealed effect named (either name for the field lag)
  bool false_finding = false;  ///< something named that was not concealed
  double final_fit = 0.0, ceiling = 0.0;
  double seconds = 0.0;
};

double log_uniform(std::mt19937& rng, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
}
double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
template <class T>
T pick(std::mt19937& rng, const std::vector<T>& v) {
  return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)];
}

std::string fmt(double v) {
  std::ostringstream o;
  o << std::setprecision(3) << v;
  return o.str();
}

/// Rig kinds on which a concealed effect can show (coil effects need a voltage-driven coil).
std::vector<RigKind> kinds_for(const std::string& truth) {
  using K = RigKind;
  if (truth == "friction") return {K::damper};
  if (truth == "coil_heating") return {K::coil_bench};
  if (truth == "fluid_inertia" || truth == "pre_yield") return {K::bypass_cylinder, K::damper};
  if (truth == "coil_inductance")
    return {K::coil_bench, K::constant_velocity_pump, K::bypass_cylinder, K::damper};
  if (truth == "none")
    return {K::coil_bench, K::constant_velocity_pump, K::bypass_cylinder, K::damper};
  return {K::constant_velocity_pump, K::bypass_cylinder, K::damper};
}

/// Two different effects that can show together on one rig (pairs of the vocabulary).
std::vector<std::string> pair_for(std::mt19937& rng) {
  const std::vector<std::vector<std::string>> pairs = {{"friction", "mr_response_time"},
                                                       {"friction", "compressibility"},
                                                       {"compressibility", "eddy_currents"},
                                                       {"fluid_inertia", "mr_response_time"},
                                                       {"coil_inductance", "compressibility"},
                                                       {"magnetic_hysteresis", "compressibility"},
                                                       {"friction", "fluid_inertia"},
                                                       {"coil_inductance", "friction"},
                                                       {"pre_yield", "friction"},
                                                       {"pre_yield", "mr_response_time"}};
  return pick(rng, pairs);
}

bool uses_voltage(const std::vector<std::string>& effects) {
  for (const auto& e : effects)
    if (e == "coil_inductance" || e == "coil_heating") return true;
  return false;
}

Draw make_draw(const std::string& truth, int index, unsigned seed, bool nuisances) {
  std::mt19937 rng(seed);
  Draw d;
  d.truth = truth;
  d.index = index;
  d.seed = seed;
  d.nuisances = nuisances;
  if (truth == "pair")
    d.effects = pair_for(rng);
  else if (truth != "none")
    d.effects = {truth};
  auto& s = d.spec;
  // Rig kind: one where every concealed effect can show.
  std::vector<RigKind> kinds = kinds_for(d.effects.empty() ? "none" : d.effects.front());
  for (std::size_t e = 1; e < d.effects.size(); ++e) {
    const auto other = kinds_for(d.effects[e]);
    std::vector<RigKind> both;
    for (auto k : kinds)
      if (std::find(other.begin(), other.end(), k) != other.end()) both.push_back(k);
    kinds = both;
  }
  s.kind = pick(rng, kinds);
  s.piston_area = 4.524e-4;
  s.valve.yield_current = {0.0, 0.25, 0.5, 0.75, 1.0};
  s.valve.yield_pressure = {0.0, 1.9e6, 3.6e6, 4.9e6, 5.8e6};
  s.valve.viscous_resistance = log_uniform(rng, 5e9, 3e10);
  s.coil.resistance_20c = uniform(rng, 5.0, 12.0);
  if (s.kind == RigKind::damper) s.gas_force = uniform(rng, 0.0, 300.0);
  // Coil drive: voltage for coil effects and the coil bench, else a current source (and a
  // voltage-driven coil in a third of the clean hydraulic draws).
  const bool voltage = s.kind == RigKind::coil_bench || uses_voltage(d.effects) ||
                       (truth == "none" && uniform(rng, 0.0, 1.0) < 1.0 / 3.0);
  if (voltage) {
    s.driver_mode = DriverMode::voltage;
    s.voltage_column = "voltage";
  }
  // Excitation.
  const double rate = s.kind == RigKind::coil_bench ? 100.0 : 250.0;
  const double duration = s.kind == RigKind::coil_bench ? 6.0 : 2.4;
  d.drive.t = lumped::uniform_times(duration, rate);
  std::ostringstream desc;
  desc << lumped::rig_kind_name(s.kind);
  std::vector<std::string> signals;
  double peak_velocity = 0.0;
  if (s.kind == RigKind::constant_velocity_pump) {
    const double v = uniform(rng, 0.005, 0.02);
    signals.push_back("velocity=constant:value=" + fmt(v));
    peak_velocity = v;
    desc << " v=" << fmt(v);
  } else if (s.kind != RigKind::coil_bench) {
    const double amp = uniform(rng, 0.01, 0.025), f = uniform(rng, 0.5, 3.0);
    signals.push_back("displacement=sine:amplitude=" + fmt(amp) + ",frequency=" + fmt(f));
    peak_velocity = 2.0 * M_PI * f * amp;
    desc << " x=" << fmt(amp) << "m f=" << fmt(f) << "Hz";
  }
  const double top = uniform(rng, 0.6, 1.0);
  std::vector<double> levels = {0.0, 0.5 * top, top};
  if (uniform(rng, 0.0, 1.0) < 0.5) levels.push_back(uniform(rng, 0.2, 0.8) * top);
  std::shuffle(levels.begin() + 1, levels.end(), rng);
  const double period =
      s.kind == RigKind::coil_bench ? uniform(rng, 0.5, 1.5) : uniform(rng, 0.2, 0.4);
  std::string lv;
  const double volts_per_amp = voltage ? s.coil.resistance_20c : 1.0;
  for (double l : levels) lv += (lv.empty() ? "" : "/") + fmt(l * volts_per_amp);
  signals.push_back(std::string(voltage ? "voltage" : "current") + "=steps:levels=" + lv +
                    ",period=" + fmt(period));
  for (const auto& sig : signals) lumped::add_signal(d.drive, sig);
  desc << (voltage ? " V=" : " I=") << lv << " P=" << fmt(period) << "s";
  // The concealed effects.
  for (const auto& e : d.effects) {
    if (e == "compressibility") {
      lumped::ChamberBlock c = s.compressibility.value_or(lumped::ChamberBlock{});
      c.oil_volume = 2e-5;
      c.air_volume = log_uniform(rng, 5e-8, 1e-6);
      s.compressibility = c;
      desc << " air=" << fmt(c.air_volume);
    } else if (e == "fluid_inertia") {
      s.inertance = log_uniform(rng, 2e8, 2e9);
      desc << " L=" << fmt(*s.inertance);
    } else if (e == "magnetic_hysteresis") {
      const double a = log_uniform(rng, 2.0, 10.0), dd = uniform(rng, 0.1, 0.6);
      s.magnetic_hysteresis = diagnose::duhem_field(a, dd);
      desc << " a=" << fmt(a) << " d=" << fmt(dd);
    } else if (e == "eddy_currents") {
      s.eddy_time_constant = log_uniform(rng, 0.008, 0.06);
      desc << " tau=" << fmt(*s.eddy_time_constant);
    } else if (e == "mr_response_time") {
      s.mr_response_time = log_uniform(rng, 0.008, 0.06);
      desc << " tau=" << fmt(*s.mr_response_time);
    } else if (e == "coil_inductance") {
      s.coil.inductance = log_uniform(rng, 0.05, 0.9);
      desc << " L=" << fmt(s.coil.inductance);
    } else if (e == "coil_heating") {
      lumped::ThermalBlock th;
      th.thermal_resistance = log_uniform(rng, 1.0, 8.0);
      th.thermal_time_constant = uniform(rng, 1.5, 5.0);
      s.coil_heating = th;
      desc << " Rth=" << fmt(th.thermal_resistance) << " tau=" << fmt(th.thermal_time_constant);
    } else if (e == "pre_yield") {
      // The elastic pre-yield branch: a linear compliance V / K between the chambers.
      lumped::ChamberBlock c = s.compressibility.value_or(lumped::ChamberBlock{});
      c.oil_volume = 2e-5;
      c.bulk_modulus = log_uniform(rng, 3e6, 1e8);
      s.compressibility = c;
      desc << " K=" << fmt(c.bulk_modulus);
    } else if (e == "friction") {
      s.coulomb_force = log_uniform(rng, 40.0, 400.0);
      desc << " Fc=" << fmt(*s.coulomb_force);
    }
  }
  d.noise_fraction = uniform(rng, 0.002, 0.015);
  desc << " noise=" << fmt(100 * d.noise_fraction) << "%";
  if (nuisances) {
    d.map_error = 0.15;
    d.held = uniform(rng, 0.0, 1.0) < 0.5;
    d.skew = uniform(rng, 0.0, 1.0) * (uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    d.drive_noise = uniform(rng, 0.001, 0.005);
    // The recorder's static map is smoother at pre-yield than the sidecar's Bingham map.
    if (s.kind != RigKind::coil_bench && peak_velocity > 0.0)
      s.valve.regularisation_flow = uniform(rng, 0.005, 0.03) * s.piston_area * peak_velocity;
    // Half of the clean voltage-driven draws have a coil inductance the sidecar states.
    if (truth == "none" && voltage && uniform(rng, 0.0, 1.0) < 0.5) {
      s.coil.inductance = log_uniform(rng, 0.05, 0.9);
      d.state_inductance = true;
      desc << " stated L=" << fmt(s.coil.inductance);
    }
    desc << (d.held ? " held" : " smooth") << " skew=" << fmt(d.skew)
         << " drive_noise=" << fmt(100 * d.drive_noise) << "%"
         << " preyield=" << fmt(s.valve.regularisation_flow);
  }
  d.description = desc.str();
  return d;
}

/// Standard deviation of v.
double spread(const std::vector<double>& v) {
  double mean = 0.0, var = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (double x : v) var += (x - mean) * (x - mean);
  return std::sqrt(var / static_cast<double>(v.size()));
}

/// Value of a sampled signal at time tt (linear interpolation, held at the ends).
double at(const std::vector<double>& t, const std::vector<double>& v, double tt) {
  if (tt <= t.front()) return v.front();
  if (tt >= t.back()) return v.back();
  const auto j = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), tt) - t.begin()) - 1;
  const double w = (tt - t[j]) / (t[j + 1] - t[j]);
  return (1.0 - w) * v[j] + w * v[j + 1];
}

constexpr int kFine = 4;  ///< the truth's time base is this much finer than the recorder's

/// A mechanical drive column (the piston's motion): smooth in time whatever the recorder does.
bool mechanical(const std::string& column) {
  return column == "velocity" || column == "displacement";
}

/// The drives acting on the rig: with nuisances on a 4x finer time base, smooth or held between
/// the recorder's samples; without, the recorder's own.
lumped::Recording rig_drives(const Draw& draw) {
  if (!draw.nuisances) return draw.drive;
  const auto& tc = draw.drive.t;
  const double dt = tc[1] - tc[0];
  lumped::Recording fine;
  for (std::size_t k = 0; k + 1 < tc.size(); ++k)
    for (int f = 0; f < kFine; ++f) fine.t.push_back(tc[k] + dt * f / kFine);
  fine.t.push_back(tc.back());
  for (const auto& [name, v] : draw.drive.columns) {
    auto& out = fine.columns[name];
    for (double tt : fine.t) {
      // Held: the value of the last recorder sample (a DAC's zero-order hold on the coil's
      // current or voltage); smooth: the drive between samples. A piston's motion is always
      // smooth (a held velocity would step, with an impulsive acceleration); its `held`
      // convention is on the recorder's side (record()).
      const double th = draw.held && !mechanical(name)
                            ? tc.front() + dt * std::floor((tt - tc.front()) / dt + 1e-9)
                            : tt;
      out.push_back(at(tc, v, th));
    }
  }
  return fine;
}

/// What the recorder writes: the truth simulated on the rig's drives (above), the output at the
/// recorder's samples, the drives sampled `skew` samples late with noise (a held motion column
/// as the mean over the interval beginning at the sample).
lumped::Recording record(const Draw& draw, std::mt19937& rng) {
  if (!draw.nuisances) return lumped::simulate_rig(draw.spec, draw.drive);
  const auto& tc = draw.drive.t;
  const double dt = tc[1] - tc[0];
  const auto fine = rig_drives(draw);
  const auto truth = lumped::simulate_rig(draw.spec, fine);
  lumped::Recording rec = truth;
  rec.t = tc;
  for (auto& [name, v] : rec.columns) {
    std::vector<double> coarse;
    for (std::size_t k = 0; k < tc.size(); ++k) coarse.push_back(v[k * kFine]);
    v = coarse;
  }
  for (const auto& c : rec.meta.drive) {
    auto& v = rec.columns.at(c);
    const auto& source = fine.columns.at(c);
    const double sigma = draw.drive_noise * spread(draw.drive.columns.at(c));
    std::normal_distribution<double> noise(0.0, sigma);
    for (std::size_t k = 0; k < tc.size(); ++k) {
      const double tk = tc[k] + draw.skew * dt;
      // A held convention on a smooth motion: the recorder writes the mean over the interval
      // that the sample stands for, the one that begins at it (as a held coil drive's sample
      // stands for its value until the next), so both drive channels are half a sample early.
      double value = at(fine.t, source, tk);
      if (draw.held && mechanical(c)) {
        value = 0.0;
        for (int f = 0; f <= kFine; ++f)
          value +=
              (f == 0 || f == kFine ? 0.5 : 1.0) / kFine * at(fine.t, source, tk + dt * f / kFine);
      }
      v[k] = value + (sigma > 0.0 ? noise(rng) : 0.0);
    }
  }
  return rec;
}

/// A concealed effect's size parameter and its drawn range; `larger_up`: a larger value is a
/// larger effect (false for the Duhem a, whose loop half width is (1 - d)/a, and the pre-yield
/// bulk modulus, whose compliance is V/K).
struct SizeRange {
  double lo, hi;
  bool larger_up = true;
};

SizeRange size_range(const std::string& e) {
  if (e == "compressibility") return {5e-8, 1e-6};
  if (e == "fluid_inertia") return {2e8, 2e9};
  if (e == "magnetic_hysteresis") return {2.0, 10.0, false};
  if (e == "eddy_currents" || e == "mr_response_time") return {0.008, 0.06};
  if (e == "coil_inductance") return {0.05, 0.9};
  if (e == "coil_heating") return {1.0, 8.0};
  if (e == "pre_yield") return {3e6, 1e8, false};
  return {40.0, 400.0};  // friction
}

/// Sets the size parameter of concealed effect `e` in `s`.
void set_size(lumped::RigSpec& s, const std::string& e, double v) {
  if (e == "compressibility") s.compressibility->air_volume = v;
  if (e == "fluid_inertia") s.inertance = v;
  if (e == "magnetic_hysteresis")
    s.magnetic_hysteresis = diagnose::duhem_field(v, s.magnetic_hysteresis->d);
  if (e == "eddy_currents") s.eddy_time_constant = v;
  if (e == "mr_response_time") s.mr_response_time = v;
  if (e == "coil_inductance") s.coil.inductance = v;
  if (e == "coil_heating") s.coil_heating->thermal_resistance = v;
  if (e == "pre_yield") s.compressibility->bulk_modulus = v;
  if (e == "friction") s.coulomb_force = v;
}

double size_of(const lumped::RigSpec& s, const std::string& e) {
  if (e == "compressibility") return s.compressibility->air_volume;
  if (e == "fluid_inertia") return *s.inertance;
  if (e == "magnetic_hysteresis") return s.magnetic_hysteresis->a;
  if (e == "eddy_currents") return *s.eddy_time_constant;
  if (e == "mr_response_time") return *s.mr_response_time;
  if (e == "coil_inductance") return s.coil.inductance;
  if (e == "coil_heating") return s.coil_heating->thermal_resistance;
  if (e == "pre_yield") return s.compressibility->bulk_modulus;
  return *s.coulomb_force;
}

/// `s` without concealed effect `e` (everything else, nuisances included, unchanged).
lumped::RigSpec without(lumped::RigSpec s, const std::string& e) {
  const lumped::ChamberBlock stiff;
  if (e == "compressibility") s.compressibility->air_volume = 0.0;
  if (e == "pre_yield") s.compressibility->bulk_modulus = stiff.bulk_modulus;
  if ((e == "compressibility" || e == "pre_yield") && s.compressibility->air_volume == 0.0 &&
      s.compressibility->bulk_modulus == stiff.bulk_modulus)
    s.compressibility.reset();
  if (e == "fluid_inertia") s.inertance.reset();
  if (e == "magnetic_hysteresis") s.magnetic_hysteresis.reset();
  if (e == "eddy_currents") s.eddy_time_constant.reset();
  if (e == "mr_response_time") s.mr_response_time.reset();
  if (e == "coil_inductance") s.coil.inductance = 0.0;
  if (e == "coil_heating") s.coil_heating.reset();
  if (e == "friction") s.coulomb_force.reset();
  return s;
}

/// "Barely visible": the part of a concealed effect's signature on the recording (the truth with
/// it minus the truth without it, on the same drives with the same nuisances, at the recorder's
/// samples) that the baseline's own calibration cannot reproduce must have an rms of at least
/// this many output-noise standard deviations. The calibration is linearised about the truth
/// without the effect: the map's yield scale and viscous resistance (coil bench: the coil
/// resistance), the damper's force offset, the output delay (d/dt of the output) and the
/// pre-yield smoothing width; the signature is projected off their span (least squares).
constexpr double kVisible = 1.0;

/// Signature of one concealed effect: rms of the whole signature and of its part beyond the
/// baseline's calibration, both over the output noise rms.
struct Visibility {
  double raw = 0.0, beyond = 0.0;
};

/// Visibility of each concealed effect of `draw`.
std::vector<Visibility> visibility(const Draw& draw) {
  const auto fine = rig_drives(draw);
  const std::string out = lumped::rig_output_column(draw.spec);
  const std::size_t step = draw.nuisances ? kFine : 1;
  const std::size_t n = draw.drive.t.size();
  const double dt_fine = fine.t[1] - fine.t[0];
  auto simulate = [&](const lumped::RigSpec& s) {
    return lumped::simulate_rig(s, fine).columns.at(out);
  };
  auto sampled = [&](const std::vector<double>& v) {
    Eigen::VectorXd y(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < n; ++k) y[static_cast<Eigen::Index>(k)] = v[k * step];
    return y;
  };
  const Eigen::VectorXd y = sampled(simulate(draw.spec));
  const double mean = y.mean();
  const double sigma = draw.noise_fraction * std::sqrt((y.array() - mean).square().mean());
  std::vector<Visibility> result;
  for (const auto& e : draw.effects) {
    const auto reference = without(draw.spec, e);
    const auto fine0 = simulate(reference);
    const Eigen::VectorXd y0 = sampled(fine0);
    const Eigen::VectorXd signature = y - y0;
    // The baseline's calibration about the reference: one column per calibrated parameter.
    std::vector<Eigen::VectorXd> columns;
    auto perturbed = [&](auto change) {
      auto s = reference;
      change(s);
      return Eigen::VectorXd(sampled(simulate(s)) - y0);
    };
    if (draw.spec.kind == RigKind::coil_bench) {
      columns.push_back(perturbed([](lumped::RigSpec& s) { s.coil.resistance_20c *= 1.01; }));
    } else {
      columns.push_back(perturbed([](lumped::RigSpec& s) { s.valve.yield_scale *= 1.01; }));
      columns.push_back(perturbed([](lumped::RigSpec& s) { s.valve.viscous_resistance *= 1.01; }));
      columns.push_back(perturbed([](lumped::RigSpec& s) { s.valve.regularisation_flow *= 1.1; }));
      if (draw.spec.kind == RigKind::damper)
        columns.push_back(Eigen::VectorXd::Ones(static_cast<Eigen::Index>(n)));
    }
    Eigen::VectorXd rate(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t a = k * step > 0 ? k * step - 1 : 0;
      const std::size_t b = std::min(k * step + 1, fine0.size() - 1);
      rate[static_cast<Eigen::Index>(k)] =
          (fine0[b] - fine0[a]) / (dt_fine * static_cast<double>(b - a));
    }
    columns.push_back(rate);
    Eigen::MatrixXd basis(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double norm = columns[c].norm();
      basis.col(static_cast<Eigen::Index>(c)) =
          norm > 0.0 ? Eigen::VectorXd(columns[c] / norm) : columns[c];
    }
    const Eigen::VectorXd beyond = signature - basis * basis.colPivHouseholderQr().solve(signature);
    const double rn = std::sqrt(static_cast<double>(n));
    result.push_back({signature.norm() / rn / sigma, beyond.norm() / rn / sigma});
  }
  return result;
}

/// Makes every concealed effect of the draw at least barely visible (kVisible): an invisible
/// effect's size is redrawn log-uniformly between its drawn value and the large end of its
/// range (up to kTries times, the last at the end itself); an effect still invisible at the end
/// of its range (its excitation cannot show it) makes the whole draw redrawn from the next seed.
/// The counts are kept in the draw and reported.
Draw make_visible(Draw d, Draw (*redraw)(const std::string&, int, unsigned, bool)) {
  constexpr int kTries = 6, kRedraws = 20;
  std::mt19937 rng(d.seed ^ 0x5eedu);
  int redrawn = 0, enlarged = 0;
  for (int r = 0; r <= kRedraws; ++r) {
    std::vector<Visibility> ratio = visibility(d);
    for (std::size_t i = 0; i < d.effects.size(); ++i) {
      const auto& e = d.effects[i];
      const auto range = size_range(e);
      const double end = range.larger_up ? range.hi : range.lo;
      bool changed = false;
      for (int t = 1; t <= kTries && ratio[i].beyond < kVisible; ++t) {
        const double now = size_of(d.spec, e);
        set_size(d.spec, e,
                 t == kTries ? end : log_uniform(rng, std::min(now, end), std::max(now, end)));
        changed = true;
        ratio = visibility(d);
      }
      if (changed) {
        ++enlarged;
        d.description += " enlarged " + e + "=" + fmt(size_of(d.spec, e));
      }
    }
    bool visible = true;
    std::ostringstream v;
    for (std::size_t i = 0; i < ratio.size(); ++i) {
      v << (i ? "/" : "") << fmt(ratio[i].raw) << ":" << fmt(ratio[i].beyond);
      if (ratio[i].beyond < kVisible) visible = false;
    }
    d.visibility = v.str();
    if (visible || r == kRedraws) {
      d.redrawn = redrawn;
      d.enlarged = enlarged;
      return d;
    }
    ++redrawn;
    d = redraw(d.truth, d.index, d.seed + 7919u, d.nuisances);
  }
  return d;
}

/// Simulates the draw, adds noise and the sidecar map error, and runs the diagnosis with
/// `options`.
Outcome run(const Draw& drawn, unsigned seed, bool visible,
            const diagnose::DiagnoseOptions& options) {
  std::mt19937 rng(seed);
  Outcome o;
  o.truth = drawn.truth;
  o.description = drawn.description;
  const auto started = std::chrono::steady_clock::now();
  try {
    const Draw draw = visible ? make_visible(drawn, &make_draw) : drawn;
    o.description = draw.description;
    o.visibility = draw.visibility;
    o.enlarged = draw.enlarged;
    o.redrawn = draw.redrawn;
    auto rec = record(draw, rng);
    const std::string out = lumped::rig_output_column(draw.spec);
    auto& y = rec.columns.at(out);
    std::normal_distribution<double> noise(0.0, draw.noise_fraction * spread(y));
    for (double& v : y) v += noise(rng);
    // The achievable ceiling: the truth driven by the recorded (noisy, skewed) drives.
    o.ceiling = lumped::fit_percent(y, lumped::simulate_rig(draw.spec, rec).columns.at(out));
    const double e = draw.map_error;
    if (draw.spec.kind != RigKind::coil_bench) {
      const double yield_error = uniform(rng, 1 - e, 1 + e),
                   viscous_error = uniform(rng, 1 - e, 1 + e);
      for (double& p : rec.meta.valve.yield_pressure) p *= yield_error;
      *rec.meta.valve.viscous_resistance *= viscous_error;
      rec.meta.rig.chamber_volume = 2e-5;
    } else {
      *rec.meta.coil.resistance *= uniform(rng, 0.95, 1.05);
    }
    if (!draw.state_inductance) rec.meta.coil.inductance.reset();
    rec.csv_path = draw.truth + "_" + std::to_string(draw.index) + ".csv";
    rec.meta.sidecar_path = draw.truth + "_" + std::to_string(draw.index) + ".toml";
    const auto d = diagnose::diagnose(rec, options);
    if (std::getenv("RHEOMAG_CONFUSION_NOTES")) {
      std::ostringstream notes;
      notes << "  notes " << draw.truth << " #" << draw.index << ":";
      for (const auto& c : d.candidates)
        notes << " [" << c.step + 1 << " " << c.effect->name() << " dBIC " << fmt(c.delta_bic)
              << (c.screened ? " screened" : "") << "]";
      for (const auto& n : d.notes) notes << "\n    " << n;
      o.notes = notes.str();
    }
    o.final_fit = d.final_fit_percent;
    std::vector<std::string> truth_classes;
    for (const auto& t : draw.effects) truth_classes.push_back(effect_class(t));
    std::vector<std::string> named_classes;
    if (d.findings.empty()) {
      o.named = "none";
    } else {
      const auto& f = d.findings.front();
      o.named = f.effect->name();
      o.ambiguous = !f.ambiguous_with.empty();
      o.truth_in_ambiguous =
          std::find(draw.effects.begin(), draw.effects.end(), o.named) != draw.effects.end();
      for (const diagnose::Candidate* a : f.ambiguous_with)
        if (std::find(draw.effects.begin(), draw.effects.end(), a->name()) != draw.effects.end())
          o.truth_in_ambiguous = true;
      for (const auto& g : d.findings) {
        o.all_named += (o.all_named.empty() ? "" : "+") + g.effect->name() + "(" +
                       fmt(g.params.front()) +
                       (g.params.size() > 1 ? "," + fmt(g.params[1]) : std::string()) + ")";
        named_classes.push_back(effect_class(g.effect->name()));
      }
    }
    o.right = true;
    for (const auto& t : truth_classes)
      if (std::find(named_classes.begin(), named_classes.end(), t) == named_classes.end())
        o.right = false;
    // Anything named that was not concealed is false, and so is a second name for one
    // concealed effect (two field lags for one time constant).
    for (const auto& n : named_classes)
      if (std::count(named_classes.begin(), named_classes.end(), n) >
          std::count(truth_classes.begin(), truth_classes.end(), n))
        o.false_finding = true;
  } catch (const std::exception& e) {
    o.named = "error";
    o.all_named = e.what();
    o.false_finding = true;
  }
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  int draws = 20, threads = 1, index = -1;
  bool nuisances = true, visible = true;
  unsigned seed = 2026;
  std::string only, csv;
  diagnose::DiagnoseOptions options;
  for (int k = 1; k + 1 < argc; k += 2) {
    const std::string a = argv[k], v = argv[k + 1];
    if (a == "--draws")
      draws = std::atoi(v.c_str());
    else if (a == "--seed")
      seed = static_cast<unsigned>(std::atoi(v.c_str()));
    else if (a == "--threads")
      threads = std::max(1, std::atoi(v.c_str()));
    else if (a == "--only")
      only = v;
    else if (a == "--index")
      index = std::atoi(v.c_str());
    else if (a == "--csv")
      csv = v;
    else if (a == "--nuisances")
      nuisances = std::atoi(v.c_str()) != 0;
    else if (a == "--visible")
      visible = std::atoi(v.c_str()) != 0;
    else if (a == "--ringing-start")
      options.ringing_start = std::atoi(v.c_str()) != 0;
    else if (a == "--current-path")
      options.current_path = std::atoi(v.c_str()) != 0;
    else if (a == "--align-delay")
      options.align_delay = std::atoi(v.c_str()) != 0;
    else if (a == "--align-margin")
      options.align_delay_margin = std::atof(v.c_str());
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  std::vector<Draw> jobs;
  // The seed of each draw's recording (noise, sampling): from the draw's place in the whole
  // run, so that --only and --index re-run a draw of the whole run exactly.
  std::vector<unsigned> run_seeds;
  // Interleave the truths so that a run cut short still covers every class.
  for (int i = 0; i < draws; ++i)
    for (std::size_t c = 0; c < kTruths.size(); ++c)
      if ((only.empty() || only == kTruths[c]) && (index < 0 || index == i)) {
        jobs.push_back(make_draw(kTruths[c], i,
                                 seed + 1000u * static_cast<unsigned>(c) + static_cast<unsigned>(i),
                                 nuisances));
        const auto place = static_cast<unsigned>(i) * kTruths.size() + c;
        run_seeds.push_back(seed + 7u * static_cast<unsigned>(place) + 1u);
      }
  std::vector<Outcome> outcomes(jobs.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  std::ofstream table;
  if (!csv.empty()) {
    table.open(csv);
    table << "truth,index,named,ambiguous,truth_in_ambiguous,right,false_finding,all_named,"
             "final_fit,ceiling,seconds,visibility,enlarged,redrawn,draw\n";
  }
  auto worker = [&]() {
    for (std::size_t j = next++; j < jobs.size(); j = next++) {
      outcomes[j] = run(jobs[j], run_seeds[j], visible, options);
      const auto& o = outcomes[j];
      std::lock_guard<std::mutex> lock(print);
      std::cout << o.truth << " #" << jobs[j].index << " -> " << o.named
                << (o.ambiguous ? " (ambiguous)" : "") << " [" << o.all_named << "] "
                << (o.right ? "right" : "MISSED") << (o.false_finding ? " FALSE" : "") << " FIT "
                << fmt(o.final_fit) << "/" << fmt(o.ceiling) << " " << fmt(o.seconds) << " s  "
                << o.description << (o.visibility.empty() ? "" : " visibility=" + o.visibility)
                << (o.notes.empty() ? "" : "\n" + o.notes) << std::endl;
      if (table.is_open())
        table << o.truth << ',' << jobs[j].index << ',' << o.named << ',' << o.ambiguous << ','
              << o.truth_in_ambiguous << ',' << o.right << ',' << o.false_finding << ",\""
              << o.all_named << "\"," << o.final_fit << ',' << o.ceiling << ',' << o.seconds << ','
              << o.visibility << ',' << o.enlarged << ',' << o.redrawn << ",\"" << o.description
              << "\"" << std::endl;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  // Matrix: rows truth, columns first named (or "ambiguous").
  std::vector<std::string> columns = kTruths;
  columns.push_back("ambiguous");
  columns.push_back("error");
  std::map<std::string, std::map<std::string, int>> m;
  int total = 0, strict = 0, lenient = 0, clean = 0, false_findings = 0;
  int right = 0, any_false = 0, near_ceiling = 0;
  double seconds = 0.0;
  for (const auto& o : outcomes) {
    m[o.truth][o.ambiguous ? "ambiguous" : o.named]++;
    seconds += o.seconds;
    if (o.false_finding) ++any_false;
    if (o.named != "error" && o.final_fit >= o.ceiling - 2.0) ++near_ceiling;
    if (o.truth != "none" && o.right) ++right;
    if (o.truth == "none") {
      ++clean;
      if (o.named != "none") ++false_findings;
      continue;
    }
    ++total;
    if (o.named == o.truth && !o.ambiguous) ++strict;
    if (o.truth_in_ambiguous) ++lenient;
  }
  std::cout << "\n| truth \\ named first |";
  for (const auto& c : columns) std::cout << ' ' << c << " |";
  std::cout << "\n|---|";
  for (std::size_t c = 0; c < columns.size(); ++c) std::cout << "---|";
  std::cout << "\n";
  for (const auto& t : kTruths) {
    if (!m.count(t)) continue;
    std::cout << "| " << t << " |";
    for (const auto& c : columns) std::cout << ' ' << m[t][c] << " |";
    std::cout << "\n";
  }
  std::cout << "\nconcealed-effect draws: " << total << "; named first, unambiguous: " << strict
            << " (" << fmt(total ? 100.0 * strict / total : 0.0)
            << " %); truth named first or in the ambiguous set: " << lenient << " ("
            << fmt(total ? 100.0 * lenient / total : 0.0) << " %)\n";
  std::cout << "clean draws: " << clean << "; false findings: " << false_findings << " ("
            << fmt(clean ? 100.0 * false_findings / clean : 0.0) << " %)\n";
  const double all = static_cast<double>(outcomes.size());
  std::cout << "concealed-effect draws with every concealed effect named: " << right << " / "
            << total << " (" << fmt(total ? 100.0 * right / total : 0.0) << " %)\n";
  std::cout << "recordings with any false finding: " << any_false << " / " << outcomes.size()
            << " (" << fmt(all > 0 ? 100.0 * any_false / all : 0.0) << " %)\n";
  std::cout << "final FIT within 2 points of the achievable ceiling: " << near_ceiling << " / "
            << outcomes.size() << " (" << fmt(all > 0 ? 100.0 * near_ceiling / all : 0.0)
            << " %)\n";
  int enlarged = 0, redrawn = 0, adjusted = 0;
  for (const auto& o : outcomes) {
    enlarged += o.enlarged;
    redrawn += o.redrawn;
    if (o.enlarged > 0 || o.redrawn > 0) ++adjusted;
  }
  if (visible)
    std::cout << "visibility (signature rms >= " << fmt(kVisible)
              << " x output noise rms): " << adjusted << " / " << outcomes.size()
              << " draws adjusted (" << enlarged << " effect sizes enlarged, " << redrawn
              << " whole redraws)\n";
  std::cout << "diagnosis wall time: total " << fmt(seconds) << " s, mean "
            << fmt(outcomes.empty() ? 0.0 : seconds / static_cast<double>(outcomes.size()))
            << " s per recording\n";
  return 0;
}
