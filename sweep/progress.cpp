#include "sweep/progress.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace rheomag::sweep {

namespace {

std::string duration_text(double seconds) {
  if (!std::isfinite(seconds)) return "?";
  const long long s = std::llround(seconds);
  char buffer[32];
  if (s >= 3600) {
    std::snprintf(buffer, sizeof buffer, "%lldh%02lldm", s / 3600, (s / 60) % 60);
  } else if (s >= 60) {
    std::snprintf(buffer, sizeof buffer, "%lldm%02llds", s / 60, s % 60);
  } else {
    std::snprintf(buffer, sizeof buffer, "%llds", s);
  }
  return buffer;
}

}  // namespace

SweepProgress::SweepProgress(long long total, std::ostream* out, bool terminal)
    : total_(total),
      out_(out),
      terminal_(terminal),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double SweepProgress::rate_per_minute() const {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return done_ > 0 && elapsed > 0.0 ? 60.0 * static_cast<double>(done_) / elapsed : 0.0;
}

void SweepProgress::record(bool ok) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  if (!ok) ++errors_;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_draw_).count();
  if (since >= (terminal_ ? 0.2 : kPlainInterval) && done_ < total_) {
    last_draw_ = now;
    draw(false);
  }
  warn_if_long(std::chrono::duration<double>(now - start_).count());
}

std::string long_run_warning(long long done, long long total, double elapsed) {
  // The pace of a few designs (or of 30 s) is enough to tell a run of days from one of hours.
  if (done <= 0 || done >= total || (done < 3 && elapsed < 30.0)) return "";
  const double left = elapsed / static_cast<double>(done) * static_cast<double>(total - done);
  if (!(left > SweepProgress::kLongRun)) return "";
  char line[320];
  std::snprintf(line, sizeof line,
                "sweep: warning: at the pace of the first %lld designs the remaining %lld take "
                "about %.1f days; stop it at any time (Ctrl-C keeps the finished rows and a new "
                "run resumes after them), or split it with --shard K/N",
                done, total - done, left / 86400.0);
  return line;
}

void SweepProgress::warn_if_long(double elapsed) {
  if (warned_ || !out_) return;
  const std::string warning = long_run_warning(done_, total_, elapsed);
  if (warning.empty()) return;
  warned_ = true;
  *out_ << (terminal_ ? "\n" : "") << warning << "\n" << std::flush;
}

void SweepProgress::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  draw(true);
}

void SweepProgress::draw(bool final) {
  if (!out_) return;
  const double rate = rate_per_minute();
  const double eta = rate > 0.0 ? 60.0 * static_cast<double>(total_ - done_) / rate : NAN;
  char numbers[160];
  std::snprintf(
      numbers, sizeof numbers, "%lld/%lld designs, %lld errors, %.1f designs/min, %s %s", done_,
      total_, errors_, rate, final ? "took" : "ETA",
      final ? duration_text(
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count())
                  .c_str()
            : duration_text(eta).c_str());
  if (terminal_) {
    constexpr int width = 30;
    const int filled = total_ > 0 ? static_cast<int>(width * done_ / total_) : width;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(width - filled), '.');
    *out_ << "\r\033[K[" << bar << "] " << numbers << (final ? "\n" : "") << std::flush;
  } else {
    *out_ << "sweep: " << numbers << "\n" << std::flush;
  }
}

}  // namespace rheomag::sweep
