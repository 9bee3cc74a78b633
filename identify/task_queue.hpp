// Independent tasks, some waiting for others, run on a few threads: each thread takes the first
// task whose prerequisites have finished, so no core waits while a task it could run is ready.

#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rheomag::identify {

/// Calls run(i) once for every task i < prerequisites.size(), on up to `threads` threads, each
/// task only after every task listed in prerequisites[i] (lower or higher numbers) has returned;
/// among the ready tasks the lowest number first. After a task throws no further task starts; the
/// first exception thrown (in task order) is rethrown once the running tasks have returned. The
/// prerequisites must not form a cycle.
template <class Run>
void run_when_ready(const std::vector<std::vector<std::size_t>>& prerequisites, unsigned threads,
                    const Run& run) {
  const std::size_t count = prerequisites.size();
  std::vector<char> started(count, 0), finished(count, 0);
  std::vector<std::exception_ptr> errors(count);
  std::size_t left = count;
  bool failed = false;
  std::mutex mutex;
  std::condition_variable changed;
  const auto ready = [&](std::size_t i) {
    for (const std::size_t j : prerequisites[i])
      if (!finished[j]) return false;
    return true;
  };
  const auto work = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      std::size_t task = count;
      changed.wait(lock, [&] {
        if (failed || left == 0) return true;
        for (std::size_t i = 0; i < count && task == count; ++i)
          if (!started[i] && ready(i)) task = i;
        return task < count;
      });
      if (task == count) return;  // all started, or a task failed
      started[task] = 1;
      --left;
      lock.unlock();
      std::exception_ptr error;
      try {
        run(task);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      finished[task] = 1;
      if (error) {
        errors[task] = error;
        failed = true;
      }
      changed.notify_all();
    }
  };
  const unsigned workers = static_cast<unsigned>(
      std::min<std::size_t>(std::max(1u, threads), std::max<std::size_t>(count, 1)));
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace rheomag::identify
