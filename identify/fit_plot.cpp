#include "identify/fit_plot.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "identify/black_box_model.hpp"

extern char** environ;

namespace rheomag::identify {

namespace {

/// A gnuplot single-quoted string literal.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

/// A scratch folder removed when it goes out of scope.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "rheomag-plot-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw InputError("--plot: cannot create a temporary folder");
    path = pattern;
    removed_if_interrupted.emplace(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  std::optional<InterruptCleanupFile> removed_if_interrupted;
};

}  // namespace

bool gnuplot_available() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate =
        std::filesystem::path(dir.empty() ? "." : dir) / "gnuplot";
    if (access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string fit_plot_script(const std::string& png_path, const std::string& title,
                            const std::string& output_label,
                            const std::vector<PlotSegment>& segments,
                            const std::vector<std::string>& data_files) {
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1400,900 font 'sans,11' noenhanced\n"
     << "set output " << quoted(png_path) << "\n"
     << "set multiplot layout 2,1 title " << quoted(title) << "\n"
     << "set grid\nset key outside right top\nset xlabel 't [s]'\n"
     << "set ylabel " << quoted(output_label) << "\n";
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  gp << "plot ";
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (s) gp << ", ";
    gp << quoted(data_files[s]) << " using 1:2 with lines lw 1.5 lc rgb 'black' title "
       << quoted(s == 0 ? "measured" : "") << ", " << quoted(data_files[s])
       << " using 1:3 with lines lw 1.2 lc rgb '" << colours[s % 4] << "' title "
       << quoted("model, " + segments[s].label);
  }
  gp << "\nset ylabel " << quoted("residual (measured - model)") << "\nplot ";
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (s) gp << ", ";
    gp << quoted(data_files[s]) << " using 1:4 with lines lw 1 lc rgb '" << colours[s % 4]
       << "' title " << quoted(segments[s].label);
  }
  gp << "\nunset multiplot\nset output\n";
  return gp.str();
}

void write_fit_plot(const std::string& png_path, const std::string& title,
                    const std::string& output_label, const std::vector<PlotSegment>& segments) {
  if (!gnuplot_available())
    throw InputError("--plot needs gnuplot on PATH (Debian package gnuplot-nox); it was not found");
  const ScratchDir scratch;
  std::vector<std::string> data_files;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const auto file = scratch.path / (numbered("segment", static_cast<long>(s)) + ".dat");
    std::ofstream out(file);
    out.precision(10);
    const auto& seg = segments[s];
    for (std::size_t k = 0; k < seg.t.size(); ++k)
      out << seg.t[k] << ' ' << seg.measured[k] << ' ' << seg.model[k] << ' '
          << seg.measured[k] - seg.model[k] << '\n';
    data_files.push_back(file.string());
  }
  const auto script_path = scratch.path / "plot.gp";
  // gnuplot draws into the atomic writer's temporary file beside the target.
  write_file_atomically_with(png_path, [&](const std::filesystem::path& temp) {
    {
      std::ofstream(script_path) << fit_plot_script(temp.string(), title, output_label, segments,
                                                    data_files);
    }
    const std::string program = "gnuplot";
    const std::string script = script_path.string();
    char* argv[] = {const_cast<char*>(program.c_str()), const_cast<char*>(script.c_str()), nullptr};
    pid_t pid = 0;
    if (posix_spawnp(&pid, program.c_str(), nullptr, nullptr, argv, environ) != 0)
      throw InputError("--plot: could not start gnuplot");
    int status = 0;
    if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
      throw InputError("--plot: gnuplot failed writing " + png_path);
    return true;
  });
}

}  // namespace rheomag::identify
