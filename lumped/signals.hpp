#pragma once
// Generated drive signals for `rheomag simulate --signal`: sine, constant, steps, square.

#include <string>
#include <vector>

#include "lumped/recording.hpp"

namespace rheomag::lumped {

/// Adds the signal described by `text` to `rec` (whose t is set). Forms:
///   displacement=sine:amplitude=A,frequency=F[,offset=X0]  (also writes velocity)
///   velocity=sine:amplitude=V,frequency=F | velocity=constant:value=V
///   COLUMN=constant:value=C
///   COLUMN=steps:levels=a/b/c...,period=P   (each level held P seconds, repeating)
///   COLUMN=square:low=L,high=H,period=P     (50 % duty)
/// Throws InputError naming the option for anything malformed.
void add_signal(Recording& rec, const std::string& text);

/// Uniform time base [0, duration) at `rate` samples per second.
std::vector<double> uniform_times(double duration, double rate);

}  // namespace rheomag::lumped
