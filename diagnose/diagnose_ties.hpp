#pragma once
// Ties decided again in the joint model: a finding accepted while another candidate explained
// the data almost as well is compared with that candidate once every other finding is in.

#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// For each finding of `d` that tied at its selection step with another candidate
/// (Finding::ambiguous_with) whose fit there differed from its own (not the same model under two
/// names), and that was accepted before another finding (a tie judged without it), re-fits the
/// joint model `fit` with the finding swapped for that candidate (`settings`; the candidate starts
/// from its parameters at that step, everything else from `fit`). Where the swap lowers BIC by more
/// than `bic_margin` and the candidate finds nothing implausible in its re-fitted parameters, it is
/// named instead: the finding keeps its step, the two exchange places in ambiguous_with, `fit`
/// becomes the swapped fit, and a note says why.
void revisit_ties(const DiagnosisModel& model, ModelFit& fit, const FitSettings& settings,
                  double bic_margin, Diagnosis& d);

}  // namespace rheomag::diagnose
