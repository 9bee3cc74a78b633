// Parameter tables of the phenomenological models.

#include "lumped/phenomenological.hpp"

namespace rheomag::lumped {

bool parse_pheno_kind(const std::string& name, PhenoKind& kind) {
  if (name == "bingham")
    kind = PhenoKind::bingham;
  else if (name == "lugre")
    kind = PhenoKind::lugre;
  else if (name == "bouc-wen")
    kind = PhenoKind::bouc_wen;
  else if (name == "maxwell")
    kind = PhenoKind::maxwell;
  else if (name == "dahl")
    kind = PhenoKind::dahl;
  else if (name == "bi-viscous")
    kind = PhenoKind::biviscous;
  else if (name == "tanh")
    kind = PhenoKind::tanh;
  else if (name == "damper")
    kind = PhenoKind::damper;
  else
    return false;
  return true;
}

std::string pheno_name(PhenoKind kind) {
  switch (kind) {
    case PhenoKind::bingham:
      return "bingham";
    case PhenoKind::lugre:
      return "lugre";
    case PhenoKind::bouc_wen:
      return "bouc-wen";
    case PhenoKind::maxwell:
      return "maxwell";
    case PhenoKind::dahl:
      return "dahl";
    case PhenoKind::biviscous:
      return "bi-viscous";
    case PhenoKind::tanh:
      return "tanh";
    case PhenoKind::damper:
      return "damper";
  }
  return "";
}

const std::vector<PhenoParam>& pheno_params(PhenoKind kind) {
  static const std::vector<PhenoParam> bingham = {{"yield", "Y", false},
                                                  {"yield_per_field", "Y/U", true},
                                                  {"viscous", "Y/M", false},
                                                  {"viscous_per_field", "Y/(M U)", true},
                                                  {"transition", "M", false},
                                                  {"offset", "Y", false},
                                                  {"output_smoothing", "1", false, true}};
  static const std::vector<PhenoParam> lugre = {{"stiffness", "Y", false},
                                                {"stiffness_per_field", "Y/U", true},
                                                {"damping", "Y s", false},
                                                {"rate", "1/X", false},
                                                {"viscous", "Y", false},
                                                {"viscous_per_field", "Y/U", true},
                                                {"exponent", "1", false},
                                                {"offset", "Y", false},
                                                {"output_smoothing", "1", false, true}};
  static const std::vector<PhenoParam> bouc_wen = {
      {"alpha_a", "Y/X", false}, {"alpha_b", "Y/(X U)", true},
      {"c0_a", "Y/M", false},    {"c0_b", "Y/(M U)", true},
      {"c1_a", "Y/M", false},    {"c1_b", "Y/(M U)", true},
      {"k0", "Y/X", false},      {"k1", "Y/X", false},
      {"gamma", "1/X^2", false}, {"beta", "1/X^2", false},
      {"A", "1", false},         {"eta", "1/s", true},
      {"offset", "Y", false},    {"output_smoothing", "1", false, true}};
  static const std::vector<PhenoParam> maxwell = {{"time_constant", "s", false},
                                                  {"viscous", "Y/M", false},
                                                  {"field_force", "Y", false},
                                                  {"field_force_per_field", "Y/U", true},
                                                  {"shape", "1/M", false},
                                                  {"offset", "Y", false},
                                                  {"output_smoothing", "1", false, true}};
  static const std::vector<PhenoParam> dahl = {{"viscous", "Y/M", false},
                                               {"dahl_force", "Y", false},
                                               {"dahl_force_per_field", "Y/U", true},
                                               {"sigma", "1/X", false},
                                               {"stiffness", "Y/X", false},
                                               {"offset", "Y", false},
                                               {"output_smoothing", "1", false, true}};
  static const std::vector<PhenoParam> biviscous = {{"yield", "Y", false},
                                                    {"yield_per_field", "Y/U", true},
                                                    {"post_yield", "Y/M", false},
                                                    {"post_yield_per_field", "Y/(M U)", true},
                                                    {"pre_yield", "Y/M", false},
                                                    {"offset", "Y", false},
                                                    {"output_smoothing", "1", false, true}};
  static const std::vector<PhenoParam> tanh_model = {{"viscous", "Y/M", false},
                                                     {"viscous_per_field", "Y/(M U)", true},
                                                     {"stiffness", "Y/X", false},
                                                     {"hysteretic", "Y", false},
                                                     {"hysteretic_per_field", "Y/U", true},
                                                     {"shape", "1/M", false},
                                                     {"lag", "1", false},
                                                     {"offset", "Y", false},
                                                     {"output_smoothing", "1", false, true}};
  static const std::vector<PhenoParam> damper = {{"yield", "Y", false},
                                                 {"yield_per_field", "Y/U", true},
                                                 {"yield_per_field2", "Y/U^2", true},
                                                 {"consistency", "Y/M", false},
                                                 {"consistency_per_field", "Y/(M U)", true},
                                                 {"flow_index", "1", false},
                                                 {"pre_yield_viscous", "Y/M", false},
                                                 {"compliance_stiffness", "Y/X", false},
                                                 {"stiffening", "1/X", false},
                                                 {"seal_friction", "Y", false},
                                                 {"seal_friction_per_field", "Y/U", true, true},
                                                 {"seal_presliding", "X", false},
                                                 {"inertance", "Y s/M", false},
                                                 {"gas_stiffness", "Y/X", false},
                                                 {"field_time_constant", "s", true},
                                                 {"offset", "Y", false},
                                                 {"field_saturation", "1/U^2", true, true},
                                                 {"output_smoothing", "1", false, true}};
  switch (kind) {
    case PhenoKind::biviscous:
      return biviscous;
    case PhenoKind::tanh:
      return tanh_model;
    case PhenoKind::damper:
      return damper;
    case PhenoKind::bingham:
      return bingham;
    case PhenoKind::lugre:
      return lugre;
    case PhenoKind::bouc_wen:
      return bouc_wen;
    case PhenoKind::maxwell:
      return maxwell;
    case PhenoKind::dahl:
      return dahl;
  }
  return bingham;
}

Domain pheno_param_domain(PhenoKind kind, std::size_t index) {
  const std::vector<PhenoParam>& params = pheno_params(kind);
  if (index >= params.size()) return Domain::finite();
  const std::string& n = params[index].name;
  const auto named = [&](std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* x) { return n == x; });
  };
  if (n == "output_smoothing") return Domain::between(0.0, 0.25);
  switch (kind) {
    case PhenoKind::bingham:
      if (n == "transition") return Domain::positive();
      if (named({"yield", "viscous"})) return Domain::non_negative();
      break;
    case PhenoKind::lugre:
      if (n == "exponent") return Domain::between(0.2, 2.0);
      if (n == "rate") return Domain::positive();
      if (named({"stiffness", "viscous"})) return Domain::non_negative();
      break;
    case PhenoKind::bouc_wen:
      if (n == "eta") return Domain::between(1.0, 5000.0);
      if (n == "A") return Domain::positive();
      if (named({"alpha_a", "c0_a", "c1_a", "k0", "gamma", "beta"})) return Domain::non_negative();
      break;
    case PhenoKind::maxwell:
      if (n == "time_constant") return Domain::between(1e-5, 2.0);
      if (n == "shape") return Domain::positive();
      if (named({"viscous", "field_force"})) return Domain::non_negative();
      break;
    case PhenoKind::dahl:
      if (n == "sigma") return Domain::positive();
      if (named({"viscous", "dahl_force"})) return Domain::non_negative();
      break;
    case PhenoKind::biviscous:
      if (n == "pre_yield") return Domain::positive();
      if (named({"yield", "post_yield"})) return Domain::non_negative();
      break;
    case PhenoKind::tanh:
      if (n == "lag") return Domain::between(-5.0, 5.0);
      if (n == "shape") return Domain::positive();
      if (named({"viscous", "hysteretic"})) return Domain::non_negative();
      break;
    case PhenoKind::damper:
      if (n == "flow_index") return Domain::between(0.2, 2.0);
      if (n == "field_time_constant") return Domain::between(1e-4, 1.0);
      if (named({"consistency", "pre_yield_viscous", "compliance_stiffness", "seal_presliding"}))
        return Domain::positive();
      if (named({"yield", "stiffening", "seal_friction", "field_saturation",
                 "seal_friction_per_field"}))
        return Domain::non_negative();
      break;
  }
  return Domain::finite();
}

std::size_t pheno_smoothing_index(PhenoKind kind) {
  return pheno_params(kind).size() - 1;
}

std::size_t pheno_state_count(PhenoKind kind) {
  switch (kind) {
    case PhenoKind::bingham:
      return 0;
    case PhenoKind::lugre:
      return 1;
    case PhenoKind::bouc_wen:
      return 3;
    case PhenoKind::maxwell:
      return 1;
    case PhenoKind::dahl:
      return 1;
    case PhenoKind::biviscous:
    case PhenoKind::tanh:
      return 0;
    case PhenoKind::damper:
      return 3;
  }
  return 0;
}

int pheno_param_index(PhenoKind kind, const std::string& name) {
  const auto& params = pheno_params(kind);
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace rheomag::lumped
