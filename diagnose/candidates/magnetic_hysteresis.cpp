// The magnetic_hysteresis candidate: a Duhem loop between the coil current and the field, so
// that the output at one current depends on where the current came from.

#include "diagnose/candidates/magnetic_hysteresis.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose {

lumped::DuhemBlock duhem_field(double a, double d) {
  lumped::DuhemBlock h;
  h.a = a;
  h.d = d;
  h.b2 = kDuhemFieldB2;
  h.b1 = 1.0 / kDuhemFieldB2;  // f(i) = b1 tanh(b2 i) = i within 0.01 % up to 1 A
  h.flux_per_ampere = 1.0;     // lambda is the field-equivalent current
  return h;
}

namespace candidates {

namespace {

/// A Duhem loop must be wider than this many noise standard deviations of the current.
constexpr double kLoopNoiseRatio = 10.0;

/// Largest reversible fraction d of the candidate's range (params()).
constexpr double kMaxReversible = 0.98;

/// Smallest share of the loop's offset that depends on the direction of approach
/// (direction_dependent_share) for a loop to be told from a reshaped yield-current map.
constexpr double kMinDirectionShare = 0.15;

/// A fitted d this close to kMaxReversible is pinned there: the fit asks for less loop than any.
constexpr double kPinnedReversible = 0.01;

/// The field-equivalent current of the candidate (duhem_field(a, d)) along the current path `i`:
/// along a distance x travelled in direction s, dh/dx = a (f - h) + s d with f(i) = i
/// (kDuhemFieldB2 small), integrated exactly on each sample interval.
std::vector<double> duhem_path(const std::vector<double>& i, double a, double d) {
  const lumped::DuhemBlock block = duhem_field(a, d);
  std::vector<double> h(i.size());
  if (i.empty()) return h;
  h[0] = block.b1 * std::tanh(block.b2 * i[0]);
  for (std::size_t k = 0; k + 1 < i.size(); ++k) {
    const double di = i[k + 1] - i[k];
    if (di == 0.0) {
      h[k + 1] = h[k];
      continue;
    }
    const double s = di > 0.0 ? 1.0 : -1.0, x = std::abs(di);
    // Particular solution h_p(x) = f(x) - s (1 - d) / a, f(x) = i_k + s x.
    const double start = i[k] - s * (1.0 - d) / a;
    h[k + 1] = i[k + 1] - s * (1.0 - d) / a + (h[k] - start) * std::exp(-a * x);
  }
  return h;
}

/// Share (rms) of the loop's offset h - i along the current `i` that no function of the
/// current alone takes: the offset minus its mean over the samples whose current lies within
/// `width` of each sample's, relative to the offset itself. Near 1 where each current is reached
/// from both directions (the offset changes sign with the approach); near 0 where each current
/// level is reached from one direction only, so a reshaped yield map gives the same output.
double direction_dependent_share(const std::vector<double>& i, const std::vector<double>& h,
                                 double width) {
  const std::size_t n = std::min(i.size(), h.size());
  if (n == 0) return 0.0;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return i[p] < i[q]; });
  // Prefix sums of the offset in the order of the current, for the window means.
  std::vector<double> sum(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) sum[k + 1] = sum[k] + (h[order[k]] - i[order[k]]);
  double unexplained = 0.0, total = 0.0;
  std::size_t lo = 0, hi = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double c = i[order[k]];
    while (i[order[lo]] < c - width) ++lo;
    while (hi < n && i[order[hi]] <= c + width) ++hi;
    const double offset = h[order[k]] - c;
    const double mean = (sum[hi] - sum[lo]) / static_cast<double>(hi - lo);
    unexplained += (offset - mean) * (offset - mean);
    total += offset * offset;
  }
  return total > 0.0 ? std::sqrt(unexplained / total) : 0.0;
}

class MagneticHysteresis final : public Candidate {
 public:
  std::string name() const override { return "magnetic_hysteresis"; }

  bool applies(const DiagnosisModel& model) const override {
    if (model.constant_field()) return false;
    // On a fitted model: a loop on its current input.
    if (model.fitted_baseline())
      return model.field_column() == "current" || model.field_column() == "current_cmd";
    // Duhem between an imposed (or ideally tracked) current and the field; a voltage-driven coil
    // would need the hysteresis inside the inductor instead (not a candidate).
    return model.baseline().kind != lumped::RigKind::coil_bench &&
           model.baseline().driver_mode == lumped::DriverMode::current_source;
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    // Duhem in field-equivalent amperes: a [1/A] (a large a closes the loop), d [-] the
    // reversible fraction of the slope; the loop's half width is (1 - d) / a.
    const auto& i = model.recording().column("current");
    const auto [lo, hi] = std::minmax_element(i.begin(), i.end());
    const double range = std::max(*hi - *lo, 1e-6);
    return {{"a", 10.0 / range, 0.3 / range, 3e3 / range, true, 1.0, "1/A"},
            {"d", 0.5, 0.0, kMaxReversible, false, 1.0, "1"}};
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    const double a = values.next();
    const double d = values.next();
    spec.magnetic_hysteresis = duhem_field(a, d);
  }

