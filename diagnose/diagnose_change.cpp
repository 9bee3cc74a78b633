// The change between a reference recording's diagnosis and today's, effect by effect.

#include "diagnose/diagnose_change.hpp"

#include <optional>

#include "diagnose/diagnose_findings.hpp"

namespace rheomag::diagnose {

namespace {

/// An effect's size on one recording and what derives from it.
struct Size {
  double value = 0.0;
  bool named = false;
  std::vector<DerivedParam> derived;
};

/// `effect`'s size in `d`: its finding's first parameter where named, else its size with the
/// sign free beside the findings, else its first-step one; none when it has none of these.
std::optional<Size> size_of(const Diagnosis& d, const Candidate* effect) {
  for (const Finding& f : d.findings)
    if (f.effect == effect && !f.params.empty()) return Size{f.params.front(), true, f.derived};
  for (const CandidateScore& c : d.signed_beside_findings)
    if (c.effect == effect) return Size{c.signed_params.front(), false, c.signed_derived};
  for (const CandidateScore& c : d.candidates)
    if (c.effect == effect && c.step == 0 && !c.signed_params.empty())
      return Size{c.signed_params.front(), false, c.signed_derived};
  return std::nullopt;
}

/// The first-step scores of `d` that have a signed size (its linear candidates, in order).
std::vector<const CandidateScore*> linear_scores(const Diagnosis& d) {
  std::vector<const CandidateScore*> scores;
  for (const CandidateScore& c : d.candidates)
    if (c.step == 0 && !c.signed_params.empty()) scores.push_back(&c);
  return scores;
}

}  // namespace

ReferenceComparison compare_with_reference(const Diagnosis& today, const Diagnosis& reference) {
  ReferenceComparison out;
  out.recording = reference.recording;
  out.baseline_fit_percent = reference.baseline_fit_percent;
  for (const Finding& f : reference.findings) out.findings.push_back(f.effect->name());
  for (const CandidateScore* c : linear_scores(today)) {
    const auto now = size_of(today, c->effect);
    const auto before = size_of(reference, c->effect);
    if (!now || !before) {
      out.sized_on_one.push_back(c->effect->name());
      continue;
    }
    EffectChange e;
    e.effect = c->effect;
    e.param = c->param_names.front();
    e.unit = c->param_units.front();
    e.today = now->value;
    e.named_today = now->named;
    e.reference = before->value;
    e.named_reference = before->named;
    e.change = now->value - before->value;
    for (const DerivedParam& q : now->derived)
      for (const DerivedParam& r : before->derived)
        if (q.name == r.name) e.derived_change.push_back({q.name, q.value - r.value, q.unit});
    out.changes.push_back(std::move(e));
  }
  for (const CandidateScore* c : linear_scores(reference))
    if (!size_of(today, c->effect)) out.sized_on_one.push_back(c->effect->name());
  return out;
}

std::string change_text(const EffectChange& e) {
  std::string text = e.effect->name() + ": " + e.param + " " + value_text(e.today, e.unit) +
                     " today (" + (e.named_today ? "named" : "signed") + "), " +
                     value_text(e.reference, e.unit) + " in the reference (" +
                     (e.named_reference ? "named" : "signed") + ") -> change " +
                     (e.change >= 0.0 ? "+" : "") + value_text(e.change, e.unit);
  for (std::size_t j = 0; j < e.derived_change.size(); ++j) {
    const DerivedParam& q = e.derived_change[j];
    text += (j == 0 ? " (" : ", ") + q.name + " " + (q.value >= 0.0 ? "+" : "") +
            value_text(q.value, q.unit) + (j + 1 == e.derived_change.size() ? ")" : "");
  }
  return text;
}

std::string reference_heading(const ReferenceComparison& r) {
  std::string named;
  for (const std::string& name : r.findings) named += (named.empty() ? "" : ", ") + name;
  return "change against the reference " + r.recording + " (same baseline: FIT " +
         percent_text(r.baseline_fit_percent) +
         " there, named there: " + (named.empty() ? "none" : named) +
         "; each size is the named one, or the one fitted with its sign free beside what was "
         "named)";
}

}  // namespace rheomag::diagnose
