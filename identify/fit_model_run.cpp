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

DriveColumns drive_columns(const GreyboxFit& fit) {
  return {fit.setup.field_column, fit.setup.motion_column, fit.setup.position_column};
}

DriveColumns drive_columns(const ValveChainFit& fit) {
  return {fit.setup.field_column, fit.setup.motion_column, ""};
}

std::vector<RangeExcess> beyond_fitted_range(const FitModel& model, const lumped::Recording& rec) {
  if (!model.operating_range) return {};
  const DriveColumns cols =
      model.valve_chain ? drive_columns(*model.valve_chain) : drive_columns(*model.greybox);
  return beyond_range(*model.operating_range, operating_range(rec, cols));
}

}  // namespace rheomag::identify
