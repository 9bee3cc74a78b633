// The text of a finding: its evidence sentence and what would tell it from a tied candidate.

#include "diagnose/diagnose_findings.hpp"

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

}  // namespace rheomag::diagnose
