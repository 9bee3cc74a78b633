// The progress printer's rate limit and quiet start, on a clock the test moves (no sleeping).

#include <gtest/gtest.h>

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

int lines(const std::ostringstream& out) {
  const std::string s = out.str();
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace

// At most one line every 2 s of the clock, the first report and a stage's last step always.
TEST(ProgressLines, PrintsAtMostEveryIntervalAndEveryLastStep) {
  double now = 0.0;
  std::ostringstream out;
  const auto print = rheomag::app::progress_lines("cmd", out, 2.0, 0.0, [&] { return now; });
  print(event("fitting", 1, 10, 0.1));  // first: printed
  now = 1.0;
  print(event("fitting", 2, 10, 1.0));  // 1 s later: not
  now = 2.5;
  print(event("fitting", 3, 10, 2.5));  // 2.5 s after the first: printed
  now = 2.6;
  print(event("fitting", 10, 10, 2.6));  // the last step: printed
  EXPECT_EQ(lines(out), 3) << out.str();
  const std::string last = "cmd: fitting, 10 of 10, 3 s\n";
  EXPECT_EQ(out.str().substr(out.str().size() - last.size()), last) << out.str();
}

// A second stage whose own elapsed time starts again at 0 (fit-family --cross-validate after the
// main fit; before the fix its lines were held back until the stage's elapsed time passed the
// first stage's: 28 s without a line on the utfsm 25 mm tests).
TEST(ProgressLines, AStageWhoseElapsedTimeRestartsIsStillPrinted) {
  double now = 0.0;
  std::ostringstream out;
  const auto print = rheomag::app::progress_lines("cmd", out, 2.0, 0.0, [&] { return now; });
  now = 26.0;
  print(event("main fit", 120, 120, 26.0));
  now = 29.0;
  print(event("cross-validation", 5, 390, 3.0));
  EXPECT_EQ(lines(out), 2) << out.str();
  EXPECT_NE(out.str().find("cmd: cross-validation, 5 of 390, 3 s"), std::string::npos) << out.str();
}

// Nothing before quiet_for seconds of the clock since the printer was made, whatever the events
// say their elapsed time is.
TEST(ProgressLines, StaysQuietForItsFirstSeconds) {
  double now = 100.0;
  std::ostringstream out;
  const auto print = rheomag::app::progress_lines("cmd", out, 2.0, 2.0, [&] { return now; });
  now = 101.0;
  print(event("meshing", 1, 2, 50.0));
  EXPECT_EQ(lines(out), 0) << out.str();
  now = 102.5;
  print(event("meshing", 2, 2, 2.5));
  EXPECT_EQ(lines(out), 1) << out.str();
}
