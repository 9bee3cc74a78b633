// Small text helpers of the diagnosis's messages and evidence sentences.

#include "diagnose/diagnose_text.hpp"

#include <sstream>

namespace rheomag::diagnose {

std::string num(double v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

std::string fmt(double v, int digits) {
  std::ostringstream o;
  o.precision(digits);
  o << v;
  return o.str();
}

double regime_share(const std::vector<MismatchWindow>& windows, const std::string& regime) {
  double s = 0.0;
  for (const auto& w : windows)
    if (w.regime == regime) s += w.share;
  return s;
}

double fit_value(const ModelFit& fit, const std::string& name) {
  for (std::size_t j = 0; j < fit.layout.size(); ++j)
    if (fit.layout[j].name == name) return fit.values[j];
  return 0.0;
}

}  // namespace rheomag::diagnose
