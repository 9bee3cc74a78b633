// Rate-limited, thread-safe progress lines.

#include "app/progress_lines.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>

namespace rheomag::app {

namespace {

std::string seconds_text(double s) {
  char buffer[32];
  if (s < 90.0)
    std::snprintf(buffer, sizeof buffer, "%.0f s", s);
  else
    std::snprintf(buffer, sizeof buffer, "%.1f min", s / 60.0);
  return buffer;
}

}  // namespace

ProgressCallback progress_lines(const std::string& prefix, std::ostream& out, double interval,
                                double quiet_for, SecondsClock clock) {
  if (!clock) {
    clock = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
          .count();
    };
  }
  struct State {
    std::mutex mutex;
    double last_printed = -1e300;
  };
  auto state = std::make_shared<State>();
  const double created = clock();
  return [=, &out](const ProgressEvent& e) {
    std::lock_guard<std::mutex> lock(state->mutex);
    const double now = clock() - created;
    if (now < quiet_for) return;
    const bool last_step = e.total > 0.0 && e.done >= e.total;
    if (e.detail.empty() && !last_step && now - state->last_printed < interval) return;
    state->last_printed = now;
    std::string line = prefix + ": " + e.stage;
    if (e.total > 0.0) {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, ", %.0f of %s%.0f", e.done,
                    e.total_is_bound ? "at most " : "", e.total);
      line += buffer;
    }
    line += ", " + seconds_text(e.elapsed);
    if (e.total > 0.0 && e.done > 0.0 && e.done < e.total) {
      const double left = e.elapsed / e.done * (e.total - e.done);
      line +=
          std::string(e.total_is_bound ? ", at most " : ", about ") + seconds_text(left) + " left";
    }
    if (!e.detail.empty()) line += ": " + e.detail;
    out << line << std::endl;
  };
}

}  // namespace rheomag::app
