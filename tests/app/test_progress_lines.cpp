// The progress printer's rate limit and quiet start, on a clock the test moves (no sleeping).

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "app/progress_lines.hpp"

namespace {

using rheomag::ProgressEvent;

ProgressEvent event(const std::string& stage, double done, double total, double elapsed) {
  ProgressEvent e;
  e.stage = stage;
  e.done = done;
  e.total = total;
  e.elapsed = elapsed;
  return e;
}

/// A printer on a clock the test sets, writing into a string.
struct Printer {
  /// Interval 2 s, quiet for `quiet_for` s, the clock starting at `start`.
  explicit Printer(double quiet_for, double start = 0.0)
      : now(start),
        print(rheomag::app::progress_lines("cmd", out, 2.0, quiet_for, [this] { return now; })) {}
  /// Lines printed so far.
  int lines() const {
    const std::string s = out.str();
    return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
  }
  double now;
  std::ostringstream out;
  rheomag::ProgressCallback print;
};

}  // namespace

// At most one line every 2 s of the clock, the first report and a stage's last step always.
TEST(ProgressLines, PrintsAtMostEveryIntervalAndEveryLastStep) {
  Printer p(0.0);
  p.print(event("fitting", 1, 10, 0.1));  // first: printed
  p.now = 1.0;
  p.print(event("fitting", 2, 10, 1.0));  // 1 s later: not
  p.now = 2.5;
  p.print(event("fitting", 3, 10, 2.5));  // 2.5 s after the first: printed
  p.now = 2.6;
  p.print(event("fitting", 10, 10, 2.6));  // the last step: printed
  EXPECT_EQ(p.lines(), 3) << p.out.str();
  const std::string all = p.out.str(), last = "cmd: fitting, 10 of 10, 3 s\n";
  EXPECT_EQ(all.substr(all.size() - last.size()), last) << all;
}

// A second stage whose own elapsed time starts again at 0 (fit-family --cross-validate after the
// main fit; before the fix its lines were held back until the stage's elapsed time passed the
// first stage's: 28 s without a line on the utfsm 25 mm tests).
TEST(ProgressLines, AStageWhoseElapsedTimeRestartsIsStillPrinted) {
  Printer p(0.0);
  p.now = 26.0;
  p.print(event("main fit", 120, 120, 26.0));
  p.now = 29.0;
  p.print(event("cross-validation", 5, 390, 3.0));
  EXPECT_EQ(p.lines(), 2) << p.out.str();
  EXPECT_NE(p.out.str().find("cmd: cross-validation, 5 of 390, 3 s"), std::string::npos)
      << p.out.str();
}

// Nothing before quiet_for seconds of the clock since the printer was made, whatever the events
// say their elapsed time is.
TEST(ProgressLines, StaysQuietForItsFirstSeconds) {
  Printer p(2.0, 100.0);
  p.now = 101.0;
  p.print(event("meshing", 1, 2, 50.0));
  EXPECT_EQ(p.lines(), 0) << p.out.str();
  p.now = 102.5;
  p.print(event("meshing", 2, 2, 2.5));
  EXPECT_EQ(p.lines(), 1) << p.out.str();
}
