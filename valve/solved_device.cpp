// Gap sampling shared by the damper and the brake (solved_device.hpp).

#include "valve/solved_device.hpp"

#include "core/error.hpp"

namespace rheomag::valve {

SolvedDevice::SolvedDevice(const magnetostatics::MagnetostaticSolver& solver,
                           const magnetostatics::Solution& solution,
                           const magnetostatics::Results& results, const fluid::Fluid& fluid,
                           const std::string& device, double inner_radius,
                           const std::string& inner_key)
    : fluid_(fluid) {
  gaps_ = sample_gaps(solver, solution, results, inner_radius, inner_key);
  if (gaps_.empty())
    throw InputError(solver.problem().geometry.source + ": the " + device +
                     " case has no fluid gap");
  if (!results.circuits.empty()) {
    current_ = results.circuits.front().current;
    inductance_ = results.circuits.front().inductance;
  }
}

void SolvedDevice::clear_field() {
  zero_fields(gaps_);
  current_ = 0.0;
  inductance_ = 0.0;
}

}  // namespace rheomag::valve
