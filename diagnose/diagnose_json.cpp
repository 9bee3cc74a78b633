// The diagnosis in the fixed JSON format (shared/docs/recording-format.md) plus details.

#include <cmath>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_findings.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

namespace {

nlohmann::json nuisance_json(const Nuisance& u) {
  nlohmann::json j = {
      {"delay", u.delay},
      {"delay_samples", u.delay_samples},
      {"sampling", u.sampling},
      {"drive_sampling", kDriveSamplingNames.name(u.drive_sampling)},
      {"sampling_fit_gain",
       std::isfinite(u.sampling_fit_gain) ? nlohmann::json(u.sampling_fit_gain) : nlohmann::json()},
      {"drive_noise", u.drive_noise},
      {"velocity_filter_bandwidth", u.velocity_filter_bandwidth},
      {"current_reversal_band", u.current_reversal_band},
      {"motion_glitches", u.motion_glitches}};
  if (u.preyield_flow > 0.0) {
    j["preyield_flow"] = u.preyield_flow;
    j["preyield_fraction_of_peak_flow"] = u.preyield_fraction;
  }
  if (std::isfinite(u.slit_fraction)) j["slit_fraction"] = u.slit_fraction;
  return j;
}

/// A finding's size sensitivity (Finding::sensitivity): per ms of output delay, in its size's
/// parameter and derived quantities, and the linear effects of the same shape on this drive.
nlohmann::json sensitivity_json(const Finding& f) {
  using json = nlohmann::json;
  const SizeSensitivity& s = f.sensitivity;
  json out = json::object();
  if (std::isfinite(s.per_delay) && !f.param_names.empty()) {
    json per = {{f.param_names.front(), 1e-3 * s.per_delay}};
    for (const auto& q : s.derived_per_delay) per[q.name] = 1e-3 * q.value;
    out["per_ms_of_output_delay"] = std::move(per);
  }
  out["one_force_with"] = json::array();
  for (const ShapeTwin& twin : s.twins) {
    json same = {{"name", twin.effect->name()},
                 {"correlation", twin.correlation},
                 {"param", twin.param},
                 {"unit", twin.unit}};
    if (std::isfinite(twin.same_force_at)) {
      json at = {{twin.param, twin.same_force_at}};
      for (const auto& q : twin.same_force_derived) at[q.name] = q.value;
      same["same_force_at"] = std::move(at);
    }
    json per = {{f.param_names.front(), twin.size_per_unit}};
    for (const auto& q : twin.derived_per_unit) per[q.name] = q.value;
    same["per_unit_of_it"] = std::move(per);
    out["one_force_with"].push_back(std::move(same));
  }
  return out;
}

}  // namespace

