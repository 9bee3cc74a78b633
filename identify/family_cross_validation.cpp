// Leave-one-recording-out refits of a family, each predicting the recording it left out, started
// from a fit of the other half of the recordings and run side by side, each as soon as its
// half is fitted.

#include "identify/family_cross_validation.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numeric>

#include "core/error.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/multistart_fit.hpp"
#include "identify/task_queue.hpp"

namespace rheomag::identify {

namespace {

/// `training` without its k-th recording.
std::vector<lumped::Recording> without(const std::vector<lumped::Recording>& training,
                                       std::size_t k) {
  std::vector<lumped::Recording> rest;
  for (std::size_t i = 0; i < training.size(); ++i)
    if (i != k) rest.push_back(training[i]);
  return rest;
}

/// Mean of the field drive column of `rec` for `model` (0 for a model without a field input).
double mean_field(const lumped::Recording& rec, const std::string& model) {
  lumped::PhenoKind kind;
  if (!lumped::parse_pheno_kind(model, kind)) return 0.0;
  const std::string column = lumped::greybox_setup_for(rec, kind).field_column;
  if (column.empty()) return 0.0;
  const auto& u = rec.column(column);
  return std::accumulate(u.begin(), u.end(), 0.0) / static_cast<double>(u.size());
}

/// The half (0 or 1) of each training recording: in order of field level (ties in training
/// order), the k-th recording of the l-th level into half (k + l) mod 2, so that each half holds
/// every level it can and, with two tests a level, not the same test condition at every level.
/// Levels closer than 1e-3 of the largest |field| are one.
std::vector<int> halves(const std::vector<lumped::Recording>& training, const std::string& model) {
  std::vector<double> field;
  double largest = 0.0;
  for (const lumped::Recording& r : training) {
    field.push_back(mean_field(r, model));
    largest = std::max(largest, std::abs(field.back()));
  }
  std::vector<std::size_t> order(training.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return field[a] < field[b]; });
  std::vector<int> half(training.size());
  std::size_t level = 0, k = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i > 0 && field[order[i]] - field[order[i - k]] > 1e-3 * largest) {
      ++level;
      k = 0;
    }
    half[order[i]] = static_cast<int>((k + level) % 2);
    ++k;
  }
  return half;
}

/// Progress of several fits run at once: the iterations of each, out of its bound, summed over
/// all of them. The callbacks of for_fit() may be called from different threads.
class FitsProgress {
 public:
  /// Fits with at most bounds[i] iterations each, reported to `report`.
  FitsProgress(const ProgressCallback& report, std::vector<double> bounds)
      : report_(report),
        done_(bounds.size(), 0.0),
        bounds_(std::move(bounds)),
        start_(std::chrono::steady_clock::now()) {}

  /// The progress callback of fit number `fit`, now at most `bound` iterations, its events named
  /// `stage`; empty without a report.
  ProgressCallback for_fit(std::size_t fit, double bound, std::string stage) {
    if (!report_) return {};
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      bounds_[fit] = bound;
    }
    return [this, fit, stage = std::move(stage)](const ProgressEvent& inner) {
      ProgressEvent e = inner;
      e.stage = stage;
      e.total_is_bound = true;
      e.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      const std::lock_guard<std::mutex> lock(mutex_);
      done_[fit] = std::min(inner.done, bounds_[fit]);
      e.done = std::accumulate(done_.begin(), done_.end(), 0.0);
      e.total = std::accumulate(bounds_.begin(), bounds_.end(), 0.0);
      report_(e);
    };
  }

 private:
  const ProgressCallback& report_;
  std::mutex mutex_;
  std::vector<double> done_, bounds_;
  std::chrono::steady_clock::time_point start_;
};

/// The parameter `name` of `fit` if the fit held it of its own accord (held_because), else null.
const FittedParameter* held_by_the_fit(const GreyboxFit& fit, const std::string& name) {
  for (const FittedParameter& p : fit.params)
    if (p.name == name && p.fixed && !p.held_because.empty()) return &p;
  return nullptr;
}

/// What of `test`'s drive lies beyond the drive of `trained` (beyond_range).
std::vector<RangeExcess> beyond_recordings(const std::vector<lumped::Recording>& trained,
                                           const lumped::Recording& test,
                                           const DriveColumns& cols) {
  OperatingRange range;
  for (const lumped::Recording& r : trained) range = span(range, operating_range(r, cols));
  return beyond_range(range, operating_range(test, cols));
}

/// The parameter values of `fit`, in the model's order.
std::vector<double> values_of(const GreyboxFit& fit) {
  std::vector<double> values;
  for (const FittedParameter& p : fit.params) values.push_back(p.value);
  return values;
}

}  // namespace

void check_cross_validation(const std::vector<lumped::Recording>& training,
                            const std::string& model) {
  const std::size_t n = training.size();
  if (n < 3)
    throw InputError("fit-family --cross-validate: needs at least 3 training recordings (got " +
                     std::to_string(n) + "): each refit leaves one out and keeps a family");
  for (std::size_t k = 0; k < n; ++k) {
    try {
      check_family(without(training, k), {training[k]}, model);
    } catch (const InputError& e) {
      throw InputError("fit-family --cross-validate: without " + training[k].csv_path +
                       " the family no longer fits: " + e.what());
    }
  }
}

