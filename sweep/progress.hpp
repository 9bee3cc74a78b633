#pragma once
// Progress of a running sweep on stderr: a redrawn bar with rate and ETA on a terminal, plain
// lines (at most one every few seconds, plus the last) otherwise.

#include <chrono>
#include <mutex>
#include <ostream>
#include <string>

namespace rheomag::sweep {

/// Counts finished designs and reports done/total, errors, designs per minute and ETA.
class SweepProgress {
 public:
  /// `total` designs to run now (resumed ones excluded); `out` null: silent.
  SweepProgress(long long total, std::ostream* out, bool terminal);
  /// One design finished (thread-safe).
  void record(bool ok);
  /// Final report (a completed bar or a last line).
  void finish();
  long long done() const { return done_; }
  long long errors() const { return errors_; }
  /// Designs per minute so far (0 before the first one finishes).
  double rate_per_minute() const;

  /// Least time between plain progress lines [s].
  static constexpr double kPlainInterval = 2.0;
  /// A run whose estimated time left exceeds this [s] (a day) is warned about once, as soon as
  /// the first designs give its pace.
  static constexpr double kLongRun = 86400.0;

 private:
  void draw(bool final);
  void warn_if_long(double elapsed);
  long long total_;
  std::ostream* out_;
  bool terminal_;
  long long done_ = 0;
  long long errors_ = 0;
  bool warned_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  std::mutex mutex_;
};

/// The warning of a run that would take more than SweepProgress::kLongRun at the pace of its
/// first `done` of `total` designs in `elapsed` seconds ("" when it would not, or when fewer than
/// 3 designs and 30 s give no pace yet).
std::string long_run_warning(long long done, long long total, double elapsed);

}  // namespace rheomag::sweep
