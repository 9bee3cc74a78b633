// SIGTERM and SIGINT during a large 3D solve (`solve --3d --full --mesher swept` of a valve with
// a bolt hole in air, 337k tetrahedra, 90 s uninterrupted): the run ends within 3 s with exit
// 143 / 130 (128 + the signal), never by a signal (the SIGSEGV, exit 139), and leaves no
// output file and no temporary. Phases: case reading and meshing, assembly, factorisation and
// Newton; also a sweep, which keeps its finished rows.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "../cli_run.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kSmallValve = fs::path(RHEOMAG_TEST_DATA) / "magnetostatics3d/small_valve.toml";

fs::path signal_scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rheomag_signal_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// True once process `pid` catches SIGTERM (its handlers are installed: the start of main).
bool catches_sigterm(pid_t pid) {
  return rheomag::cli_test::catches_signal(pid, SIGTERM);
}

/// Waits until err.txt in `dir` holds `text` (empty: until the process catches SIGTERM; before
/// main the default action applies, as for any program), at most 60 s; false if the process
/// ended first.
bool wait_for_stderr(const fs::path& dir, pid_t pid, const std::string& text) {
  for (int k = 0; k < 6000; ++k) {
    if (text.empty() ? catches_sigterm(pid)
                     : text_of(dir / "err.txt").find(text) != std::string::npos)
      return true;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

struct Ended {
  int status = 0;
  double seconds = 0.0;  // from the signal to the end
};

Ended signal_and_wait(pid_t pid, int signal_number) {
  const auto sent = std::chrono::steady_clock::now();
  ::kill(pid, signal_number);
  Ended e;
  for (int k = 0; k < 3000; ++k) {  // 30 s at most, then killed
    if (::waitpid(pid, &e.status, WNOHANG) == pid) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (k == 2999) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &e.status, 0);
    }
  }
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  return e;
}

/// A copy of small_valve with an axial bolt hole of radius 6 mm in the air around it.
fs::path write_holed_valve(const fs::path& dir) {
  const fs::path file = dir / "holed.toml";
  std::ofstream(file) << text_of(kSmallValve)
                      << "\n[[feature]]\nkind = \"hole\"\nregion = \"air\"\nradius = 6.0\n"
                         "position = 20.0\nangle = 30\n";
  return file;
}

/// Every file of `dir` but the inputs and the captured streams (outputs, temporaries).
std::vector<std::string> left_files(const fs::path& dir) {
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name != "holed.toml" && name != "out.txt" && name != "err.txt" && name != "sweep.toml" &&
        name != "sweep_out")
      left.push_back(name);
  }
  return left;
}

void expect_clean_end(const Ended& e, int signal_number, const fs::path& dir,
                      const std::string& phase) {
  ASSERT_TRUE(WIFEXITED(e.status)) << phase << ": ended by signal " << WTERMSIG(e.status);
  EXPECT_EQ(WEXITSTATUS(e.status), 128 + signal_number) << phase << "\n"
                                                        << text_of(dir / "err.txt");
  EXPECT_LT(e.seconds, 3.0) << phase;
  EXPECT_EQ(left_files(dir), std::vector<std::string>{}) << phase;
  const std::string err = text_of(dir / "err.txt");
  EXPECT_EQ(err.find("internal error"), std::string::npos) << phase << ": " << err;
}

}  // namespace

TEST(InterruptCli, Solve3dEndsCleanlyAtEveryPhase) {
  const fs::path dir = signal_scratch("solve3d");
  const std::string holed = write_holed_valve(dir).string();
  const std::vector<std::string> args{"solve",    holed,   "--3d",  "--full",
                                      "--mesher", "swept", "--vtk", "field.vtu"};
  struct Phase {
    const char* name;
    const char* after;  // stderr text that starts the phase
    int delay_ms;
    int signal_number;
  };
  for (const Phase& p :
       {Phase{"case reading", "", 0, SIGTERM}, Phase{"meshing", "3d: mesh", 300, SIGINT},
        Phase{"assembly", "3d: solve", 200, SIGTERM},
        Phase{"factorisation and Newton", "3d: solve", 4000, SIGTERM},
        Phase{"factorisation and Newton (SIGINT)", "3d: solve", 6000, SIGINT}}) {
    const pid_t pid = rheomag::cli_test::start_rheomag(dir, args);
    ASSERT_GT(pid, 0);
    ASSERT_TRUE(wait_for_stderr(dir, pid, p.after)) << p.name << ": " << text_of(dir / "err.txt");
    std::this_thread::sleep_for(std::chrono::milliseconds(p.delay_ms));
    expect_clean_end(signal_and_wait(pid, p.signal_number), p.signal_number, dir, p.name);
    EXPECT_NE(text_of(dir / "err.txt").find(p.signal_number == SIGINT ? "SIGINT" : "SIGTERM"),
              std::string::npos)
        << p.name;
  }
  fs::remove_all(dir);
}

TEST(InterruptCli, SweepKeepsItsFinishedRowsAndExits143) {
  const fs::path dir = signal_scratch("sweep");
  // Twelve 2D designs of the small valve; the signal comes after the first row.
  std::ofstream(dir / "sweep.toml")
      << "[sweep]\nbase = \"" << kSmallValve.string()
      << "\"\n[[axis]]\nkey = \"geometry.gap_width\"\nvalues = [1.0, 1.2, 1.4, 1.6, 1.8, 2.0, "
         "2.2, 2.4, 2.6, 2.8, 3.0, 3.2]\n";
  const pid_t pid =
      rheomag::cli_test::start_rheomag(dir, {"sweep", "sweep.toml", "-j", "1", "-o", "sweep_out"});
  ASSERT_GT(pid, 0);
  const fs::path csv = dir / "sweep_out" / "results.csv";
  bool has_row = false;
  for (int k = 0; k < 6000 && !has_row; ++k) {
    const std::string text = text_of(csv);
    has_row = std::count(text.begin(), text.end(), '\n') >= 2;  // header and one row
    if (!has_row) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(has_row) << text_of(dir / "err.txt");
  const Ended e = signal_and_wait(pid, SIGTERM);
  ASSERT_TRUE(WIFEXITED(e.status));
  EXPECT_EQ(WEXITSTATUS(e.status), 143) << text_of(dir / "err.txt");
  const std::string rows = text_of(csv);
  EXPECT_GE(std::count(rows.begin(), rows.end(), '\n'), 2) << rows;  // the finished rows kept
  fs::remove_all(dir);
}
