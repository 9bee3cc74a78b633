#include "transient/report.hpp"

#include "transient/lag_fit.hpp"

#include <cstdio>
#include <optional>
#include <sstream>
#include <vector>

namespace rheomag::transient {
namespace {

nlohmann::json optional_time(const std::optional<double>& t) {
  return t ? nlohmann::json(*t) : nlohmann::json(nullptr);
}

/// The reduced model of a response after the step (transient::fit_reduced_model; null when the
/// response does not change or has too few samples).
std::optional<ReducedModel> reduced_model(const TransientResult& r,
                                          const std::vector<double>& values, double end) {
  const std::vector<double> time(r.time.begin() + 1, r.time.end());
  const std::vector<double> after(values.begin() + 1, values.end());
  if (end == values.front() || time.size() < 5) return std::nullopt;
  return fit_reduced_model(time, after, values.front(), end);
}

nlohmann::json lags_array(const std::vector<Lag>& lags) {
  nlohmann::json out = nlohmann::json::array();
  for (const Lag& lag : lags)
    out.push_back({{"weight", lag.weight}, {"time_constant", lag.time_constant}});
  return out;
}

nlohmann::json reduced_model_json(const TransientResult& r, const std::vector<double>& values,
                                  double end) {
  const std::optional<ReducedModel> m = reduced_model(r, values, end);
  if (!m) return nullptr;
  char rule[200];
  std::snprintf(rule, sizeof rule,
                "two lags when their time constants differ by at least a factor %g and no "
                "|weight| exceeds %g; otherwise the better (smaller largest error) of one lag "
                "after a delay and a double lag",
                kMinLagSeparation, kMaxLagWeight);
  return {{"form", kReducedFormNames.name(m->form)},
          {"lags", lags_array(m->lags)},
          {"delay", m->delay},
          {"shape", m->shape},
          {"max_error", m->max_error},
          {"rule", rule},
          {"two_lag_fit", lags_array(m->two_lag_fit)}};
}

/// "one lag 12.3 ms after a delay of 4.5 ms", "double lag of 138 ms, shape -0.5 (...)" or "two lags
/// 2 ms (weight 0.3) and 20 ms (weight 0.7)", with the largest error.
std::string reduced_model_text(const ReducedModel& m) {
  char text[200];
  switch (m.form) {
    case ReducedForm::lag_with_delay:
      std::snprintf(text, sizeof text, "one lag %.4g ms after a delay of %.4g ms",
                    m.lags.front().time_constant * 1e3, m.delay * 1e3);
      break;
    case ReducedForm::double_lag:
      std::snprintf(text, sizeof text,
                    "double lag of %.4g ms, shape %.3g (transfer function (1 + %.4g p) / (1 + "
                    "%.4g p)^2, p the Laplace variable in 1/s)",
                    m.lags.front().time_constant * 1e3, m.shape,
                    (1.0 - m.shape) * m.lags.front().time_constant, m.lags.front().time_constant);
      break;
    case ReducedForm::two_lags:
      std::snprintf(text, sizeof text, "two lags %.4g ms (weight %.3g) and %.4g ms (weight %.3g)",
                    m.lags[0].time_constant * 1e3, m.lags[0].weight, m.lags[1].time_constant * 1e3,
                    m.lags[1].weight);
      break;
  }
  char error[80];
  std::snprintf(error, sizeof error, " (max error %.2g %% of the change)", 100.0 * m.max_error);
  return std::string(text) + error;
}

}  // namespace

nlohmann::json transient_json(const TransientResult& r, const TransientOptions& o) {
  nlohmann::json gaps = nlohmann::json::array();
  for (const GapSeries& g : r.gaps)
    gaps.push_back({{"name", g.name},
                    {"B_avg", g.b_avg},
                    {"B_final", g.final_b},
                    {"t63", optional_time(g.t63)},
                    {"t90", optional_time(g.t90)},
                    {"reduced_model", reduced_model_json(r, g.b_avg, g.final_b)}});
  const EnergyBalance& e = r.energy;
  nlohmann::json j = {
      {"drive", kDriveNames.name(o.drive)},
      {"value", o.value},
      {"from", o.from_current},
      {"resistance", o.resistance},
      {"scheme", kTimeSchemeNames.name(o.scheme)},
      {"duration", o.duration},
      {"time", r.time},
      {"current", r.current},
      {"flux_linkage", r.flux_linkage},
      {"eddy_power", r.eddy_power},
      {"gaps", gaps},
      {"final_current", r.final_current},
      {"final_flux_linkage", r.final_flux_linkage},
      {"t63", optional_time(r.t63)},
      {"t90", optional_time(r.t90)},
      {"reduced_model", reduced_model_json(r, r.flux_linkage, r.final_flux_linkage)},
      {"eddy_loss", e.eddy_loss},
      {"copper_loss", e.copper_loss},
      {"energy",
       {{"source", e.source},
        {"field_work", e.field_work},
        {"stored_change", e.stored_change},
        {"numerical_dissipation", e.numerical_dissipation},
        {"max_step_dissipation", e.max_step_dissipation},
        {"eddy_loss", e.eddy_loss},
        {"copper_loss", e.copper_loss},
        {"step_energy", e.step_energy},
        {"max_step_error", e.max_step_error},
        {"total_error", e.total_error}}},
      {"steps", r.steps},
      {"rejected_steps", r.rejected_steps},
      {"step_error", r.step_error},
      {"step_error_measured", r.step_error_measured},
      {"newton_iterations", r.newton_iterations},
      {"factorizations", r.factorizations},
      {"dofs", r.dofs},
      {"seconds", r.seconds}};
  if (const std::string warning = step_warning(r, o); !warning.empty()) j["warnings"] = {warning};
  return j;
}

std::string step_warning(const TransientResult& r, const TransientOptions& o) {
  if (o.steps == 0 || !r.step_error_measured || !(r.step_error > kFixedStepErrorLimit)) return "";
  char text[400];
  std::snprintf(text, sizeof text,
                "the %d equal steps do not resolve the response: the flux linkage is off by up "
                "to %.3g %% of its change (measured against a run of half the step); expected "
                "below %.3g %%: use more --steps, or adaptive steps (leave --steps out)",
                o.steps, 100.0 * r.step_error, 100.0 * kFixedStepErrorLimit);
  return text;
}

std::string transient_summary(const TransientResult& r, const TransientOptions& o) {
  std::ostringstream out;
  char line[200];
  auto ms = [](const std::optional<double>& t) {
    char text[32];
    if (!t) return std::string("not reached");
    std::snprintf(text, sizeof text, "%.4g ms", *t * 1e3);
    return std::string(text);
  };
  out << (o.drive == Drive::voltage ? "voltage" : "current") << " step to " << o.value
      << (o.drive == Drive::voltage ? " V" : " A") << " from " << o.from_current << " A";
  if (o.resistance > 0.0) out << ", coil resistance " << o.resistance << " Ohm";
  out << "\nsteady state after the step: " << r.final_current << " A, flux linkage "
      << r.final_flux_linkage * 1e3 << " mWb\n"
      << "flux linkage t63 " << ms(r.t63) << ", t90 " << ms(r.t90) << "\n";
  for (const GapSeries& g : r.gaps)
    out << "gap " << g.name << " mean |B| -> " << g.final_b * 1e3 << " mT: t63 " << ms(g.t63)
        << ", t90 " << ms(g.t90) << "\n";
  if (const auto m = reduced_model(r, r.flux_linkage, r.final_flux_linkage))
    out << "reduced model of the flux linkage: " << reduced_model_text(*m) << "\n";
  for (const GapSeries& g : r.gaps)
    if (const auto m = reduced_model(r, g.b_avg, g.final_b))
      out << "reduced model of gap " << g.name << " mean |B|: " << reduced_model_text(*m) << "\n";
  std::snprintf(line, sizeof line,
                "energy [J]: source %.6g = stored %.6g + numerical dissipation %.3g + eddy %.6g + "
                "copper %.6g (worst step balance %.2g)\n",
                r.energy.source, r.energy.stored_change, r.energy.numerical_dissipation,
                r.energy.eddy_loss, r.energy.copper_loss, r.energy.max_step_error);
  out << line;
  out << r.steps << " steps (" << r.rejected_steps << " rejected), " << r.newton_iterations
      << " Newton iterations, " << r.dofs << " dofs, " << r.seconds << " s\n";
  if (const std::string warning = step_warning(r, o); !warning.empty())
    out << "warning: " << warning << "\n";
  out << "\n";
  out << "    t [ms]     i [A]  lambda [mWb]";
  for (const GapSeries& g : r.gaps) out << "  " << g.name << " |B| [mT]";
  out << "\n";
  const std::size_t rows = r.time.size(), stride = rows > 21 ? (rows + 19) / 20 : 1;
  std::vector<std::size_t> shown;
  for (std::size_t k = 0; k < rows; k += stride) shown.push_back(k);
  if (!shown.empty() && shown.back() + 1 != rows) shown.push_back(rows - 1);
  for (std::size_t k : shown) {
    std::snprintf(line, sizeof line, "%10.4g %9.4g %13.5g", r.time[k] * 1e3, r.current[k],
                  r.flux_linkage[k] * 1e3);
    out << line;
    for (const GapSeries& g : r.gaps) {
      std::snprintf(line, sizeof line, "  %*.4g", static_cast<int>(g.name.size()) + 11,
                    g.b_avg[k] * 1e3);
      out << line;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace rheomag::transient
