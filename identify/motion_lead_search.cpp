// The motion lead of a family or of one recording: the fit at the given lead, warm refits at
// the others, the lowest training misfit at full rate kept.

#include "identify/motion_lead_search.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "lumped/metrics.hpp"

namespace rheomag::identify {

namespace {

/// Sum over the training recordings of (1 - FIT)^2, each simulated at its full rate as the
/// family's report simulates it: the FITs the user is shown decide, not the fit's own cost on the
/// decimated samples with its coarser integrator (on utfsm the two rank the leads alike).
double full_rate_misfit(const std::vector<lumped::Recording>& recs, const GreyboxFit& fit) {
  double score = 0.0;
  for (const lumped::Recording& rec : recs) {
    const lumped::Metrics m =
        lumped::compute_metrics(rec.column(fit.setup.output_column), simulate_greybox(rec, fit));
    const double miss = 1.0 - m.fit_percent / 100.0;
    score += miss * miss;
  }
  return score;
}

}  // namespace

std::vector<double> default_motion_leads() {
  std::vector<double> leads;
  for (int k = -2; k <= 6; ++k) leads.push_back(2.5e-3 * k);
  return leads;
}

GreyboxOptions warm_refit_options(const GreyboxOptions& options, const GreyboxFit& fit,
                                  int iterations) {
  GreyboxOptions refit = options;
  refit.start.clear();
  for (const auto& p : fit.params) refit.start.push_back(p.value);
  refit.starts = 1;
  refit.max_iterations = iterations;
  refit.min_inertance_gain = 0.0;  // the inertance check is not made again
  for (const auto& p : fit.params)
    if (p.fixed && !p.held_because.empty()) refit.held.emplace_back(p.name, p.value);
  return refit;
}

void keep_fit_decisions(const GreyboxFit& before, GreyboxFit& refit) {
  for (std::size_t k = 0; k < refit.params.size() && k < before.params.size(); ++k)
    refit.params[k].held_because = before.params[k].held_because;
  refit.inertance_gain = before.inertance_gain;
}

GreyboxFit search_motion_lead(const GreyboxOptions& options, const std::vector<double>& leads,
                              int iterations, const FitWithOptions& fit_at,
                              const std::function<double(const GreyboxFit&)>& misfit) {
  GreyboxFit best = fit_at(options);
  const GreyboxFit first = best;
  double best_misfit = misfit(best);
  std::size_t tried = 0;
  for (const double lead : leads) {
    ++tried;  // the given lead too: every candidate gets the same warm refit
    GreyboxOptions refit = warm_refit_options(options, first, iterations);
    refit.motion_lead = lead;
    if (options.progress) {
      char stage[96];
      std::snprintf(stage, sizeof stage, "motion lead %.1f ms (%zu of %zu)", 1e3 * lead, tried,
                    leads.size());
      refit.progress = [&options, text = std::string(stage)](const ProgressEvent& e) {
        ProgressEvent named = e;
        named.stage = text;
        options.progress(named);
      };
    }
    GreyboxFit fit;
    try {
      fit = fit_at(refit);
    } catch (const ConvergenceError&) {
      continue;  // no finite simulation from the first fit's values at this lead: not a candidate
    }
    const double m = misfit(fit);
    if (!(m < best_misfit)) continue;
    keep_fit_decisions(first, fit);
    best = std::move(fit);
    best_misfit = m;
  }
  return best;
}

GreyboxFit fit_family_searching_motion_lead(const std::vector<lumped::Recording>& recs,
                                            const std::string& model, const GreyboxOptions& options,
                                            int decimation, const std::vector<double>& leads,
                                            int iterations) {
  return search_motion_lead(
      options, leads, iterations,
      [&](const GreyboxOptions& o) { return fit_greybox_family(recs, model, o, decimation); },
      [&](const GreyboxFit& fit) { return full_rate_misfit(recs, fit); });
}

GreyboxFit fit_searching_motion_lead(const lumped::Recording& rec, const std::string& model,
                                     const GreyboxOptions& options,
                                     const std::vector<double>& leads, int iterations) {
  return search_motion_lead(
      options, leads, iterations,
      [&](const GreyboxOptions& o) { return fit_greybox(rec, model, o); },
      [](const GreyboxFit& fit) {
        const double miss = 1.0 - fit.train.fit_percent / 100.0;
        return miss * miss;
      });
}

}  // namespace rheomag::identify
