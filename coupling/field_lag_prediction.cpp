// FE step responses of a case reduced to a current-dependent first-order field lag.

#include "coupling/field_lag_prediction.hpp"

#include <cmath>
#include <string>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "transient/from_case.hpp"
#include "transient/lag_fit.hpp"

namespace rheomag::coupling {

lumped::PredictedLag predict_field_lag(const std::filesystem::path& case_path,
                                       const std::vector<double>& currents) {
  const std::string where = case_path.string();
  if (currents.empty()) throw InputError(where + ": predicted field lag needs currents > 0 A");
  for (std::size_t k = 0; k < currents.size(); ++k)
    if (!(currents[k] > 0.0) || !std::isfinite(currents[k]) ||
        (k > 0 && !(currents[k] > currents[k - 1])))
      throw InputError(where + ": predicted field lag: currents must be > 0 A and increasing");
  const cases::Case c = cases::load_case(case_path);
  const transient::CaseTransient set_up = transient::transient_from_case(c);
  lumped::PredictedLag out;
  for (double current : currents) {
    double duration = 0.5;
    for (int attempt = 0;; ++attempt, duration *= 2.0) {
      transient::TransientOptions o =
          transient::step_options(transient::Drive::current, current, duration);
      o.tolerance = 1e-3;
      const transient::TransientResult r = set_up.solver->run(o);
      if (r.gaps.empty()) throw InputError(where + ": the case has no fluid gap");
      const transient::GapSeries* slowest = nullptr;
      bool reached = true;
      for (const transient::GapSeries& g : r.gaps) {
        if (!g.t90)
          reached = false;
        else if (!slowest || *g.t90 > *slowest->t90)
          slowest = &g;
      }
      if (!reached) {
        if (attempt == 4)
          throw ConvergenceError(where + ": the gaps' field did not settle within " +
                                 std::to_string(duration) + " s of a " + std::to_string(current) +
                                 " A step");
        continue;
      }
      // The response after the step (the entry at t = 0- is the state before it).
      const std::vector<double> time(r.time.begin() + 1, r.time.end());
      const std::vector<double> b(slowest->b_avg.begin() + 1, slowest->b_avg.end());
      const auto lags = transient::fit_lags(time, b, slowest->b_avg.front(), slowest->final_b, 1);
      out.current.push_back(current);
      out.time_constant.push_back(lags.front().time_constant);
      break;
    }
  }
  return out;
}

}  // namespace rheomag::coupling