  bool composes_with_fitted_model() const override { return true; }

  bool follows_current_path() const override { return true; }

  void compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                          const DiagnosisModel& model) const override {
    const double a = values.next();
    const double d = values.next();
    auto& r = blocks.inputs;
    const auto& path = model.current_path();
    r.columns[blocks.field_column] =
        duhem_path(path.empty() ? r.column(blocks.field_column) : path, a, d);
  }

  std::string evidence(const Diagnosis& d, const ModelFit& fit) const override {
    std::ostringstream o;
    double memory = 0.0;
    for (const auto& l : d.baseline_stats.loops)
      if (l.input == "current" || l.input == "current_cmd") memory = l.memory_opening;
    const double a = fit_value(fit, "a"), dd = fit_value(fit, "d");
    o << "the output at one current depends on where the current came from: the residual "
         "signed by the direction of the last current change averages "
      << fmt(memory, 2)
      << " of its rms, a loop in (current, residual) that stays open while the current "
         "rests (rate-independent, unlike a lag, which settles); a Duhem field with a = "
      << fmt(a) << " 1/A, d = " << fmt(dd, 2)
      << " (loop half width (1 - d)/a = " << fmt(a > 0 ? (1.0 - dd) / a : 0.0) << " A) explains it";
    return o.str();
  }

  std::string separating_measurement(const Candidate& /*other*/) const override {
    return "hold each current level longer and approach it from above and from below: a lag "
           "settles within a few time constants, magnetic hysteresis leaves a lasting offset "
           "that depends on the approach (also at DC); a search coil on the core shows the "
           "flux loop directly";
  }

  std::string implausible(const DiagnosisModel& model, const ModelFit& fit) const override {
    const std::size_t j = fit.layout.size() - 2;
    // A reversible fraction at the top of its range: the fit wants an even thinner loop than the
    // candidate allows, and what it uses is the slow approach over 1/a amperes (a small
    // reshaping of the yield-current map), not a loop.
    const double d = fit.values[j + 1];
    if (d >= kMaxReversible - kPinnedReversible)
      return " with a reversible fraction d = " + fmt(d, 3) + " at the top of its range (" +
             fmt(kMaxReversible, 2) +
             "): the fit asks for less loop than any, and reshapes the "
             "yield's approach to each current instead; not accepted";
    // A loop whose offset is a function of the current alone (each current level reached from
    // one direction only, the steps between them too quick to show the loop) is what a reshaped
    // yield map between the stated currents gives; the recording cannot tell the two apart.
    const double a = fit.values[j], width = (1.0 - d) / a;
    const auto& path = model.current_path();
    const std::string column = model.fitted_baseline() ? model.field_column() : "current";
    const auto& current = path.empty() ? model.recording().column(column) : path;
    const double share = direction_dependent_share(current, duhem_path(current, a, d), width);
    if (share < kMinDirectionShare)
      return " whose offset from the current (h - i) depends on the direction of approach for "
             "only " +
             fmt(100.0 * share, 2) + " % of its rms (under " + fmt(100.0 * kMinDirectionShare, 2) +
             " %): within the loop's half width (" + fmt(width) +
             " A) each current is reached from one direction only, or too briefly from the "
             "other, so a yield map reshaped at those currents gives the same output; not "
             "accepted";
    // A loop narrower than ten noise standard deviations of the current is what a Duhem block
    // does to a noisy current (it follows the noise and low-passes it), not a loop.
    if (!model.drive_noise().count("current")) return "";
    const double noise = model.drive_noise().at("current");
    if (!(width < kLoopNoiseRatio * noise)) return "";
    return " with a loop half width (1 - d)/a of " + fmt(width) + " A, less than " +
           fmt(kLoopNoiseRatio, 2) + " times the current's noise (" + fmt(noise) +
           " A): not told apart from the noise; not accepted";
  }
};

}  // namespace

/// The magnetic_hysteresis candidate (registered in candidate_registry.cpp).
const Candidate& magnetic_hysteresis() {
  static const MagneticHysteresis candidate;
  return candidate;
}

}  // namespace candidates

}  // namespace rheomag::diagnose
