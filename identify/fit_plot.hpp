#pragma once
// Comparison figure of a fit (measured vs model, and the residual) drawn by gnuplot (Debian
// gnuplot-nox), run as a child process on a generated script.

#include <string>
#include <vector>

namespace rheomag::identify {

/// One stretch of a recording to draw: its times, measurement and model output.
struct PlotSegment {
  std::string label;  ///< e.g. "training", "validation"
  std::vector<double> t, measured, model;
};

/// True if a `gnuplot` executable is on PATH.
bool gnuplot_available();

/// The gnuplot script drawing `segments` (their samples in `data_files`, one per segment: t,
/// measured, model, residual) into `png_path`. The text is drawn as written (no enhanced-text
/// markup: an underscore in a file name is not a subscript).
std::string fit_plot_script(const std::string& png_path, const std::string& title,
                            const std::string& output_label,
                            const std::vector<PlotSegment>& segments,
                            const std::vector<std::string>& data_files);

/// Writes a PNG (atomically: temp file + rename) with two panels: measured and model output of
/// each segment over time, and the residual. InputError if gnuplot is missing or fails.
void write_fit_plot(const std::string& png_path, const std::string& title,
                    const std::string& output_label, const std::vector<PlotSegment>& segments);

}  // namespace rheomag::identify
