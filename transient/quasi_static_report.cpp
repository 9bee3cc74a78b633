#include "transient/quasi_static_report.hpp"

#include <sstream>

#include "core/format_text.hpp"

namespace rheomag::transient {
namespace {

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::string optional_ms(const std::optional<double>& v) {
  return v ? format_text("%.4g ms", *v * 1e3) : std::string("not reached");
}

}  // namespace

nlohmann::json quasi_static_json(const QuasiStaticRun& run) {
  nlohmann::json j;
  j["model"] = "quasi_static";
  j["drive"] = run.drive;
  j["value"] = run.value;
  j["from"] = run.from_current;
  j["final_current"] = run.final_current;
  j["resistance"] = run.resistance;
  j["t63"] = optional_json(run.step.t63);
  j["t90"] = optional_json(run.step.t90);
  j["gaps"] = nlohmann::json::array();
  for (std::size_t g = 0; g < run.gap_names.size(); ++g) {
    j["gaps"].push_back({{"name", run.gap_names[g]},
                         {"B_from", run.step.gap_b_from[g]},
                         {"B_final", run.step.gap_b_final[g]},
                         {"t63", optional_json(run.step.gap_t63[g])},
                         {"t90", optional_json(run.step.gap_t90[g])}});
  }
  j["table"] = nlohmann::json::array();
  for (const QuasiStaticPoint& p : run.table.points)
    j["table"].push_back({{"current", p.current},
                          {"flux_linkage", p.flux_linkage},
                          {"inductance", p.inductance},
                          {"eddy_load", p.eddy_load}});
  j["newton_iterations"] = run.table.newton_iterations;
  j["dofs"] = run.dofs;
  return j;
}

std::string quasi_static_summary(const QuasiStaticRun& run) {
  std::ostringstream out;
  out << format_text(
      "quasi-static response (no time stepping; docs/transient.md): %s step to %.6g %s from "
      "%.6g A, final current %.6g A\n",
      run.drive.c_str(), run.value, run.drive == "voltage" ? "V" : "A", run.from_current,
      run.final_current);
  out << format_text("%zu static solves, %d Newton iterations, %d dofs\n", run.table.points.size(),
                     run.table.newton_iterations, run.dofs);
  out << "flux linkage: t63 " << optional_ms(run.step.t63) << ", t90 " << optional_ms(run.step.t90)
      << "\n";
  for (std::size_t g = 0; g < run.gap_names.size(); ++g)
    out << "gap " << run.gap_names[g] << ": t63 " << optional_ms(run.step.gap_t63[g]) << ", t90 "
        << optional_ms(run.step.gap_t90[g]) << "\n";
  return out.str();
}

}  // namespace rheomag::transient
