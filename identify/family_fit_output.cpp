// The JSON document and the text report of a current-dependent family fit (`rheomag
// fit-family`).

#include "identify/family_fit_output.hpp"

#include <algorithm>

#include "core/format_text.hpp"
#include "identify/fit_model_json.hpp"

namespace rheomag::identify {

namespace {

/// `value` of the member's calibrated level, null without one.
template <class Value>
nlohmann::json level_json(const FamilyMember& m, Value LevelCalibration::*value) {
  return m.level ? nlohmann::json((*m.level).*value) : nlohmann::json();
}

nlohmann::json regime_json(const RegimeResidual& r) {
  return {{"time_percent", r.time_percent},
          {"energy_percent", r.energy_percent},
          {"rms", r.rms},
          {"mean", r.mean}};
}

nlohmann::json regimes_json(const FamilyMember& m) {
  if (!m.regimes) return nullptr;
  return {{"transition", regime_json(m.regimes->transition)},
          {"positive", regime_json(m.regimes->positive)},
          {"negative", regime_json(m.regimes->negative)}};
}

nlohmann::json member_json(const FamilyMember& m) {
  return {
      {"file", m.csv_path},
      {"field", m.field},
      {"fit_percent", m.metrics.fit_percent},
      {"rmse_percent", m.metrics.rmse_percent},
      {"re", m.metrics.re},
      {"mean_removed", m.mean_removed},
      {"tared_at_rest_s", m.rest_seconds > 0.0 ? nlohmann::json(m.rest_seconds) : nlohmann::json()},
      {"band_rms", m.band ? nlohmann::json(m.band->rms) : nlohmann::json()},
      {"band_percent", m.band ? nlohmann::json(m.band->percent) : nlohmann::json()},
      {"repeatability_percent",
       m.repeatability ? nlohmann::json(*m.repeatability) : nlohmann::json()},
      {"level_fit_percent", level_json(m, &LevelCalibration::fit_percent)},
      {"level_pure_fit_percent", level_json(m, &LevelCalibration::pure_fit_percent)},
      {"level_gain", level_json(m, &LevelCalibration::gain)},
      {"level_offset", level_json(m, &LevelCalibration::offset)},
      {"level_window_s", level_json(m, &LevelCalibration::seconds)},
      {"level_window_start_s", level_json(m, &LevelCalibration::start_seconds)},
      {"viscosity_factor",
       m.viscosity_factor ? nlohmann::json(*m.viscosity_factor) : nlohmann::json()},
      {"viscosity_temperature_offset_k",
       m.viscosity_factor ? nlohmann::json(viscosity_temperature_offset(*m.viscosity_factor))
                          : nlohmann::json()},
      {"regimes", regimes_json(m)},
      {"beyond_training", range_excess_json(m.beyond)}};
}

/// Width of the recording column of every table: the longest name, at least 40 characters, so the
/// columns after it stay aligned whatever paths the user gave.
int name_width(const FamilyFit& r) {
  std::size_t width = 40;
  for (const auto* members : {&r.training, &r.predicted, &r.held_out})
    for (const FamilyMember& m : *members) width = std::max(width, m.csv_path.size());
  return static_cast<int>(width);
}

void print_members(std::ostream& out, const char* title, const std::vector<FamilyMember>& members,
                   int width) {
  const bool banded = std::any_of(members.begin(), members.end(),
                                  [](const FamilyMember& m) { return m.band.has_value(); });
  const bool levelled = std::any_of(members.begin(), members.end(),
                                    [](const FamilyMember& m) { return m.level.has_value(); });
  const bool factored = std::any_of(members.begin(), members.end(), [](const FamilyMember& m) {
    return m.viscosity_factor.has_value();
  });
  out << format_text("%s\n  %-*s %8s %8s %8s %6s%s%s%s\n", title, width, "recording", "field",
                     "FIT%", "RE", "rep%", banded ? "  band%" : "",
                     levelled ? "  after 1st steady cycle: FIT% pure -> 1 level (gain)" : "",
                     factored ? "  viscosity factor (fitted nuisance; K warmer at 2 %/K)" : "");
  for (const auto& m : members) {
    out << format_text("  %-*s %8.3g %8.1f %8.3f", width, m.csv_path.c_str(), m.field,
                       m.metrics.fit_percent, m.metrics.re);
    if (m.repeatability)
      out << format_text(" %6.1f", *m.repeatability);
    else
      out << format_text(" %6s", "-");
    if (banded)
      out << (m.band ? format_text("  %5.1f", m.band->percent) : format_text("  %5s", "-"));
    if (m.level)
      out << format_text("  %30.1f -> %5.1f (%.3f)", m.level->pure_fit_percent,
                         m.level->fit_percent, m.level->gain);
    else if (levelled)
      out << format_text("  %30s", "-");
    if (m.viscosity_factor)
      out << format_text("  %6.3f (%+.1f K)", *m.viscosity_factor,
                         viscosity_temperature_offset(*m.viscosity_factor));
    if (m.mean_removed)
      out << "  (mean removed: compared without the model's mean)";
    else if (m.rest_seconds > 0.0)
      out << format_text(
          "  (tared: the model's level set to the recording's over its first %.2f s "
          "at rest)",
          m.rest_seconds);
    out << "\n";
  }
}

/// One line per member: the share of its residual energy (and of its time) in each regime, and
/// the mean residual of the settled strokes.
void print_regimes(std::ostream& out, const char* title, const std::vector<FamilyMember>& members,
                   int width) {
  out << format_text("%s\n  %-*s %19s %31s %31s\n", title, width, "recording", "reversals",
                     "strokes with motion > 0", "strokes with motion < 0");
  for (const auto& m : members) {
    out << format_text("  %-*s", width, m.csv_path.c_str());
    if (!m.regimes) {
      out << "  - (constant motion)\n";
      continue;
    }
    const ResidualRegimes& g = *m.regimes;
    out << format_text(" %8.0f %% of %3.0f %%", g.transition.energy_percent,
                       g.transition.time_percent);
    for (const RegimeResidual* r : {&g.positive, &g.negative})
      out << format_text(" %5.0f %% of %3.0f %%, mean %+8.3g", r->energy_percent, r->time_percent,
                         r->mean);
    out << "\n";
  }
}

/// One line per drive quantity of a member beyond the recordings its model was fitted on.
void print_beyond(std::ostream& out, const char* what, const std::vector<FamilyMember>& members) {
  for (const FamilyMember& m : members)
    for (const RangeExcess& e : m.beyond)
      out << "  " << what << ": " << m.csv_path << ": " << e.text() << "\n";
}

/// One line comparing the held-out FITs with the fitted ones: the median and the lowest of each;
/// another for the held-out tests inside their refits' drive, when some are beyond it.
void print_held_out_summary(std::ostream& out, const FamilyFit& r) {
  const auto fits = [](const std::vector<FamilyMember>& members) {
    std::vector<double> v;
    for (const auto& m : members) v.push_back(m.metrics.fit_percent);
    std::sort(v.begin(), v.end());
    return v;
  };
  const std::vector<double> held = fits(r.held_out), fitted = fits(r.training);
  const auto median = [](const std::vector<double>& v) {
    const std::size_t h = v.size() / 2;
    return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
  };
  out << format_text(
      "held-out FIT: median %.1f %%, lowest %.1f %% (fitted on all: median %.1f %%, lowest "
      "%.1f %%)\n",
      median(held), held.front(), median(fitted), fitted.front());
  std::vector<FamilyMember> inside;
  for (const FamilyMember& m : r.held_out)
    if (m.beyond.empty()) inside.push_back(m);
  if (!inside.empty() && inside.size() < r.held_out.size()) {
    const std::vector<double> within = fits(inside);
    out << format_text(
        "held-out FIT within the drive each refit was fitted on: median %.1f %%, lowest %.1f %% "
        "(%zu of %zu tests; the other %zu extrapolate, above)\n",
        median(within), within.front(), inside.size(), r.held_out.size(),
        r.held_out.size() - inside.size());
  }
  std::vector<double> pure, levelled;
  for (const FamilyMember& m : r.held_out)
    if (m.level) {
      pure.push_back(m.level->pure_fit_percent);
      levelled.push_back(m.level->fit_percent);
    }
  if (pure.empty()) return;
  std::sort(pure.begin(), pure.end());
  std::sort(levelled.begin(), levelled.end());
  out << format_text(
      "held out, after the first cycle: median FIT %.1f %% pure, %.1f %% with one level per test "
      "(lowest %.1f %% -> %.1f %%)\n",
      median(pure), median(levelled), pure.front(), levelled.front());
}

}  // namespace

std::string decimation_text(int decimation) {
  if (decimation <= 1)
    return "samples: the fit uses every sample of each training recording (--decimation 1)";
  const int last = decimation % 10, tens = decimation % 100 / 10;
  const char* suffix = tens == 1   ? "th"
                       : last == 1 ? "st"
                       : last == 2 ? "nd"
                       : last == 3 ? "rd"
                                   : "th";
  return format_text(
      "samples: the fit uses every %d%s sample of each training recording (--decimation %d, "
      "default 4: samples 0, %d, %d, ...; 1/%d of the cost); the FIT and RE below are computed "
      "on every sample",
      decimation, suffix, decimation, decimation, 2 * decimation, decimation);
}

void write_family_fit_text(const FamilyFit& r, std::size_t recordings, int decimation,
                           std::ostream& out) {
  out << format_text("model %s, joint fit on %zu recordings\n", r.fit.model.c_str(), recordings);
  out << decimation_text(decimation) << "\n";
  out << format_text("  %-24s %14s %-13s %-13s\n", "parameter", "value", "+- classical",
                     "+- between recordings");
  const auto error_column = [&out](const std::optional<double>& e) {
    if (e)
      out << format_text(" +- %-10.3g", *e);
    else
      out << format_text("    %-10s", "");
  };
  for (const auto& p : r.fit.params) {
    out << format_text("  %-24s %14.6g", p.name.c_str(), p.value);
    error_column(p.standard_error);
    error_column(p.standard_error_between_recordings);
    const std::string remark = parameter_remark(p);
    out << format_text(" %s%s\n", p.unit.c_str(),
                       remark.empty() ? "" : (" (" + remark + ")").c_str());
  }
  if (const std::optional<double> above = level_in_motion_above_rest(r.fit))
    for (const auto& p : r.fit.params)
      if (p.name == "offset")
        out << format_text(
            "tared recordings: in motion the model's level is %.4g %s above their rest's (the "
            "offset less their mean level at rest)\n",
            *above, p.unit.c_str());
  if (r.fit.setup.motion_lead != 0.0)
    out << format_text("motion lead %.1f ms: the %s drive read this much later than recorded\n",
                       1e3 * r.fit.setup.motion_lead, r.fit.setup.motion_column.c_str());
  const int width = name_width(r);
  print_members(out, "training recordings:", r.training, width);
  if (!r.predicted.empty()) {
    print_members(out, "predicted recordings:", r.predicted, width);
    print_beyond(out, "beyond the training recordings' drive", r.predicted);
  }
  if (!r.held_out.empty()) {
    print_members(out,
                  "held out (each training recording predicted by the family fitted without it):",
                  r.held_out, width);
    print_beyond(out, "beyond the drive of the recordings its refit was fitted on", r.held_out);
    print_held_out_summary(out, r);
  }
  out << "residual by regime (% of the model's residual energy in % of the samples; mean "
         "residual of the settled strokes, model minus measured):\n";
  print_regimes(out, " training:", r.training, width);
  if (!r.predicted.empty()) print_regimes(out, " predicted:", r.predicted, width);
  if (!r.held_out.empty()) print_regimes(out, " held out:", r.held_out, width);
  out << format_text(
      "reversals: from each reversal of the motion until the measured force reaches %.0f %% of "
      "its median over the stroke (pre-yield, compliance, seal presliding, low speed)\n",
      100.0 * kSettledFraction);
  out << format_text(
      "rep%%: FIT of each recording's own mean cycle on its steady cycles, the most a model "
      "answering a periodic drive with a periodic output reaches there (- : drive not "
      "periodic)\n");
  if (!r.predicted.empty() || !r.held_out.empty())
    out << format_text(
        "band%%: the prediction's 1-sigma band from the parameters' spread between recordings; "
        "after 1st steady cycle: FIT on the samples after the first steady drive cycle (start-up "
        "cycles left out) of the prediction itself and with one gain and offset fitted on that "
        "cycle (least squares)\n");
}

nlohmann::json family_fit_json(const FamilyFit& r, const lumped::RecordingMeta& meta,
                               int decimation, bool cross_validate) {
  nlohmann::json j = fit_model_json(r.fit, meta);
  j["operating_range"] = operating_range_json(r.trained);
  j["train"] = nlohmann::json::array();
  for (const auto& m : r.training) j["train"].push_back(member_json(m));
  j["prediction"] = nlohmann::json::array();
  for (const auto& m : r.predicted) j["prediction"].push_back(member_json(m));
  if (cross_validate) {
    j["held_out"] = nlohmann::json::array();
    for (const auto& m : r.held_out) j["held_out"].push_back(member_json(m));
  }
  j["decimation"] = decimation;
  j["mode"] = "simulation";
  return j;
}

}  // namespace rheomag::identify
