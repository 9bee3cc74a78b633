#pragma once
// A sweep's results drawn as a grid: each output column against each swept key.

#include <filesystem>
#include <string>
#include <vector>

#include "plot/figure.hpp"

namespace rheomag::figures {

/// A results table read from a sweep's CSV: its column names and, per row with status "ok",
/// the numbers (NaN where a cell is empty or not a number).
struct SweepTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

/// Reads the sweep results file `csv` (header line, then rows; fields may be double-quoted).
/// Only rows whose "status" is "ok" are kept. InputError naming the file when it cannot be read
/// or has no "status" column.
SweepTable read_sweep_table(const std::filesystem::path& csv);

/// One panel per (output, key): the output column against the key column, a row of panels per
/// output. The outputs are the columns after the keys up to "status" that hold a finite number
/// in some row (design_id, the keys, status and error are not outputs). With one other key of at
/// most 8 values, one line per value of it; otherwise dots. Each panel is panel_width x
/// panel_height pixels. InputError when a key is not a column.
plot::Figure sweep_figure(const SweepTable& table, const std::vector<std::string>& keys,
                          int panel_width, int panel_height);

}  // namespace rheomag::figures
