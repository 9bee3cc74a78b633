// Fit metrics: FIT%, RMSE% (paper 000 eq. 6), RE (paper 001 eq. 10).

#include "lumped/metrics.hpp"

#include <charconv>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace rheomag::lumped {

namespace {

void check_sizes(std::span<const double> y, std::span<const double> yhat) {
  if (y.size() != yhat.size())
    throw InputError("metrics: measured and model signals differ in length (" +
                     std::to_string(y.size()) + " vs " + std::to_string(yhat.size()) + ")");
  if (y.size() < 2) throw InputError("metrics: need at least 2 samples");
}

/// ||y - yhat||_2 / ||y - mean(y)||_2
double normalised_error(std::span<const double> y, std::span<const double> yhat) {
  check_sizes(y, yhat);
  const double mean = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(y.size());
  double err = 0.0, spread = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    err += (y[i] - yhat[i]) * (y[i] - yhat[i]);
    spread += (y[i] - mean) * (y[i] - mean);
  }
  if (!(spread > 0.0))
    throw InputError("metrics: the measured signal is constant, FIT% and RMSE% are undefined");
  return std::sqrt(err / spread);
}

std::size_t parse_index(const std::string& s, const std::string& option) {
  std::size_t v = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size())
    throw InputError(option + ": '" + s + "' is not a sample index");
  return v;
}

}  // namespace

SampleRange parse_sample_range(const std::string& text, std::size_t n, const std::string& option) {
  auto colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError(option + ": expected a:b (sample indices), got '" + text + "'");
  std::string a = text.substr(0, colon), b = text.substr(colon + 1);
  SampleRange r{a.empty() ? 0 : parse_index(a, option), b.empty() ? n : parse_index(b, option)};
  if (r.end > n)
    throw InputError(option + ": end " + std::to_string(r.end) + " is past the last sample (" +
                     std::to_string(n) + " samples)");
  if (r.begin + 2 > r.end)
    throw InputError(option + ": range '" + text + "' holds fewer than 2 samples");
  return r;
}

double fit_percent(std::span<const double> y, std::span<const double> yhat) {
  return 100.0 * (1.0 - normalised_error(y, yhat));
}

double rmse_percent(std::span<const double> y, std::span<const double> yhat) {
  return 100.0 * normalised_error(y, yhat);
}

double relative_error(std::span<const double> y, std::span<const double> yhat) {
  check_sizes(y, yhat);
  double err = 0.0, ref = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    err += std::abs(y[i] - yhat[i]);
    ref += std::abs(y[i]);
  }
  if (!(ref > 0.0)) throw InputError("metrics: the measured signal is all zero, RE is undefined");
  return err / ref;
}

Metrics compute_metrics(std::span<const double> y, std::span<const double> yhat) {
  const double ne = normalised_error(y, yhat);
  return Metrics{100.0 * (1.0 - ne), 100.0 * ne, relative_error(y, yhat)};
}

Metrics compute_metrics(std::span<const double> y, std::span<const double> yhat,
                        SampleRange range) {
  if (range.end > y.size() || range.end > yhat.size() || range.begin >= range.end)
    throw InputError("metrics: sample range " + std::to_string(range.begin) + ":" +
                     std::to_string(range.end) + " is outside the " + std::to_string(y.size()) +
                     " samples");
  return compute_metrics(y.subspan(range.begin, range.size()),
                         yhat.subspan(range.begin, range.size()));
}

}  // namespace rheomag::lumped
