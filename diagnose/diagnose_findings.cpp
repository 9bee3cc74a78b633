// The text of a finding: its evidence sentence and what would tell it from a tied candidate.

#include "diagnose/diagnose_findings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose {

std::string finding_evidence(const Finding& f, const Diagnosis& d, const ModelFit& fit) {
  std::string text = f.effect->evidence(d, fit);
  const auto& correlations = d.baseline_stats.correlations;
  if (!correlations.empty())
    text += "; strongest residual correlation: " + correlations.front().signal + " (" +
            fmt(correlations.front().value, 2) + ")";
  if (!f.ruled_out_by_current.empty()) {
    text += "; the output alone fits as well with";
    for (const Candidate* e : f.ruled_out_by_current) text += " " + e->name();
    text += ", but the measured coil current rules that out";
  }
  return text;
}

std::string separating_measurement(const Candidate& a, const Candidate& b) {
  if (auto how = a.separating_measurement(b); !how.empty()) return how;
  if (auto how = b.separating_measurement(a); !how.empty()) return how;
  return "excite the device at several frequencies and amplitudes: the two effects scale "
         "differently with rate and amplitude";
}

std::string selection_stage(int step) {
  return "selection step " + std::to_string(step + 1);
}

std::string percent_text(double percent) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", percent);
  return text;
}

namespace {

std::string significant(double value, int digits) {
  char text[48];
  std::snprintf(text, sizeof text, "%#.*g", digits, value);
  std::string out = text;
  if (!out.empty() && out.back() == '.') out.pop_back();  // "%#g" keeps a bare point
  return out;
}

}  // namespace

std::string value_text(double value, const std::string& unit) {
  const std::string number = significant(value, 3);
  return unit.empty() || unit == "1" ? number : number + " " + unit;
}

std::string delay_text(const Nuisance& u) {
  char text[160];
  const double samples = u.delay_samples;
  std::snprintf(text, sizeof text, "%+.3g ms (%+.2f samples, %s)", 1e3 * u.delay, samples,
                std::abs(samples) < 0.25 ? "output and drives aligned"
                : samples > 0.0          ? "output behind the drives"
                                         : "output ahead of the drives");
  return text;
}

std::string parameter_text(const Finding& f, std::size_t j, const std::string& plus_minus) {
  const std::string unit = j < f.param_units.size() ? f.param_units[j] : "";
  std::string text = f.param_names[j] + " = " + value_text(f.params[j], unit);
  // A standard error is infinite (or unknown) where the parameter is not identified.
  if (std::isfinite(f.standard_errors[j])) {
    const std::string se = significant(f.standard_errors[j], 2);
    text += " " + plus_minus + " " + (unit.empty() || unit == "1" ? se : se + " " + unit);
  } else {
    text += " (standard error unbounded)";
  }
  return text;
}

namespace {

/// `size` of finding `f` as its first derived quantity when it has one (a moving mass rather
/// than an inertance), else in its size's unit; `derived` the derived quantities at `size`.
std::string size_text(const Finding& f, double size, const std::vector<DerivedParam>& derived) {
  if (!derived.empty()) return value_text(derived.front().value, derived.front().unit);
  return value_text(size, f.param_units.empty() ? "" : f.param_units.front());
}

}  // namespace

std::vector<std::string> sensitivity_lines(const Finding& f) {
  std::vector<std::string> lines;
  const SizeSensitivity& s = f.sensitivity;
  if (std::isfinite(s.per_delay) && !f.params.empty()) {
    const double per_ms = 1e-3 * s.per_delay;
    std::vector<DerivedParam> derived = s.derived_per_delay;
    for (auto& q : derived) q.value *= 1e-3;
    const double share = f.params.front() != 0.0 ? std::abs(per_ms / f.params.front()) : 0.0;
    lines.push_back(std::string(per_ms >= 0.0 ? "+" : "") + size_text(f, per_ms, derived) +
                    " per ms of output delay (" + percent_text(100.0 * share) +
                    " of it): the model's timing error at this drive's frequency lands in the "
                    "size, not in its standard error");
  }
  for (const ShapeTwin& twin : s.twins) {
    if (!std::isfinite(twin.same_force_at)) continue;
    char correlation[32];
    std::snprintf(correlation, sizeof correlation, "%+.4f", twin.correlation);
    std::string derived;
    for (const DerivedParam& q : twin.same_force_derived)
      derived += ", " + q.name + " = " + value_text(q.value, q.unit);
    lines.push_back("one force with " + twin.effect->name() + " on this drive (correlation " +
                    correlation + "): the same force as " + twin.param + " = " +
                    value_text(twin.same_force_at, twin.unit) + derived +
                    "; one recording of this drive cannot tell them apart (a reference "
                    "recording, --reference, sizes the change of the two together)");
  }
  return lines;
}