nlohmann::json diagnosis_json(const Diagnosis& d) {
  using nlohmann::json;
  auto params_of = [](const ModelFit& f, std::size_t from, std::size_t to) {
    json p = json::object();
    for (std::size_t j = from; j < to; ++j) p[f.layout[j].name] = f.values[j];
    return p;
  };
  const std::size_t n_static = d.baseline.values.size();
  json out;
  out["recording"] = d.recording;
  out["baseline"] = {{"fit_percent", d.baseline_fit_percent},
                     {"params", params_of(d.baseline, 0, n_static)},
                     {"includes", json::array()},
                     {"nuisance", nuisance_json(d.nuisance)},
                     {"beyond_training", identify::range_excess_json(d.beyond_training)}};
  for (const auto& item : d.includes)
    out["baseline"]["includes"].push_back(
        {{"name", item.name},
         {"value", item.unit.empty() && item.value == 0.0 ? json() : json(item.value)},
         {"unit", item.unit},
         {"source", item.source}});
  out["mismatch"] = json::array();
  for (const auto& w : d.mismatch)
    out["mismatch"].push_back({{"t_start", w.t_start},
                               {"t_end", w.t_end},
                               {"share_of_residual", w.share},
                               {"regime", w.regime}});
  out["missing_physics"] = json::array();
  for (const auto& f : d.findings) {
    json p = json::object(), u = json::object(), units = json::object();
    for (std::size_t j = 0; j < f.params.size(); ++j) {
      p[f.param_names[j]] = f.params[j];
      if (j < f.param_units.size()) units[f.param_names[j]] = f.param_units[j];
      u[f.param_names[j]] =
          std::isfinite(f.standard_errors[j]) ? json(f.standard_errors[j]) : json();
    }
    for (const auto& q : f.derived) p[q.name] = q.value, units[q.name] = q.unit;
    json e = {{"name", f.effect->name()},
              {"params", p},
              {"standard_errors", u},
              {"units", units},
              {"accepted_at", selection_stage(f.step)},
              {"fit_percent", f.fit_percent},
              {"delta_bic", f.delta_bic},
              {"heldout_gain", f.heldout_gain},
              {"share_of_residual_above_noise", f.share},
              {"evidence", f.evidence}};
    if (std::isfinite(f.sensitivity.per_delay) || !f.sensitivity.twins.empty())
      e["size_sensitivity"] = sensitivity_json(f);
    if (!f.ruled_out_by_current.empty()) {
      e["ruled_out_by_measured_current"] = json::array();
      for (const Candidate* a : f.ruled_out_by_current)
        e["ruled_out_by_measured_current"].push_back(a->name());
    }
    if (!f.ambiguous_with.empty()) {
      e["ambiguous_with"] = json::array();
      for (const Candidate* a : f.ambiguous_with) e["ambiguous_with"].push_back(a->name());
      e["separating_measurement"] = f.separating_measurement;
      e["ambiguity"] = ambiguity_text(f, d);
    }
    out["missing_physics"].push_back(e);
  }
  out["final"] = {{"fit_percent", d.final_fit_percent},
                  {"params", params_of(d.final_fit, 0, d.final_fit.values.size())},
                  {"nuisance", nuisance_json(d.final_nuisance)}};
  out["unexplained"] = {{"share_of_residual", d.unexplained.share},
                        {"share_of_baseline_residual", d.unexplained.baseline_share},
                        {"noise_floor_rms", d.unexplained.noise_sigma},
                        {"residual_rms", d.unexplained.residual_rms}};
  json stats;
  stats["whiteness"] = {{"lag1_autocorrelation", d.baseline_stats.lag1_autocorrelation},
                        {"ljung_box_q", d.baseline_stats.ljung_box_q},
                        {"white", d.baseline_stats.white}};
  stats["correlations"] = json::array();
  for (const auto& c : d.baseline_stats.correlations)
    stats["correlations"].push_back({{"signal", c.signal}, {"value", c.value}, {"lag", c.lag}});
  stats["loops"] = json::array();
  for (const auto& l : d.baseline_stats.loops)
    stats["loops"].push_back({{"input", l.input},
                              {"opening", l.opening},
                              {"slow_fast_ratio", l.slow_fast_ratio},
                              {"rate_independent", l.rate_independent}});
  stats["output_lag"] = d.baseline_stats.output_lag;
  stats["final_white"] = d.final_stats.white;
  out["residual_statistics"] = stats;
  out["candidates"] = json::array();
  for (const auto& c : d.candidates) {
    json row = {{"name", c.effect->name()},
                {"step", c.step + 1},
                {"fit_percent", c.screened ? nlohmann::json() : nlohmann::json(c.fit_percent)},
                {"screened", c.screened},
                {"delta_bic", c.delta_bic},
                {"outcome", candidate_outcome(c, d)}};
    // Its own parameters as fitted at that step (what the recording carries of it, accepted
    // or not); a screened candidate was not fitted.
    if (!c.screened) {
      row["params"] = json::object();
      row["units"] = json::object();
      for (std::size_t j = 0; j < c.params.size(); ++j) {
        row["params"][c.param_names[j]] = c.params[j];
        row["units"][c.param_names[j]] = c.param_units[j];
      }
    }
    // Its size with the sign free (first step, linear candidates): what to subtract from
    // another recording's finding, also when this one's fit was screened or held at 0.
    if (!c.signed_params.empty()) {
      json p = json::object(), units = json::object();
      for (std::size_t j = 0; j < c.signed_params.size() && j < c.param_names.size(); ++j)
        p[c.param_names[j]] = c.signed_params[j], units[c.param_names[j]] = c.param_units[j];
      for (const auto& q : c.signed_derived) p[q.name] = q.value, units[q.name] = q.unit;
      row["signed_params"] = std::move(p);
      row["signed_units"] = std::move(units);
    }
    out["candidates"].push_back(std::move(row));
  }
  if (d.selection.size() > 0)
    out["selection_samples"] = {{"begin", d.selection.begin}, {"end", d.selection.end}};
  if (d.reference) {
    json changes = json::array();
    for (const EffectChange& e : d.reference->changes) {
      json row = {{"name", e.effect->name()},
                  {"param", e.param},
                  {"unit", e.unit},
                  {"today", e.today},
                  {"named_today", e.named_today},
                  {"reference", e.reference},
                  {"named_reference", e.named_reference},
                  {"change", e.change}};
      for (const DerivedParam& q : e.derived_change)
        row["derived_change"][q.name] = {{"change", q.value}, {"unit", q.unit}};
      for (const SameForce& same : e.same_force) {
        json one = {{"name", same.effect->name()},
                    {"correlation", same.correlation},
                    {"combined_change", same.combined_change}};
        for (const DerivedParam& q : same.combined_derived)
          one["combined_derived"][q.name] = {{"change", q.value}, {"unit", q.unit}};
        row["one_force_with"].push_back(std::move(one));
      }
      changes.push_back(std::move(row));
    }
    out["reference"] = {{"recording", d.reference->recording},
                        {"baseline_fit_percent", d.reference->baseline_fit_percent},
                        {"delay", d.reference->reference_delay},
                        {"missing_physics", d.reference->findings},
                        {"changes", std::move(changes)},
                        {"sized_on_one_only", d.reference->sized_on_one}};
  }
  out["notes"] = d.notes;
  return out;
}

}  // namespace rheomag::diagnose
