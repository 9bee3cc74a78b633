#include "figures/sweep_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <numeric>

#include "core/error.hpp"
#include "plot/line_plot.hpp"

namespace rheomag::figures {

namespace {

/// The fields of one CSV line ("a","b,c" quoted fields; "" inside quotes is a quote).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        fields.back() += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      fields.emplace_back();
    } else if (ch != '\r') {
      fields.back() += ch;
    }
  }
  return fields;
}

/// The number in `text`, NaN when it is empty or not wholly a number.
double cell_number(const std::string& text) {
  if (text.empty()) return std::nan("");
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return end && *end == '\0' ? v : std::nan("");
}

/// Index of column `name`, or -1.
int column_of(const SweepTable& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  return it == t.columns.end() ? -1 : static_cast<int>(it - t.columns.begin());
}

}  // namespace

SweepTable read_sweep_table(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  if (!in) throw InputError(csv.string() + ": cannot be read");
  SweepTable table;
  std::string line;
  if (!std::getline(in, line)) throw InputError(csv.string() + ": empty, expected a header");
  table.columns = csv_fields(line);
  const int status = column_of(table, "status");
  if (status < 0) throw InputError(csv.string() + ": no 'status' column (not a sweep's results)");
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = csv_fields(line);
    if (static_cast<int>(fields.size()) <= status || fields[status] != "ok") continue;
    std::vector<double> row;
    for (const std::string& f : fields) row.push_back(cell_number(f));
    row.resize(table.columns.size(), std::nan(""));
    table.rows.push_back(std::move(row));
  }
  return table;
}

plot::Figure sweep_figure(const SweepTable& table, const std::vector<std::string>& keys,
                          int panel_width, int panel_height) {
  std::vector<int> key_columns;
  for (const std::string& k : keys) {
    const int c = column_of(table, k);
    if (c < 0) throw InputError("sweep results: no column '" + k + "'");
    key_columns.push_back(c);
  }
  const int first_output =
      key_columns.empty() ? 1 : *std::max_element(key_columns.begin(), key_columns.end()) + 1;
  const int status = column_of(table, "status");
  std::vector<int> outputs;
  for (int c = first_output; c < status; ++c) {
    const bool any = std::any_of(table.rows.begin(), table.rows.end(),
                                 [c](const std::vector<double>& r) { return std::isfinite(r[c]); });
    if (any) outputs.push_back(c);
  }
  const int columns = std::max<int>(1, static_cast<int>(key_columns.size()));
  const int rows = std::max<int>(1, static_cast<int>(outputs.size()));
  plot::Figure figure(columns * panel_width, rows * panel_height);
  for (int o = 0; o < static_cast<int>(outputs.size()); ++o) {
    for (int k = 0; k < static_cast<int>(key_columns.size()); ++k) {
      const int x = key_columns[k], y = outputs[o];
      // Group by the other key when there is exactly one and it has few values.
      int other = -1;
      if (key_columns.size() == 2) other = key_columns[1 - k];
      std::map<double, std::vector<std::size_t>> groups;
      for (std::size_t r = 0; r < table.rows.size(); ++r)
        groups[other >= 0 ? table.rows[r][other] : 0.0].push_back(r);
      const bool lines = other >= 0 && groups.size() <= 8;
      if (!lines) {
        groups.clear();
        std::vector<std::size_t> all(table.rows.size());
        std::iota(all.begin(), all.end(), std::size_t{0});
        groups[0.0] = all;
      }
      plot::LinePlot p;
      p.title = table.columns[y] + " against " + table.columns[x];
      p.x_label = table.columns[x];
      p.y_label = table.columns[y];
      int colour = 0;
      for (auto& [value, members] : groups) {
        std::sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) {
          return table.rows[a][x] < table.rows[b][x];
        });
        plot::Series s;
        if (lines) {
          char name[96];
          // The key's last part ("gap_width" of "geometry.gap_width"): the legend is narrow.
          const std::string& key = table.columns[other];
          const std::string short_key = key.substr(key.find_last_of('.') + 1);
          std::snprintf(name, sizeof name, "%s = %g", short_key.c_str(), value);
          s.name = name;
        }
        s.colour = plot::series_colour(colour++);
        s.markers = true;
        for (std::size_t r : members) {
          s.x.push_back(table.rows[r][x]);
          s.y.push_back(table.rows[r][y]);
        }
        if (!lines) {  // dots only: every point its own piece of line
          std::vector<double> xs, ys;
          for (std::size_t i = 0; i < s.x.size(); ++i) {
            xs.insert(xs.end(), {s.x[i], std::nan("")});
            ys.insert(ys.end(), {s.y[i], std::nan("")});
          }
          s.x = xs, s.y = ys;
        }
        p.series.push_back(std::move(s));
      }
      plot::draw_line_plot(figure.cr(),
                           {double(k * panel_width), double(o * panel_height), double(panel_width),
                            double(panel_height)},
                           p);
    }
  }
  return figure;
}

}  // namespace rheomag::figures
