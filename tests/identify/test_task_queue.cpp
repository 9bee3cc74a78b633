// run_when_ready (identify/task_queue.hpp), the scheduler of the cross-validation's fits: every
// task runs once, after its prerequisites; a thread takes a task as soon as it is ready rather than
// waiting for unrelated tasks; the first error is rethrown and stops further starts.

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "identify/task_queue.hpp"

using rheomag::identify::run_when_ready;

namespace {

/// The order in which tasks started and finished, recorded from several threads.
struct Log {
  std::mutex mutex;
  std::vector<std::size_t> started, finished;
  void start(std::size_t i) {
    const std::lock_guard<std::mutex> lock(mutex);
    started.push_back(i);
  }
  void finish(std::size_t i) {
    const std::lock_guard<std::mutex> lock(mutex);
    finished.push_back(i);
  }
  /// Position of task i in `finished` (finished.size() if it never finished).
  std::size_t finished_at(std::size_t i) const {
    for (std::size_t k = 0; k < finished.size(); ++k)
      if (finished[k] == i) return k;
    return finished.size();
  }
};

}  // namespace

// The cross-validation's shape: two halves, then refits that each wait for one half. Every task
// runs exactly once, and each refit starts only after its half has finished (checked on the
// recorded order: when a refit starts, its half is already in the finished list).
TEST(TaskQueue, EveryTaskRunsOnceAfterItsPrerequisites) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    std::vector<std::vector<std::size_t>> prerequisites(2);
    for (std::size_t k = 0; k < 9; ++k) prerequisites.push_back({k % 2});
    Log log;
    std::vector<std::size_t> finished_before_start(prerequisites.size(), 0);
    run_when_ready(prerequisites, threads, [&](std::size_t i) {
      {
        const std::lock_guard<std::mutex> lock(log.mutex);
        for (const std::size_t j : prerequisites[i])
          for (const std::size_t f : log.finished) finished_before_start[i] += f == j;
        log.started.push_back(i);
      }
      log.finish(i);
    });
    ASSERT_EQ(log.started.size(), prerequisites.size()) << threads;
    ASSERT_EQ(log.finished.size(), prerequisites.size()) << threads;
    for (std::size_t i = 0; i < prerequisites.size(); ++i) {
      EXPECT_LT(log.finished_at(i), prerequisites.size()) << "task " << i << " never finished";
      EXPECT_EQ(finished_before_start[i], prerequisites[i].size()) << "task " << i;
    }
  }
}

// A thread that finishes one half goes on with the refits that wait only for it while the other
// half still runs. Task 0 (the long half) cannot end until task 2, which waits for task 1 (the
// short half), has run: with two threads this completes; a scheduler that waited for both halves
// before any refit would hang, which the 20-s guard turns into a failure.
TEST(TaskQueue, AReadyTaskDoesNotWaitForAnUnrelatedOne) {
  const std::vector<std::vector<std::size_t>> prerequisites = {{}, {}, {1}, {0}};
  std::mutex mutex;
  std::condition_variable changed;
  bool refit_done = false, released = false;
  Log log;
  run_when_ready(prerequisites, 2, [&](std::size_t i) {
    log.start(i);
    if (i == 0) {
      std::unique_lock<std::mutex> lock(mutex);
      released = changed.wait_for(lock, std::chrono::seconds(20), [&] { return refit_done; });
    }
    if (i == 2) {  // recorded as finished before task 0 may go on
      log.finish(i);
      const std::lock_guard<std::mutex> lock(mutex);
      refit_done = true;
      changed.notify_all();
      return;
    }
    log.finish(i);
  });
  EXPECT_TRUE(released) << "task 2 did not run while task 0 was running";
  EXPECT_LT(log.finished_at(2), log.finished_at(0));
  EXPECT_LT(log.finished_at(0), log.finished_at(3));
}

// An error stops further starts and is rethrown: with one thread and tasks in order, task 1
// throws, tasks 2.. never start; the rethrown error is task 1's.
TEST(TaskQueue, TheFirstErrorIsRethrownAndStopsFurtherTasks) {
  const std::vector<std::vector<std::size_t>> prerequisites(6);
  Log log;
  try {
    run_when_ready(prerequisites, 1, [&](std::size_t i) {
      log.start(i);
      if (i == 1) throw std::runtime_error("task 1 failed");
      log.finish(i);
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 1 failed");
  }
  EXPECT_EQ(log.started, (std::vector<std::size_t>{0, 1}));
}

// No tasks: returns at once.
TEST(TaskQueue, NoTasksIsNothingToDo) {
  int calls = 0;
  run_when_ready({}, 2, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}
