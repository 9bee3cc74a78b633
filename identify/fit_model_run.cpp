// Running a fitted model read back from its JSON (see fit_model_json.hpp).

#include "core/error.hpp"
#include "identify/fit_model_json.hpp"

namespace rheomag::identify {

std::vector<double> simulate_fit_model(const lumped::Recording& rec, const FitModel& model) {
  if (rec.meta.output != model.output)
    throw InputError(rec.csv_path + ": output column '" + rec.meta.output + "', the " +
                     model.model + " model was fitted to '" + model.output + "'");
  if (model.valve_chain) return simulate_valve_chain(rec, *model.valve_chain);
  return simulate_greybox(rec, *model.greybox);
}

}  // namespace rheomag::identify
