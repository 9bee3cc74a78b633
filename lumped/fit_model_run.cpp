// Running a fitted model read back from its JSON (see fit_model_json.hpp).

#include "core/error.hpp"
#include "lumped/fit_model_json.hpp"

namespace rheomag::lumped {

std::vector<double> simulate_fit_model(const Recording& rec, const FitModel& model) {
  if (rec.meta.output != model.output)
    throw InputError(rec.csv_path + ": output column '" + rec.meta.output + "', the " +
                     model.model + " model was fitted to '" + model.output + "'");
  if (model.valve_chain) return simulate_valve_chain(rec, *model.valve_chain);
  return simulate_greybox(rec, *model.greybox);
}

}  // namespace rheomag::lumped
