#pragma once
// Progress of one diagnosis, timed.

#include <chrono>
#include <string>

#include "core/progress.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose {

/// Progress of one diagnosis: each finished stage with its own time, each candidate's result,
/// timed from the start of the run.
class Clock {
 public:
  using time_point = std::chrono::steady_clock::time_point;
  explicit Clock(const ProgressCallback& progress) : progress_(progress) {}
  /// [s] since `t`.
  static double since(time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
  /// [s] since the run started.
  double elapsed() const { return since(start_); }
  /// Reports `event` to the listener, if any (its elapsed time set here).
  void report(ProgressEvent event) const {
    if (!progress_) return;
    event.elapsed = elapsed();
    progress_(event);
  }
  /// Reports `event` timed from `from` (a stage's start, so that its done of total gives the time
  /// left in the stage).
  void report_since(ProgressEvent event, time_point from) const {
    if (!progress_) return;
    event.elapsed = since(from);
    progress_(event);
  }
  /// A finished stage: its name and its own time in the detail.
  void stage(const std::string& what) {
    const auto now = std::chrono::steady_clock::now();
    report({what, 0.0, 0.0, 0.0,
            "in " + num(std::chrono::duration<double>(now - stage_).count()) + " s"});
    stage_ = now;
  }

 private:
  const ProgressCallback& progress_;
  time_point start_ = std::chrono::steady_clock::now();
  time_point stage_ = start_;
};

}  // namespace rheomag::diagnose
