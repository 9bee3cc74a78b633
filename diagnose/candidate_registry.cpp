// The candidate registry: one line per candidate (its file is diagnose/candidates/<name>.cpp).

#include "diagnose/candidate_registry.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace rheomag::diagnose {

namespace candidates {
// The candidates' objects, one per file in diagnose/candidates/.
const Candidate& compressibility();
const Candidate& fluid_inertia();
const Candidate& magnetic_hysteresis();
const Candidate& eddy_currents();
const Candidate& coil_inductance();
const Candidate& coil_heating();
const Candidate& mr_response_time();
const Candidate& friction();
const Candidate& pre_yield();
const Candidate& fluid_heating();
const Candidate& gas_spring();
}  // namespace candidates

namespace {

/// One registered candidate and its place in the trial order of each kind of baseline.
struct Registration {
  const Candidate* candidate;
  int sidecar_rank;  ///< place among the candidates tried on a sidecar baseline
  int fitted_rank;   ///< place on a fitted-model baseline (0: it does not compose with one)
};

/// The registry. On a sidecar baseline the chamber candidates come first, then the lags and the
/// coil, friction last; on a fitted model the blocks on its inputs come before those on its
/// output. Changing a rank changes which of two equally good candidates is named.
const std::vector<Registration>& registry() {
  static const std::vector<Registration> r = {
      {&candidates::compressibility(), 1, 0},     {&candidates::fluid_inertia(), 3, 5},
      {&candidates::magnetic_hysteresis(), 6, 3}, {&candidates::eddy_currents(), 5, 2},
      {&candidates::coil_inductance(), 7, 4},     {&candidates::coil_heating(), 8, 0},
      {&candidates::mr_response_time(), 4, 1},    {&candidates::friction(), 9, 6},
      {&candidates::pre_yield(), 2, 0},           {&candidates::fluid_heating(), 10, 0},
      {&candidates::gas_spring(), 11, 7},
  };
  return r;
}

std::vector<const Candidate*> ordered(bool fitted) {
  auto r = registry();
  std::stable_sort(r.begin(), r.end(), [fitted](const Registration& a, const Registration& b) {
    return fitted ? a.fitted_rank < b.fitted_rank : a.sidecar_rank < b.sidecar_rank;
  });
  std::vector<const Candidate*> out;
  for (const auto& x : r)
    if (!fitted || x.fitted_rank > 0) out.push_back(x.candidate);
  return out;
}

}  // namespace

const std::vector<const Candidate*>& registered_candidates() {
  static const std::vector<const Candidate*> all = [] {
    std::vector<const Candidate*> out;
    for (const auto& x : registry()) out.push_back(x.candidate);
    return out;
  }();
  return all;
}

const std::vector<const Candidate*>& candidates_in_trial_order(bool fitted) {
  static const std::vector<const Candidate*> sidecar = ordered(false), model = ordered(true);
  return fitted ? model : sidecar;
}

std::vector<const Candidate*> applicable_candidates(const DiagnosisModel& model) {
  std::vector<const Candidate*> out;
  for (const Candidate* c : candidates_in_trial_order(model.fitted_baseline()))
    if (c->applies(model)) out.push_back(c);
  return out;
}

const Candidate& candidate_named(std::string_view name) {
  for (const Candidate* c : registered_candidates())
    if (c->name() == name) return *c;
  throw InputError("diagnose: no candidate called '" + std::string(name) + "'");
}

}  // namespace rheomag::diagnose