std::string output_unit(const Diagnosis& d) {
  return d.output_column == "force" ? "N" : d.output_column == "current" ? "A" : "Pa";
}

std::string nuisance_text(const Nuisance& u) {
  std::string text = "delay " + delay_text(u) + ", drives " +
                     std::string(kDriveSamplingNames.name(u.drive_sampling)) + " between samples";
  if (std::isfinite(u.sampling_fit_gain))
    text += " (" + significant(u.sampling_fit_gain, 2) +
            " FIT points better than the other convention)";
  if (u.preyield_flow > 0.0)
    text +=
        ", pre-yield smoothing " + significant(100 * u.preyield_fraction, 2) + " % of peak flow";
  if (std::isfinite(u.slit_fraction))
    text += ", knee " + significant(u.slit_fraction, 2) +
            " of the way from the Bingham line to "
            "the exact slit law";
  return text;
}

namespace {

const CandidateScore* score_of(const Diagnosis& d, const Candidate* c, int step) {
  for (const auto& s : d.candidates)
    if (s.effect == c && s.step == step) return &s;
  return nullptr;
}

}  // namespace

std::string ambiguity_text(const Finding& f, const Diagnosis& d) {
  if (f.ambiguous_with.empty()) return "";
  std::string text = "equally well explained at " + selection_stage(f.step) + " by";
  for (std::size_t i = 0; i < f.ambiguous_with.size(); ++i) {
    const Candidate* a = f.ambiguous_with[i];
    text += (i == 0 ? " " : ", ") + a->name();
    if (const CandidateScore* s = score_of(d, a, f.step); s && !s->screened)
      text +=
          " (FIT " + percent_text(s->fit_percent) + " against " + percent_text(f.fit_percent) + ")";
  }
  // What became of each tied candidate once this finding was in: screened out or not accepted
  // later is no contradiction, it says the two explain the same part of the residual.
  for (const Candidate* a : f.ambiguous_with)
    for (int step = f.step + 1; step < f.step + 8; ++step) {
      const CandidateScore* later = score_of(d, a, step);
      if (!later) continue;
      const bool accepted =
          std::any_of(d.findings.begin(), d.findings.end(),
                      [&](const Finding& g) { return g.effect == a && g.step == step; });
      if (accepted)
        text += "; " + a->name() + " was accepted as well at " + selection_stage(step) + ": with " +
                f.effect->name() + " in, it still explains part of the residual";
      else
        text += "; " + a->name() + " was " +
                (later->screened ? std::string("screened out") : std::string("not accepted")) +
                " at " + selection_stage(step) + ", once " + f.effect->name() +
                " was in: the two explain the same part of the residual, so the data name one of "
                "them, not both";
      break;
    }
  return text;
}

std::string candidate_outcome(const CandidateScore& c, const Diagnosis& d) {
  if (c.screened) return "screened out (no decade of its parameter helps)";
  for (const Finding& f : d.findings) {
    if (f.step != c.step) continue;
    if (f.effect == c.effect) return "accepted";
    if (std::find(f.ambiguous_with.begin(), f.ambiguous_with.end(), c.effect) !=
        f.ambiguous_with.end())
      return "tied with " + f.effect->name() + " (reported as its equal)";
  }
  return "not accepted";
}

}  // namespace rheomag::diagnose
