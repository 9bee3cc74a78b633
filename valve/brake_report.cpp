#include "valve/brake_report.hpp"

#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::valve {

namespace {

nlohmann::json torque_json(const fluid::ShearTorque& t) {
  return {{"torque", t.torque},
          {"torque_yield", t.torque_yield},
          {"torque_viscous", t.torque_viscous},
          {"breakaway_torque", t.breakaway_torque},
          {"yielded_fraction", t.yielded_fraction}};
}

}  // namespace

BrakeReport evaluate_brake(const cases::Case& c, const std::vector<double>& currents,
                           const std::vector<double>& speeds, const ProgressCallback& progress) {
  const BrakeOptions options = read_brake_options(c);
  const std::vector<double> at_currents = currents_or_case(c, currents);
  const std::vector<double> at_speeds = speeds.empty() ? options.speeds : speeds;
  if (at_speeds.empty())
    throw InputError(c.source.string() +
                     ": no speed: pass --speed W[,W...] (rad/s) or set [brake] "
                     "speed in the case");
  BrakeChain chain(c, options);
  chain.set_progress(progress);
  return {c.name, chain.fluid().name, chain.evaluate(at_currents, at_speeds)};
}

nlohmann::json brake_json(const BrakeReport& report) {
  nlohmann::json out;
  out["case"] = report.case_name;
  out["fluid"] = report.fluid;
  out["points"] = nlohmann::json::array();
  for (const auto& p : report.points) {
    nlohmann::json gaps = nlohmann::json::array();
    for (const auto& g : p.gaps) {
      nlohmann::json gap = torque_json(g.torque);
      gap["name"] = g.name;
      gap["kind"] = g.kind;
      gap["b_average"] = g.b_average;
      gaps.push_back(gap);
    }
    nlohmann::json point = torque_json(p.torque);
    point["current"] = p.current;
    point["speed"] = p.speed;
    point["inductance"] = p.inductance;
    point["gaps"] = gaps;
    out["points"].push_back(point);
  }
  return out;
}

std::string brake_text(const BrakeReport& report) {
  std::string out =
      format_text("brake %s, fluid %s\n", report.case_name.c_str(), report.fluid.c_str());
  out += format_text("%8s %12s %12s %12s %12s %12s\n", "I [A]", "w [rad/s]", "T [N m]", "T_yield",
                     "T_viscous", "T(0+) [N m]");
  for (const auto& p : report.points)
    out += format_text("%8.4g %12.4g %12.5g %12.5g %12.5g %12.5g\n", p.current, p.speed,
                       p.torque.torque, p.torque.torque_yield, p.torque.torque_viscous,
                       p.torque.breakaway_torque);
  return out;
}

}  // namespace rheomag::valve
