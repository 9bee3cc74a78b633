#include "valve/valve_report.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::valve {

namespace {

nlohmann::json segment_json(const SegmentResult& s) {
  const auto& d = s.drop.integrated;
  nlohmann::json out = {
      {"name", s.name},
      {"kind", std::string(kSegmentKindNames.name(s.kind))},
      {"b_average", s.b_average},
      {"dp", d.dp},
      {"dp_yield", d.dp_yield},
      {"dp_viscous", d.dp_viscous},
      {"dp_average_b", s.drop.average_b.dp},
      {"plug_fraction", d.plug_fraction},
      {"bingham_number", d.bingham_number},
      {"reynolds_number",
       s.kind == SegmentKind::passage ? nlohmann::json(s.reynolds_number) : nullptr}};
  // The field the yield drop was integrated over: s along the gap (axial distance from its
  // start, or the radius of a radial gap) [m] and |B_n| [T] on its mid-line.
  if (!s.field.position.empty()) out["profile"] = {{"s", s.field.position}, {"B_n", s.field.b}};
  return out;
}

}  // namespace

ValveReport evaluate_valve(const cases::Case& c, const ValveOptions& options,
                           const std::vector<double>& currents, const std::vector<double>& flows,
                           const ProgressCallback& progress) {
  const std::vector<double> at_currents = currents_or_case(c, currents);
  const std::vector<double> at_flows = flows.empty() ? options.flows : flows;
  if (at_flows.empty())
    throw InputError(c.source.string() + ": no flow rate: pass --flow Q[,Q...] (m^3/s) or set " +
                     "[valve] flow in the case");
  ValveChain chain(c, options);
  chain.set_progress(progress);
  ValveReport report;
  report.case_name = c.name;
  report.fluid = chain.fluid().name;
  report.options = options;
  report.points = chain.evaluate(at_currents, at_flows);
  report.flows_per_current = at_flows.size();
  report.turns = chain.turns();
  for (std::size_t k = 0; k < report.points.size(); ++k)
    if (std::abs(report.points[k].current) > std::abs(report.points[report.peak].current))
      report.peak = k;
  // The coil at the largest current (its secant inductance from the FE solve there).
  const ValvePoint& peak = report.points[report.peak];
  if (!options.wire.empty()) report.coil = chain.coil(peak.current, peak.inductance);
  return report;
}

nlohmann::json valve_json(const ValveReport& report) {
  nlohmann::json out;
  out["case"] = report.case_name;
  out["fluid"] = report.fluid;
  out["points"] = nlohmann::json::array();
  for (const auto& p : report.points) {
    nlohmann::json segments = nlohmann::json::array();
    for (const auto& s : p.segments) segments.push_back(segment_json(s));
    out["points"].push_back({{"current", p.current},
                             {"flow", p.flow},
                             {"dp_total", p.dp_total},
                             {"dp_yield", p.dp_yield},
                             {"dp_viscous", p.dp_viscous},
                             {"dp_total_average_b", p.dp_total_average_b},
                             {"inductance", p.inductance},
                             {"segments", segments}});
  }
  const ValvePoint& peak = report.points[report.peak];
  const bool have_wire = report.coil.has_value();
  nlohmann::json coil_json = {{"turns", report.turns},
                              {"current", peak.current},
                              {"inductance", peak.inductance},
                              {"wire", have_wire ? nlohmann::json(report.options.wire) : nullptr},
                              {"temperature", report.options.temperature}};
  if (have_wire) {
    coil_json["resistance"] = report.coil->resistance;
    coil_json["time_constant"] = report.coil->time_constant;
    coil_json["power"] = report.coil->power;
    coil_json["wire_length"] = report.coil->wire_length;
    coil_json["copper_fill"] = report.coil->copper_fill;
    coil_json["current_density"] = report.coil->current_density;
  } else {
    for (const char* key : {"resistance", "time_constant", "power"}) coil_json[key] = nullptr;
  }
  // L(I) from the FE solve at each requested current (one row per current).
  nlohmann::json table = nlohmann::json::array();
  for (std::size_t i = 0; i < report.points.size(); i += report.flows_per_current)
    table.push_back({{"current", report.points[i].current},
                     {"flux_linkage", report.points[i].flux_linkage},
                     {"inductance", report.points[i].inductance},
                     {"incremental_inductance", report.points[i].incremental_inductance}});
  coil_json["inductance_table"] = table;
  out["coil"] = coil_json;
  return out;
}

std::string valve_text(const ValveReport& report) {
  std::string out =
      format_text("valve %s, fluid %s\n", report.case_name.c_str(), report.fluid.c_str());
  out += format_text("%10s %12s %12s %12s %12s %14s\n", "I [A]", "Q [m3/s]", "dp [bar]",
                     "yield [bar]", "visc. [bar]", "avg-B [bar]");
  for (const auto& p : report.points)
    out += format_text("%10.4g %12.4g %12.5g %12.5g %12.5g %14.5g\n", p.current, p.flow,
                       p.dp_total * 1e-5, p.dp_yield * 1e-5, p.dp_viscous * 1e-5,
                       p.dp_total_average_b * 1e-5);
  out += format_text("%10s %14s %14s %16s\n", "I [A]", "lambda [Wb]", "L = l/I [H]", "dl/dI [H]");
  for (std::size_t i = 0; i < report.points.size(); i += report.flows_per_current)
    out += format_text("%10.4g %14.5g %14.5g %16.5g\n", report.points[i].current,
                       report.points[i].flux_linkage, report.points[i].inductance,
                       report.points[i].incremental_inductance);
  const ValvePoint& peak = report.points[report.peak];
  out += format_text("coil: %g turns, L = %.4g H at %g A", report.turns, peak.inductance,
                     peak.current);
  if (report.coil)
    out += format_text(
        ", R = %.4g Ohm (%s, %g C), L/R = %.4g s, P = %.4g W, J = %.4g A/mm^2, copper fill "
        "%.3f\n",
        report.coil->resistance, report.options.wire.c_str(), report.options.temperature,
        report.coil->time_constant, report.coil->power, report.coil->current_density * 1e-6,
        report.coil->copper_fill);
  else
    out += "; R, L/R and power need the wire: [valve] wire = \"AWG 24\" or --wire\n";
  return out;
}

}  // namespace rheomag::valve
