// Python: Case.valve, Case.damper, Case.brake — the steady chain (FE field -> gap flow), each a
// dict built by the library function behind the CLI's --json.

#include <chrono>
#include <optional>

#include "core/error.hpp"
#include "coupling/quasi_static_request.hpp"
#include "coupling/step_request.hpp"
#include "python/bindings.hpp"
#include "python/handles.hpp"
#include "thermal/thermal_report.hpp"
#include "transient/quasi_static_report.hpp"
#include "transient/report.hpp"
#include "valve/brake_report.hpp"
#include "valve/damper_report.hpp"
#include "valve/valve_report.hpp"

namespace rheomag::python {

namespace {

py::object valve_dict(const CaseHandle& h, const std::vector<double>& currents,
                      const std::vector<double>& flows) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = valve::valve_json(
        valve::evaluate_valve(*h.c, valve::read_valve_options(*h.c), currents, flows));
  }
  return to_python(j);
}

py::object damper_dict(const CaseHandle& h, const std::vector<double>& currents,
                       const std::vector<double>& velocities) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = valve::damper_json(valve::evaluate_damper(*h.c, currents, velocities));
  }
  return to_python(j);
}

py::object brake_dict(const CaseHandle& h, const std::vector<double>& currents,
                      const std::vector<double>& speeds) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = valve::brake_json(valve::evaluate_brake(*h.c, currents, speeds));
  }
  return to_python(j);
}

py::object step_response(const CaseHandle& h, std::optional<double> duration,
                         std::optional<double> current, std::optional<double> voltage, double from,
                         int steps, double tolerance, int newton_iterations,
                         const std::string& scheme, std::optional<double> resistance,
                         bool quasi_static, int table_points, const py::object& progress) {
  coupling::StepRequest r;
  r.current = current;
  r.voltage = voltage;
  r.duration = duration.value_or(0.0);
  r.from = from;
  r.steps = steps;
  r.tolerance = tolerance;
  r.newton_iterations = newton_iterations;
  r.scheme = scheme;
  r.resistance = resistance;
  r.progress = progress_to_python(progress);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    if (quasi_static) {
      j = transient::quasi_static_json(
          coupling::quasi_static_response(*h.c, h.path, r, table_points));
      j["case"] = h.c->name;
    } else {
      if (!duration)
        throw InputError("--duration is required (the simulated time after the step), e.g. 50ms");
      const coupling::PreparedStep step = coupling::prepare_step(*h.c, h.path, r);
      const auto start = std::chrono::steady_clock::now();
      const transient::TransientResult result = step.set_up.solver->run(step.options, {});
      j = transient::transient_json(result, step.options);
      j["case"] = h.c->name;
      j["seconds"] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  }
  return to_python(j);
}

py::object thermal_dict(const CaseHandle& h, std::optional<double> current,
                        std::optional<double> flow, std::optional<double> velocity,
                        std::optional<double> speed, double duty, std::optional<double> temperature,
                        std::optional<double> duration, int steps, std::optional<double> limit) {
  if (flow.has_value() + velocity.has_value() + speed.has_value() > 1)
    throw InputError("thermal: give at most one of flow, velocity and speed");
  thermal::ThermalRequest r;
  r.point.duty = duty;
  r.point.current =
      current.value_or(h.c->problem.circuits.empty() ? 0.0 : h.c->problem.circuits.back().current);
  if (flow) r.point.motion = thermal::Motion::flow, r.point.value = *flow;
  if (velocity) r.point.motion = thermal::Motion::velocity, r.point.value = *velocity;
  if (speed) r.point.motion = thermal::Motion::speed, r.point.value = *speed;
  r.temperature = temperature;
  r.duration = duration;
  r.steps = steps;
  r.limit = limit;
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = thermal::thermal_json(thermal::run_thermal(*h.c, r));
  }
  return to_python(j);
}

}  // namespace

void bind_chain(py::class_<CaseHandle>& c) {
  c.def("valve", &valve_dict, py::arg("currents") = std::vector<double>{},
        py::arg("flows") = std::vector<double>{},
        "Steady valve chain at `currents` [A] x `flows` [m^3/s] (empty: the case's [valve]); "
        "the dict of `rheomag valve --json` (pressure drops in Pa).");
  c.def("damper", &damper_dict, py::arg("currents") = std::vector<double>{},
        py::arg("velocities") = std::vector<double>{},
        "Force-velocity of the case's [damper] piston at `currents` [A] x `velocities` [m/s]; "
        "the dict of `rheomag damper --json` (forces in N).");
  c.def("brake", &brake_dict, py::arg("currents") = std::vector<double>{},
        py::arg("speeds") = std::vector<double>{},
        "Torque-speed of the case's brake at `currents` [A] x `speeds` [rad/s]; the dict of "
        "`rheomag brake --json` (torques in N m).");
  c.def("thermal", &thermal_dict, py::kw_only(), py::arg("current") = py::none(),
        py::arg("flow") = py::none(), py::arg("velocity") = py::none(),
        py::arg("speed") = py::none(), py::arg("duty") = 1.0, py::arg("temperature") = py::none(),
        py::arg("duration") = py::none(), py::arg("steps") = 200, py::arg("limit") = py::none(),
        "Coil and fluid temperatures at one operating point (a valve's flow [m^3/s], a damper's "
        "velocity [m/s] or a brake's speed [rad/s]; duty in [0, 1]): steady and coupled, at a "
        "given temperature [deg C], or heating from ambient for `duration` [s]; the dict of "
        "`rheomag thermal --json` (docs/thermal.md).");
  c.def("transient", &step_response, py::kw_only(), py::arg("duration") = py::none(),
        py::arg("current") = py::none(), py::arg("voltage") = py::none(),
        py::arg("from_current") = 0.0, py::arg("steps") = 0, py::arg("tolerance") = 1e-4,
        py::arg("newton_iterations") = 50, py::arg("scheme") = "midpoint",
        py::arg("resistance") = py::none(), py::arg("quasi_static") = false,
        py::arg("table_points") = 8, py::arg("progress") = py::none(),
        "Step response with eddy currents from the steady state at `from_current` [A]: a current "
        "[A] or voltage [V] step for `duration` [s] (steps=0: adaptive); the dict of "
        "`rheomag transient --json`. progress(event: dict) after each accepted step. "
        "quasi_static=True: no time stepping and no duration; the rise times from a table of "
        "static states (`table_points` starting currents), the dict of `rheomag transient "
        "--quasi-static --json` (docs/transient.md).");
}

}  // namespace rheomag::python
