#pragma once
// The text of a finding: its evidence sentence and what would tell it from a tied candidate;
// the phrases the text summary and the HTML report share (stage labels, units, precision, the
// delay's sign convention), so that both say the same thing.

#include <cstddef>
#include <string>
#include <vector>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// The evidence of finding `f` in `d` (Candidate::evidence), its values as in `fit`, with the
/// residual's strongest correlation and the candidates the measured coil current ruled out.
std::string finding_evidence(const Finding& f, const Diagnosis& d, const ModelFit& fit);

/// What would tell `a` from `b` when both explain the data almost equally: what either says
/// about the other (Candidate::separating_measurement), else a generic advice.
std::string separating_measurement(const Candidate& a, const Candidate& b);

/// The stage a reported value comes from: the baseline's calibration (before any candidate), a
/// forward-selection step (candidates fitted one at a time on top; screening is its first test)
/// or the final joint fit of every accepted effect with the nuisances free again.
inline constexpr const char* kCalibrationStage = "baseline calibration";
inline constexpr const char* kFinalStage = "final fit";
/// What a signed size is measured against, in the report's words.
inline constexpr const char* kSignedSizeStage =
    "first step, sign free: less than the baseline has is negative; another recording's finding "
    "minus it is the change between the two";

/// "selection step 2" (`step` counted from 0).
std::string selection_stage(int step);

/// A FIT or share in percent with one decimal: "57.8 %".
std::string percent_text(double percent);

/// A value with 3 significant digits and its SI unit ("9.80 N", "5.18e-06 m^3"; none for "1").
std::string value_text(double value, const std::string& unit);

/// The output delay with one sign convention (positive: the output behind the drives):
/// "+10 ms (+2.00 samples, output behind the drives)", "-8.64 ms (-1.73 samples, output ahead of
/// the drives)", or "... output and drives aligned" within a quarter sample.
std::string delay_text(const Nuisance& u);

/// What one recording cannot tell finding `f`'s size from (Finding::sensitivity), one sentence
/// each: "+24.1 kg per ms of output delay (38 % of it): ..."; "one force with gas_spring on this
/// drive (correlation -1.000): ..."; none for an effect not linear in its size.
std::vector<std::string> sensitivity_lines(const Finding& f);

/// "coulomb_force = 9.80 N +- 0.30 N" (standard error with 2 digits, or "(standard error
/// unbounded)") for parameter `j` of finding `f`; `plus_minus` spells the sign ("+-" or HTML's).
std::string parameter_text(const Finding& f, std::size_t j, const std::string& plus_minus = "+-");

/// The SI unit of the explained output ("N", "A" or "Pa").
std::string output_unit(const Diagnosis& d);

/// The calibrated nuisances of one stage in one line: "delay ..., drives linear between samples
/// (...), pre-yield smoothing 3.0 % of peak flow".
std::string nuisance_text(const Nuisance& u);

/// The candidates that tied with `f` where it was accepted, with their FIT there, and what
/// became of each at later steps: "equally well explained at selection step 1 by pre_yield (FIT
/// 80.9 % against 81.0 %); pre_yield was screened out at selection step 2, once compressibility
/// was in: ..." ("" when none tied).
std::string ambiguity_text(const Finding& f, const Diagnosis& d);

/// What became of a candidate scored at one step: "accepted", "tied with X (reported as its
/// equal)", "screened out (no decade of its parameter helps)" or "not accepted".
std::string candidate_outcome(const CandidateScore& c, const Diagnosis& d);

}  // namespace rheomag::diagnose
