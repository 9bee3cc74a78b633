#pragma once
// Progress of a long command on stderr: a library's ProgressCallback printed as plain lines, at
// most one every few seconds (plus every finished step), safe to call from several threads.

#include <ostream>
#include <string>

#include "core/progress.hpp"

namespace rheomag::app {

/// A callback printing "PREFIX: stage, done of total, elapsed, time left" lines on `out` (a total
/// that is a bound gives a time left that is one too); a step with a detail is always printed,
/// other reports at most every `interval` seconds; nothing is printed before `quiet_for` seconds
/// have passed (a quick run stays silent).
ProgressCallback progress_lines(const std::string& prefix, std::ostream& out, double interval = 2.0,
                                double quiet_for = 0.0);

}  // namespace rheomag::app
