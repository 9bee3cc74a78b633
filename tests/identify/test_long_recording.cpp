// A recording too long to fit whole is thinned to every n-th sample by the stated rule
// (lumped::kMaxFitSamples), and says so in the text and the JSON (issue #36: a 10^7-row recording
// took 6.6 GB and "132 min left" in `fit --model bingham`).

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../cli_run.hpp"
#include "lumped/recording_excerpt.hpp"

namespace fs = std::filesystem;
using namespace rheomag;

namespace {

/// rec.csv + rec.toml in `dir`: `rows` samples of a damper at 10 kHz, velocity sine, Bingham
/// force 400 tanh(v / 0.01) + 2000 v [N].
void write_long_damper(const fs::path& dir, int rows) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream csv(dir / "rec.csv");
  csv << "t,velocity,force\n";
  for (int k = 0; k < rows; ++k) {
    const double t = k * 1e-4, v = 0.05 * std::sin(2 * M_PI * 2 * t);
    csv << t << ',' << v << ',' << 400 * std::tanh(v / 0.01) + 2000 * v << '\n';
  }
  std::ofstream(dir / "rec.toml") << "[recording]\ndrive = [\"velocity\"]\noutput = \"force\"\n"
                                     "[rig]\nkind = \"damper\"\n";
}

}  // namespace

TEST(LongRecording, ThinningRuleKeepsEveryNthSampleAndItsRanges) {
  EXPECT_EQ(lumped::thinning_factor(lumped::kMaxFitSamples), 1u);
  EXPECT_EQ(lumped::thinning_factor(lumped::kMaxFitSamples + 1), 2u);
  EXPECT_EQ(lumped::thinning_factor(10'000'000), 50u);
  lumped::Recording rec;
  rec.csv_path = "r.csv";
  for (int k = 0; k < 10; ++k) rec.t.push_back(k);
  rec.columns["force"] = rec.t;
  const lumped::Recording thin = lumped::every_nth_sample(rec, 3);
  EXPECT_EQ(thin.t, (std::vector<double>{0, 3, 6, 9}));
  EXPECT_EQ(thin.columns.at("force"), thin.t);
  // Samples 4:8 of the original are 4..7; of those the thinned recording keeps 6 (its sample 2).
  const lumped::SampleRange r = lumped::thinned_range({4, 8}, 3);
  EXPECT_EQ(r.begin, 2u);
  EXPECT_EQ(r.end, 3u);
  EXPECT_EQ(lumped::thinning_note(10'000'000, 50).rfind("every 50th of its 10000000 samples", 0),
            0u);
  EXPECT_EQ(lumped::thinning_note(700'000, 2).rfind("every 2nd of its", 0), 0u);
}

// 450 000 rows: thinned to every 3rd (150 000 samples), the ranges follow, and the fit is still
// the generating law (FIT > 99 %: the static Bingham law is exact on every kept sample).
TEST(LongRecording, FitThinsARecordingTooLongAndSaysSo) {
  const fs::path dir = fs::temp_directory_path() / "rheomag_long_recording_fit";
  write_long_damper(dir, 450'000);
  const auto json = cli_test::run_rheomag("fit rec.csv --model bingham --json", dir);
  ASSERT_EQ(json.code, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  ASSERT_TRUE(j.contains("thinned")) << json.out;
  EXPECT_NE(j["thinned"][0].get<std::string>().find("every 3rd of its 450000 samples"),
            std::string::npos)
      << j["thinned"];
  EXPECT_EQ(j["train_range"][1].get<std::size_t>(), 150'000u);
  EXPECT_GT(j["train"]["fit_percent"].get<double>(), 99.0);
  const auto text = cli_test::run_rheomag("fit rec.csv --model bingham --train 0:300000", dir);
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("samples: rec.csv: every 3rd of its 450000 samples"), std::string::npos)
      << text.out;
  fs::remove_all(dir);
}

// SIGINT during a long fit (issue #36, "also a sweep and a fit"): sent 1 s after rheomag installed
// its handlers (read from /proc, so a loaded machine does not signal it before main), the run
// ends with 130 and its message, and leaves nothing in the folder but the recording (no
// temporary).
TEST(LongRecording, FitInterruptedBySigintEndsCleanly) {
  const fs::path dir = fs::temp_directory_path() / "rheomag_long_recording_sigint";
  write_long_damper(dir, 450'000);
  const pid_t pid = cli_test::start_rheomag(dir, {"fit", "rec.csv", "--model", "bouc-wen"});
  ASSERT_GT(pid, 0);
  for (int k = 0; k < 600 && !cli_test::catches_signal(pid, SIGINT); ++k) ::usleep(50'000);
  ::usleep(1'000'000);
  ::kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream err(dir / "err.txt");
  const std::string message{std::istreambuf_iterator<char>(err), {}};
  EXPECT_NE(message.find("rheomag: interrupted (SIGINT)"), std::string::npos) << message;
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"err.txt", "out.txt", "rec.csv", "rec.toml"}));
  fs::remove_all(dir);
}
