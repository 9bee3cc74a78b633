#pragma once
// The damper parameters the identify tests simulate their families with: a valve whose yield
// grows with the field, a compliance, a seal, a gas spring, a fluid inertance and a field lag.

#include <string>
#include <utility>
#include <vector>

#include "lumped/phenomenological.hpp"

namespace rheomag::test {

/// Damper parameters in the order of pheno_params(damper): the family's values with `set` on
/// top (by name); every parameter named in neither is 0.
inline std::vector<double> damper_family_truth(
    const std::vector<std::pair<std::string, double>>& set = {}) {
  std::vector<std::pair<std::string, double>> all = {{"yield", 60.0},
                                                     {"yield_per_field", 900.0},
                                                     {"yield_per_field2", -200.0},
                                                     {"consistency", 1500.0},
                                                     {"consistency_per_field", 3000.0},
                                                     {"flow_index", 0.5},
                                                     {"pre_yield_viscous", 1e5},
                                                     {"compliance_stiffness", 3e5},
                                                     {"stiffening", 500.0},
                                                     {"seal_friction", 30.0},
                                                     {"seal_presliding", 5e-4},
                                                     {"inertance", 5.0},
                                                     {"gas_stiffness", 800.0},
                                                     {"field_time_constant", 0.01}};
  all.insert(all.end(), set.begin(), set.end());
  using lumped::PhenoKind;
  std::vector<double> p(lumped::pheno_params(PhenoKind::damper).size(), 0.0);
  for (const auto& [name, value] : all)
    p.at(static_cast<std::size_t>(lumped::pheno_param_index(PhenoKind::damper, name))) = value;
  return p;
}

}  // namespace rheomag::test
