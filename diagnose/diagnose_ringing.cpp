// Ringing frequencies from power spectra (Eigen's FFT) and the inertance starts they give.

#include "diagnose/diagnose_ringing.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <unsupported/Eigen/FFT>

namespace rheomag::diagnose {

namespace {

/// One-sided power spectrum of `x` (mean removed, Hann window, zero-padded to `n`), bins 0..n/2.
std::vector<double> power_spectrum(const std::vector<double>& x, std::size_t n) {
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  std::vector<double> w(n, 0.0);
  const auto m = static_cast<double>(x.size());
  for (std::size_t k = 0; k < x.size(); ++k)
    w[k] = (x[k] - mean) * (0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (k + 0.5) / m));
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, w);
  std::vector<double> p(n / 2 + 1);
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = std::norm(spectrum[k]);
  return p;
}

}  // namespace

std::vector<double> ringing_frequencies(const std::vector<double>& residual,
                                        const std::vector<double>& drive, double dt,
                                        std::size_t count) {
  if (residual.size() < 16 || drive.size() != residual.size() || !(dt > 0.0)) return {};
  std::size_t n = 1;
  while (n < residual.size()) n *= 2;
  const double df = 1.0 / (static_cast<double>(n) * dt);
  // The drive band: 99 % of the drive's energy (without the mean) lies below it.
  const auto pd = power_spectrum(drive, n);
  const double total = std::accumulate(pd.begin() + 1, pd.end(), 0.0);
  if (!(total > 0.0)) return {};
  std::size_t band = 1;
  for (double below = 0.0; band < pd.size(); ++band)
    if ((below += pd[band]) >= 0.99 * total) break;
  const std::size_t first = std::max<std::size_t>(2 * band, 3);
  const std::size_t last = std::min(pd.size() - 3, static_cast<std::size_t>(0.4 / (dt * df)));
  if (first >= last) return {};
  // The residual's power averaged over +-10 % in frequency (a cumulative sum).
  const auto pr = power_spectrum(residual, n);
  std::vector<double> cum(pr.size() + 1, 0.0);
  std::partial_sum(pr.begin(), pr.end(), cum.begin() + 1);
  std::vector<double> smooth(pr.size(), 0.0);
  for (std::size_t k = 1; k < pr.size(); ++k) {
    const auto lo = static_cast<std::size_t>(std::floor(k / 1.1));
    const auto hi = std::min(pr.size() - 1, static_cast<std::size_t>(std::ceil(k * 1.1)));
    smooth[k] = (cum[hi + 1] - cum[lo]) / static_cast<double>(hi + 1 - lo);
  }
  // Local maxima of the averaged power, strongest first; each located at the power-weighted mean
  // frequency of the +-10 % about it (re-centred a few times): a periodically restarted ring is
  // a comb of drive harmonics whose envelope, not its strongest line, peaks at the resonance.
  std::vector<std::size_t> peaks;
  for (std::size_t k = first; k <= last; ++k)
    if (smooth[k] > smooth[k - 1] && smooth[k] >= smooth[k + 1]) peaks.push_back(k);
  std::sort(peaks.begin(), peaks.end(),
            [&](std::size_t a, std::size_t b) { return smooth[a] > smooth[b]; });
  std::vector<double> out;
  for (std::size_t k : peaks) {
    double bin = static_cast<double>(k);
    for (int pass = 0; pass < 4; ++pass) {
      const auto lo = std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(bin / 1.1)));
      const auto hi = std::min(pr.size() - 1, static_cast<std::size_t>(std::ceil(bin * 1.1)));
      double power = 0.0, moment = 0.0;
      for (std::size_t j = lo; j <= hi; ++j)
        power += pr[j], moment += pr[j] * static_cast<double>(j);
      if (!(power > 0.0)) break;
      bin = moment / power;
    }
    const double f = bin * df;
    const bool distinct = std::none_of(
        out.begin(), out.end(), [f](double g) { return std::max(f, g) < 1.25 * std::min(f, g); });
    if (distinct) out.push_back(f);
    if (out.size() == count) break;
  }
  return out;
}

double loop_compliance(const lumped::RigSpec& spec) {
  if (!spec.compressibility) return 0.0;
  // dp1/dt = (Q_in - Q) / C and dp2/dt = (Q - Q_in) / C: the pressure across the valve loop
  // sees the two chambers in series.
  return 0.5 * spec.compressibility->capacitance(spec.compressibility->precharge);
}

std::vector<double> ringing_inertances(const DiagnosisModel& model, const ModelFit& current,
                                       const ParamDef& bounds) {
  if (model.fitted_baseline() || model.baseline().kind == lumped::RigKind::coil_bench) return {};
  const double c = loop_compliance(model.spec(current.effects, current.values));
  if (!(c > 0.0)) return {};
  const auto& y = model.measured();
  std::vector<double> residual(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) residual[k] = y[k] - current.prediction[k];
  std::vector<double> out;
  for (double f : ringing_frequencies(residual, model.recording().column("velocity"),
                                      model.sample_interval())) {
    const double omega = 2.0 * std::numbers::pi * f;
    const double inertance = 1.0 / (omega * omega * c);
    if (inertance >= bounds.lower && inertance <= bounds.upper) out.push_back(inertance);
  }
  return out;
}

}  // namespace rheomag::diagnose