std::vector<std::vector<lumped::Recording>> cross_validation_halves(
    const std::vector<lumped::Recording>& training, const std::string& model) {
  const std::vector<int> half = halves(training, model);
  std::vector<std::vector<lumped::Recording>> out(2);
  for (std::size_t i = 0; i < training.size(); ++i)
    out[static_cast<std::size_t>(half[i])].push_back(training[i]);
  return out;
}

std::vector<FamilyMember> cross_validate_family(const std::vector<lumped::Recording>& training,
                                                const std::string& model,
                                                const FamilyFitOptions& options) {
  check_cross_validation(training, model);
  const std::size_t n = training.size();
  const unsigned threads = fit_threads(options.greybox.threads);
  // Every fit here runs on one thread (its starts one after the other), the fits side by side:
  // the results do not depend on the thread count.
  GreyboxOptions single = options.greybox;
  single.threads = 1;
  const bool warm = options.refit_iterations > 0;
  GreyboxOptions refit = single;
  if (warm) {
    refit.starts = 1;
    refit.max_iterations = options.refit_iterations;
    refit.min_inertance_gain = 0.0;  // it keeps the inertance decision of the half it starts from
  }
  const double fit_bound = greybox_iteration_bound(model, single);
  const double refit_bound = greybox_iteration_bound(model, refit);
  // Refits 0..n-1, then the two halves (warm refits only).
  std::vector<double> bounds(n, warm ? refit_bound : fit_bound);
  if (warm) bounds.insert(bounds.end(), 2, fit_bound);
  FitsProgress progress(options.greybox.progress, bounds);

  // The two halves, each fitted on its own from the nominal start with the main fit's options (a
  // half that is no family for the model, e.g. one field level, is not fitted and its tests are
  // refitted from nominal).
  const std::vector<int> half = halves(training, model);
  const std::vector<std::vector<lumped::Recording>> parts =
      cross_validation_halves(training, model);
  std::array<std::optional<GreyboxFit>, 2> half_fit;
  const auto fit_half = [&](std::size_t h) {
    try {
      check_family(parts[h], {}, model);
    } catch (const InputError&) {
      progress.for_fit(n + h, 0.0, "");  // not fitted: nothing to count
      return;
    }
    GreyboxOptions g = single;
    g.progress = progress.for_fit(n + h, fit_bound,
                                  "cross-validation, fitting half " + std::to_string(h + 1) +
                                      " of 2 (" + std::to_string(parts[h].size()) + " recordings)");
    half_fit[h] = fit_family(parts[h], model, g, options);
  };

  // Each test refitted on all the others, started from the fit of the half it is not in.
  std::vector<FamilyMember> held_out(n);
  const auto refit_without = [&](std::size_t k) {
    GreyboxOptions g = refit;
    const std::optional<GreyboxFit>& other = half_fit[static_cast<std::size_t>(1 - half[k])];
    if (other) {
      g.start = values_of(*other);
      if (const auto* inertance = held_by_the_fit(*other, "inertance"))
        g.held.emplace_back(inertance->name, inertance->value);
      g.motion_lead = other->setup.motion_lead;  // chosen without this test
    } else {
      g = single;  // no fit of the other half: the cold refit
    }
    g.progress =
        progress.for_fit(k, other ? refit_bound : fit_bound,
                         "cross-validation, refit " + std::to_string(k + 1) + " of " +
                             std::to_string(n) + " (without " + training[k].csv_path + ")");
    const std::vector<lumped::Recording> rest = without(training, k);
    const GreyboxFit fit = other ? fit_greybox_family(rest, model, g, options.decimation)
                                 : fit_family(rest, model, g, options);
    held_out[k] = predict_family_member(training[k], fit);
    held_out[k].beyond = beyond_recordings(rest, training[k], drive_columns(fit));
  };

  // The tasks: the two halves first (warm refits only), then the refits, each as soon as the half
  // it starts from is fitted, so a core that finishes one half goes on with the refits of the
  // other half's tests instead of waiting for the second half; the longest refits (those without
  // the shortest recordings) first, so that the last to end is short and no core waits long.
  std::vector<std::size_t> refit_order(n);
  std::iota(refit_order.begin(), refit_order.end(), std::size_t{0});
  std::stable_sort(refit_order.begin(), refit_order.end(), [&](std::size_t a, std::size_t b) {
    return training[a].t.size() < training[b].t.size();
  });
  const std::size_t first_refit = warm ? 2 : 0;
  std::vector<std::vector<std::size_t>> prerequisites(first_refit + n);
  if (warm)
    for (std::size_t i = 0; i < n; ++i)
      prerequisites[first_refit + i] = {static_cast<std::size_t>(1 - half[refit_order[i]])};
  run_when_ready(prerequisites, threads, [&](std::size_t task) {
    if (task < first_refit)
      fit_half(task);
    else
      refit_without(refit_order[task - first_refit]);
  });
  return held_out;
}

}  // namespace rheomag::identify
