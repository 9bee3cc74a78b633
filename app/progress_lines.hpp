#pragma once
// Progress of a long command on stderr: a library's ProgressCallback printed as plain lines, at
// most one every few seconds (plus every finished step), safe to call from several threads.

#include <functional>
#include <ostream>
#include <string>

#include "core/progress.hpp"

namespace rheomag::app {

/// Seconds on a monotonic clock (steady_clock by default; a test passes its own).
using SecondsClock = std::function<double()>;

/// A callback printing "PREFIX: stage, done of total, elapsed, time left" lines on `out` (a total
/// that is a bound gives a time left that is one too; elapsed is the stage's, as reported). A
/// step with a detail is always printed, other reports at most every `interval` seconds; nothing
/// is printed before `quiet_for` seconds have passed since this call (a quick run stays silent).
/// Both are timed on `clock`, not on the events' elapsed times, which restart with each stage.
ProgressCallback progress_lines(const std::string& prefix, std::ostream& out, double interval = 2.0,
                                double quiet_for = 0.0, SecondsClock clock = {});

}  // namespace rheomag::app
