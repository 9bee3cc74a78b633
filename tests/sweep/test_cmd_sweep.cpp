// `rheomag sweep` as a process: killed mid-way (SIGKILL) and re-run gives the CSV of an
// uninterrupted run; SIGTERM stops cleanly (exit 130) and resumes; an unknown key exits 2 with
// a suggestion; mpirun -n 2 (when installed) gives the serial CSV.

#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "sweep/mpi.hpp"
#include "sweep_fixture.hpp"

namespace rheomag::sweep {
namespace {

using namespace testing;

// 2 gap widths x 12 currents = 24 designs of the tiny valve.
const std::string kAxes =
    "[[axis]]\nkey = \"geometry.gap_width\"\nvalues = [0.8, 1.2]\n"
    "[[axis]]\nkey = \"circuit.current\"\nstart = 0.1\nstop = 1.2\ncount = 12\n";
constexpr std::size_t kDesigns = 24;

std::size_t rows_in(const std::filesystem::path& csv) {
  const std::string text = read_text(csv);
  const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  return lines > 0 ? lines - 1 : 0;
}

/// Starts the sweep, waits until `rows` rows are in its CSV, sends `signal`; returns the exit
/// code and the rows then in the file.
std::pair<int, std::size_t> interrupt_after(const std::filesystem::path& dir,
                                            const std::filesystem::path& sweep, std::size_t rows,
                                            int signal) {
  const pid_t pid = start_cli({"sweep", sweep.string(), "--jobs", "1", "--out", dir.string()},
                              dir / "killed.out", dir / "killed.err");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (rows_in(dir / "results.csv") < rows && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, signal);
  const int code = wait_exit(pid);
  return {code, rows_in(dir / "results.csv")};
}

class SweepCli : public ::testing::Test {
 protected:
  void SetUp() override {
    reference_dir = scratch_dir("cli-reference");
    sweep = write_file(reference_dir, "sweep.toml", sweep_text("", kAxes));
    const CliRun run = run_cli(
        {"sweep", sweep.string(), "--out", reference_dir.string(), "--jobs", "2"}, reference_dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    reference = read_text(reference_dir / "results.csv");
    ASSERT_EQ(rows_in(reference_dir / "results.csv"), kDesigns);
  }
  std::filesystem::path reference_dir, sweep;
  std::string reference;
};

TEST_F(SweepCli, KilledMidwayAndRerunGivesTheUninterruptedCsv) {
  const auto dir = scratch_dir("cli-killed");
  const auto [code, rows] = interrupt_after(dir, sweep, 3, SIGKILL);
  EXPECT_EQ(code, 128 + SIGKILL);
  EXPECT_GE(rows, 3u);
  EXPECT_LT(rows, kDesigns) << "the sweep finished before it could be killed";
  const CliRun rerun = run_cli({"sweep", sweep.string(), "--out", dir.string()}, dir);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_EQ(read_text(dir / "results.csv"), reference);
}

TEST_F(SweepCli, TerminatedStopsCleanlyAndResumes) {
  const auto dir = scratch_dir("cli-term");
  const auto [code, rows] = interrupt_after(dir, sweep, 2, SIGTERM);
  // finished the running design, kept the rows, reported interruption; 128 + SIGTERM (issue 36)
  EXPECT_EQ(code, 128 + SIGTERM);
  EXPECT_LT(rows, kDesigns);
  EXPECT_NE(read_text(dir / "killed.out").find("interrupted"), std::string::npos);
  const CliRun rerun = run_cli({"sweep", sweep.string(), "--out", dir.string(), "--json"}, dir);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_NE(rerun.out.find("\"resumed\":" + std::to_string(rows)), std::string::npos) << rerun.out;
  EXPECT_EQ(read_text(dir / "results.csv"), reference);
}

TEST(SweepCliErrors, UnknownKeyExitsTwoWithTheSuggestionAndWritesNothing) {
  const auto dir = scratch_dir("cli-unknown");
  const auto sweep = write_file(
      dir, "sweep.toml", sweep_text("", "[[axis]]\nkey = \"geometry.gap_with\"\nvalues = [1]\n"));
  const CliRun run = run_cli({"sweep", sweep.string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("did you mean 'geometry.gap_width'"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// Issue 36: `-j -1` printed the largest double in full (309 digits) as the range's upper end.
TEST(SweepCliErrors, NegativeJobsNamesTheRangeReadably) {
  const auto dir = scratch_dir("cli-jobs");
  const auto sweep = write_file(dir, "sweep.toml", sweep_text("", ""));
  const CliRun run = run_cli({"sweep", sweep.string(), "-j", "-1"}, dir);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--jobs: expected a whole number >= 0, got -1"), std::string::npos)
      << run.err;
  EXPECT_LT(run.err.size(), 200u) << run.err;
}

// Issue 36, a security defect: `[output] csv` wrote where it named, `/abs.csv`, `../x.csv` or a
// folder linked out of --out (its _vtu/ folder too). Every way out is refused with exit 2 at the
// spec's line and key, before anything is written; a subfolder inside --out stays allowed.
TEST(SweepCliErrors, OutputsOutsideTheOutputFolderAreRefused) {
  namespace fs = std::filesystem;
  const auto dir = scratch_dir("cli-escape");
  fs::create_directories(dir / "out" / "sub");
  fs::create_directories(dir / "elsewhere");
  fs::create_symlink("../elsewhere", dir / "out" / "link");
  fs::create_symlink("../elsewhere", dir / "out" / "r_vtu");
  const std::string axes = "[[axis]]\nkey = \"circuit.0.current\"\nvalues = [1.0]\n";
  const struct {
    std::string csv, expected;
  } cases[] = {
      {(dir / "abs.csv").string(), "is an absolute path"},
      {"../x.csv", "leaves the output folder through '..'"},
      {"sub/../../x.csv", "leaves the output folder through '..'"},
      {"link/x.csv", "resolves through a symbolic link to " + (dir / "elsewhere").string()},
      {"r.csv", "writes " + (dir / "out" / "r_vtu").string()},  // vtu = true: r_vtu/ is a link
  };
  for (const auto& c : cases) {
    const auto sweep = write_file(dir, "sweep.toml",
                                  sweep_text("", axes, "csv = \"" + c.csv + "\"\nvtu = true\n"));
    const CliRun run =
        run_cli({"sweep", sweep.string(), "-q", "--out", (dir / "out").string()}, dir);
    EXPECT_EQ(run.exit_code, 2) << c.csv << ": " << run.err;
    EXPECT_NE(run.err.find("sweep.toml:9: output.csv: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.err;
  }
  EXPECT_TRUE(fs::is_empty(dir / "elsewhere"));
  EXPECT_FALSE(fs::exists(dir / "abs.csv"));
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
  const auto inside = write_file(dir, "sweep.toml", sweep_text("", axes, "csv = \"sub/r.csv\"\n"));
  const CliRun ok = run_cli({"sweep", inside.string(), "-q", "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "sub" / "r.csv"));
}

// A design outside a key's domain is an error row citing the key's line of the base case (the
// probe found the line of a comment above it): comments precede both keys here.
TEST(SweepCliErrors, ErrorRowsCiteTheKeyLineOfTheBaseCase) {
  const auto dir = scratch_dir("cli-error-line");
  std::string base = read_text(tiny_valve());
  base.replace(base.find("gap_width = 1.0"), 0, "# the clearance under study\n# (mm)\n");
  base.replace(base.find("outer_radius_factor"), 0, "# open boundary distance\n");
  const auto base_path = write_file(dir, "base.toml", base);
  auto line_of = [&](const std::string& key) {
    const std::size_t at = base.find("\n" + key + " = ");
    return 2 + std::count(base.begin(), base.begin() + static_cast<std::ptrdiff_t>(at), '\n');
  };
  const auto sweep = write_file(dir, "sweep.toml",
                                "[sweep]\nbase = \"" + base_path.string() +
                                    "\"\n[[axis]]\nkey = \"geometry.gap_width\"\nvalues = [0.0, "
                                    "1.0]\n[[axis]]\nkey = \"solver.outer_radius_factor\"\n"
                                    "values = [3.0, 1e9]\n[output]\ncsv = \"results.csv\"\n");
  const CliRun run = run_cli({"sweep", sweep.string(), "--out", (dir / "out").string()}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> rows = lines_of(read_text(dir / "out/results.csv"));
  ASSERT_EQ(rows.size(), 5u);
  const std::string gap = base_path.string() + ":" + std::to_string(line_of("gap_width")) +
                          ": geometry.gap_width: expected a positive number, got 0\"";
  const std::string radius = base_path.string() + ":" +
                             std::to_string(line_of("outer_radius_factor")) +
                             ": solver.outer_radius_factor: expected a number in (1, 100], got "
                             "1000000000\"";
  EXPECT_NE(rows[1].find(gap), std::string::npos) << rows[1];
  EXPECT_NE(rows[2].find(gap), std::string::npos) << rows[2];
  EXPECT_NE(rows[4].find(radius), std::string::npos) << rows[4];
  EXPECT_NE(rows[3].find(",ok,"), std::string::npos) << rows[3];
}

TEST(SweepCliErrors, UnwritableOutputDirectoryExitsTwo) {
  const auto dir = scratch_dir("cli-unwritable");
  write_file(dir, "file", "x");
  const auto sweep = write_file(
      dir, "sweep.toml", sweep_text("", "[[axis]]\nkey = \"circuit.current\"\nvalues = [1]\n"));
  const CliRun run = run_cli({"sweep", sweep.string(), "--out", (dir / "file/out").string()}, dir);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("cannot be created"), std::string::npos) << run.err;
}

bool have_mpirun() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string dirs = path;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    if (::access((dirs.substr(start, end - start) + "/mpirun").c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

TEST_F(SweepCli, MpiRunEqualsTheSerialRun) {
  if (!have_mpirun()) GTEST_SKIP() << "mpirun not installed";
  if (!mpi_built()) GTEST_SKIP() << "rheomag built without MPI";
  const auto dir = scratch_dir("cli-mpi");
  const pid_t pid =
      start_program({"mpirun", "-n", "2", "--oversubscribe", "--allow-run-as-root", RHEOMAG_BINARY,
                     "sweep", sweep.string(), "--out", dir.string(), "--json"},
                    dir / "mpi.out", dir / "mpi.err");
  const int code = wait_exit(pid);
  ASSERT_EQ(code, 0) << read_text(dir / "mpi.err");
  // One summary (from rank 0 only) that solved all designs on the worker rank.
  const std::string out = read_text(dir / "mpi.out");
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
  EXPECT_NE(out.find("\"evaluated\":24"), std::string::npos) << out;
  EXPECT_EQ(read_text(dir / "results.csv"), reference);
}

}  // namespace
}  // namespace rheomag::sweep
