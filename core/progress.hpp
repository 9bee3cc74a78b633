#pragma once
// Progress of a long computation, reported by libraries through a callback that the caller
// (the CLI) prints; libraries never write to the terminal themselves.

#include <functional>
#include <string>

namespace rheomag {

/// One progress report: what is being done, how far (done of total, total 0 when unknown) and
/// the seconds elapsed since the computation started.
struct ProgressEvent {
  std::string stage;            ///< e.g. "candidate fluid_inertia" or "design 12"
  double done = 0.0;            ///< units of work finished
  double total = 0.0;           ///< units of work in all (0: unknown)
  double elapsed = 0.0;         ///< [s]
  std::string detail;           ///< a finished step's result, e.g. "dBIC 12.3" ("" while running)
  bool total_is_bound = false;  ///< `total` is an upper bound (e.g. an iteration limit)
};

/// Receives progress reports; an empty callback means nobody listens. Never called from two
/// threads at once (parallel work serialises its reports), so it need not be thread-safe.
using ProgressCallback = std::function<void(const ProgressEvent&)>;

}  // namespace rheomag
