// Confusion-matrix benchmark of `rheomag diagnose` (issue 5): random virtual-rig recordings, each
// with one concealed effect (or none), random parameters, excitation, noise level, sidecar map
// error and rig kind; the diagnosis sees only the noisy recording. Prints one line per draw as it
// finishes, then the matrix truth x first named effect (an ambiguous first finding is its own
// column), the share named right and the false-finding rate on clean recordings.
// Not a Google Benchmark (it takes minutes):
//   bench_diagnose_confusion [--draws N] [--seed S] [--threads T] [--only NAME] [--csv FILE]

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

#include "diagnose/diagnose_run.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"
#include "lumped/signals.hpp"

namespace {

using namespace rheomag;
using diagnose::Effect;
using lumped::DriverMode;
using lumped::RigKind;

const std::vector<std::string> kTruths = {
    "none",          "compressibility", "fluid_inertia", "magnetic_hysteresis",
    "eddy_currents", "coil_inductance", "coil_heating",  "mr_response_time",
    "friction"};

/// One random draw: the truth spec, its drive and a description of what was drawn.
struct Draw {
  std::string truth;
  int index = 0;
  lumped::RigSpec spec;
  lumped::Recording drive;
  double noise_fraction = 0.0;  ///< noise std / output std
  std::string description;
};

/// Outcome of one diagnosed draw.
struct Outcome {
  std::string truth, named, all_named, description;
  bool ambiguous = false, truth_in_ambiguous = false;
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
  if (truth == "fluid_inertia") return {K::bypass_cylinder, K::damper};
  if (truth == "coil_inductance")
    return {K::coil_bench, K::constant_velocity_pump, K::bypass_cylinder, K::damper};
  if (truth == "none")
    return {K::coil_bench, K::constant_velocity_pump, K::bypass_cylinder, K::damper};
  return {K::constant_velocity_pump, K::bypass_cylinder, K::damper};
}

Draw make_draw(const std::string& truth, int index, unsigned seed) {
  std::mt19937 rng(seed);
  Draw d;
  d.truth = truth;
  d.index = index;
  auto& s = d.spec;
  s.kind = pick(rng, kinds_for(truth));
  s.piston_area = 4.524e-4;
  s.valve.yield_current = {0.0, 0.25, 0.5, 0.75, 1.0};
  s.valve.yield_pressure = {0.0, 1.9e6, 3.6e6, 4.9e6, 5.8e6};
  s.valve.viscous_resistance = log_uniform(rng, 5e9, 3e10);
  s.coil.resistance_20c = uniform(rng, 5.0, 12.0);
  if (s.kind == RigKind::damper) s.gas_force = uniform(rng, 0.0, 300.0);
  // Coil drive: voltage for coil effects and the coil bench, else a current source (and a
  // voltage-driven coil in a third of the clean hydraulic draws).
  const bool voltage = s.kind == RigKind::coil_bench || truth == "coil_inductance" ||
                       truth == "coil_heating" ||
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
  if (s.kind == RigKind::constant_velocity_pump) {
    const double v = uniform(rng, 0.005, 0.02);
    lumped::add_signal(d.drive, "velocity=constant:value=" + fmt(v));
    desc << " v=" << fmt(v);
  } else if (s.kind != RigKind::coil_bench) {
    const double amp = uniform(rng, 0.01, 0.025), f = uniform(rng, 0.5, 3.0);
    lumped::add_signal(d.drive, "displacement=sine:amplitude=" + fmt(amp) + ",frequency=" + fmt(f));
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
  lumped::add_signal(d.drive, std::string(voltage ? "voltage" : "current") + "=steps:levels=" + lv +
                                  ",period=" + fmt(period));
  desc << (voltage ? " V=" : " I=") << lv << " P=" << fmt(period) << "s";
  // The concealed effect.
  if (truth == "compressibility") {
    lumped::ChamberBlock c;
    c.oil_volume = 2e-5;
    c.air_volume = log_uniform(rng, 1e-7, 1e-6);
    s.compressibility = c;
    desc << " air=" << fmt(c.air_volume);
  } else if (truth == "fluid_inertia") {
    s.inertance = log_uniform(rng, 2e8, 2e9);
    desc << " L=" << fmt(*s.inertance);
  } else if (truth == "magnetic_hysteresis") {
    const double a = log_uniform(rng, 2.0, 10.0), dd = uniform(rng, 0.1, 0.6);
    s.magnetic_hysteresis = diagnose::duhem_field(a, dd);
    desc << " a=" << fmt(a) << " d=" << fmt(dd);
  } else if (truth == "eddy_currents") {
    s.eddy_time_constant = log_uniform(rng, 0.01, 0.06);
    desc << " tau=" << fmt(*s.eddy_time_constant);
  } else if (truth == "mr_response_time") {
    s.mr_response_time = log_uniform(rng, 0.01, 0.06);
    desc << " tau=" << fmt(*s.mr_response_time);
  } else if (truth == "coil_inductance") {
    s.coil.inductance = log_uniform(rng, 0.1, 0.9);
    desc << " L=" << fmt(s.coil.inductance);
  } else if (truth == "coil_heating") {
    lumped::ThermalBlock th;
    th.thermal_resistance = log_uniform(rng, 1.0, 8.0);
    th.thermal_time_constant = uniform(rng, 1.5, 5.0);
    s.coil_heating = th;
    desc << " Rth=" << fmt(th.thermal_resistance) << " tau=" << fmt(th.thermal_time_constant);
  } else if (truth == "friction") {
    s.coulomb_force = log_uniform(rng, 50.0, 400.0);
    desc << " Fc=" << fmt(*s.coulomb_force);
  }
  d.noise_fraction = uniform(rng, 0.002, 0.015);
  desc << " noise=" << fmt(100 * d.noise_fraction) << "%";
  d.description = desc.str();
  return d;
}

/// Simulates the draw, adds noise and the sidecar map error, and runs the diagnosis.
Outcome run(const Draw& draw, unsigned seed) {
  std::mt19937 rng(seed);
  Outcome o;
  o.truth = draw.truth;
  o.description = draw.description;
  const auto started = std::chrono::steady_clock::now();
  try {
    auto rec = lumped::simulate_rig(draw.spec, draw.drive);
    const std::string out = lumped::rig_output_column(draw.spec);
    auto& y = rec.columns.at(out);
    double mean = 0.0, var = 0.0;
    for (double v : y) mean += v;
    mean /= static_cast<double>(y.size());
    for (double v : y) var += (v - mean) * (v - mean);
    std::normal_distribution<double> noise(
        0.0, draw.noise_fraction * std::sqrt(var / static_cast<double>(y.size())));
    for (double& v : y) v += noise(rng);
    if (draw.spec.kind != RigKind::coil_bench) {
      const double yield_error = uniform(rng, 0.9, 1.1), viscous_error = uniform(rng, 0.9, 1.1);
      for (double& p : rec.meta.valve.yield_pressure) p *= yield_error;
      *rec.meta.valve.viscous_resistance *= viscous_error;
      rec.meta.rig.chamber_volume = 2e-5;
    } else {
      *rec.meta.coil.resistance *= uniform(rng, 0.95, 1.05);
    }
    rec.meta.coil.inductance.reset();
    rec.csv_path = draw.truth + "_" + std::to_string(draw.index) + ".csv";
    rec.meta.sidecar_path = draw.truth + "_" + std::to_string(draw.index) + ".toml";
    const auto d = diagnose::diagnose(rec);
    if (d.findings.empty()) {
      o.named = "none";
    } else {
      const auto& f = d.findings.front();
      o.named = diagnose::effect_name(f.effect);
      o.ambiguous = !f.ambiguous_with.empty();
      o.truth_in_ambiguous = o.named == o.truth;
      for (Effect e : f.ambiguous_with)
        if (diagnose::effect_name(e) == o.truth) o.truth_in_ambiguous = true;
      for (const auto& g : d.findings)
        o.all_named += (o.all_named.empty() ? "" : "+") + diagnose::effect_name(g.effect);
    }
  } catch (const std::exception& e) {
    o.named = "error";
    o.all_named = e.what();
  }
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  int draws = 20, threads = 1;
  unsigned seed = 2026;
  std::string only, csv;
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
    else if (a == "--csv")
      csv = v;
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  std::vector<Draw> jobs;
  // Interleave the truths so that a run cut short still covers every class.
  for (int i = 0; i < draws; ++i)
    for (std::size_t c = 0; c < kTruths.size(); ++c)
      if (only.empty() || only == kTruths[c])
        jobs.push_back(make_draw(
            kTruths[c], i, seed + 1000u * static_cast<unsigned>(c) + static_cast<unsigned>(i)));
  std::vector<Outcome> outcomes(jobs.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  std::ofstream table;
  if (!csv.empty()) {
    table.open(csv);
    table << "truth,index,named,ambiguous,truth_in_ambiguous,all_named,seconds,draw\n";
  }
  auto worker = [&]() {
    for (std::size_t j = next++; j < jobs.size(); j = next++) {
      outcomes[j] = run(jobs[j], seed + 7u * static_cast<unsigned>(j) + 1u);
      const auto& o = outcomes[j];
      std::lock_guard<std::mutex> lock(print);
      std::cout << o.truth << " #" << jobs[j].index << " -> " << o.named
                << (o.ambiguous ? " (ambiguous)" : "") << " [" << o.all_named << "] "
                << fmt(o.seconds) << " s  " << o.description << std::endl;
      if (table.is_open())
        table << o.truth << ',' << jobs[j].index << ',' << o.named << ',' << o.ambiguous << ','
              << o.truth_in_ambiguous << ",\"" << o.all_named << "\"," << o.seconds << ",\""
              << o.description << "\"" << std::endl;
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
  double seconds = 0.0;
  for (const auto& o : outcomes) {
    m[o.truth][o.ambiguous ? "ambiguous" : o.named]++;
    seconds += o.seconds;
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
  std::cout << "diagnosis wall time: total " << fmt(seconds) << " s, mean "
            << fmt(outcomes.empty() ? 0.0 : seconds / static_cast<double>(outcomes.size()))
            << " s per recording\n";
  return 0;
}
