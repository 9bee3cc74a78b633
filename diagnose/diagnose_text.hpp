#pragma once
// Small text helpers of the diagnosis's messages and evidence sentences.

#include <string>
#include <vector>

#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_locate.hpp"

namespace rheomag::diagnose {

/// `v` as a stream prints it by default (6 significant digits).
std::string num(double v);

/// `v` with `digits` significant digits.
std::string fmt(double v, int digits = 3);

/// Share of the residual energy in the mismatch windows of `regime` ("flow reversal", ...).
double regime_share(const std::vector<MismatchWindow>& windows, const std::string& regime);

/// Value of the first parameter called `name` in `fit`'s layout (0 when there is none).
double fit_value(const ModelFit& fit, const std::string& name);

}  // namespace rheomag::diagnose
