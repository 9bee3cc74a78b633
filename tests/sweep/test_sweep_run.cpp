// Running sweeps through the library: --jobs independence, error rows, mesh reuse against direct
// solves, shards, resume after a torn row, refusing another sweep's file and output checks.

#include <gtest/gtest.h>

#include <sstream>

#include <algorithm>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "sweep/evaluate.hpp"
#include "sweep/run.hpp"
#include "sweep/valve_columns.hpp"
#include "sweep_fixture.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::sweep {
namespace {

// The design's case the independent way: its values written into the base case's TOML text and
// that text read as a case file (the sweep itself edits the typed case; both must agree).
cases::Case design_case_via_text(const SweepSpec& spec, const Design& design,
                                 const std::string& source) {
  toml::table table = spec.base.table;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    toml::node* node = &table;
    const auto& path = spec.axes[a].key.path;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
      node = node->is_table() ? node->as_table()->get(path[i])
                              : node->as_array()->get(std::stoul(path[i]));
    std::visit([&](const auto& v) { node->as_table()->insert_or_assign(path.back(), v); },
               design.values[a]);
  }
  std::ostringstream text;
  text << table;
  return cases::parse_case(text.str(), source);
}

using namespace testing;

// 2 widths x 2 neck radii x 2 currents = 8 designs; neck_radius = 19 mm leaves no room for the
// coil (core radius 19.0 mm - 0.5 sleeve - 1 bobbin < 19): an impossible geometry.
const std::string kAxes =
    "[[axis]]\nkey = \"geometry.gap_width\"\nvalues = [0.8, 1.2]\n"
    "[[axis]]\nkey = \"geometry.neck_radius\"\nvalues = [10.5, 19.0]\n"
    "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 1.0]\n";

SweepSummary run_in(const std::filesystem::path& dir, const std::string& text, int jobs,
                    Shard shard = {}, bool valve = false) {
  const SweepSpec spec = parse_sweep(text, dir / "sweep.toml");
  SweepRunOptions options;
  if (valve) options.extra_columns = valve_columns(spec);
  options.jobs = jobs;
  options.out_dir = dir;
  options.shard = shard;
  options.handle_signals = false;
  return run_sweep(spec, options);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (char c : line) {
    if (c == ',') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(cell);
  return cells;
}

std::size_t column(const std::string& header, const std::string& name) {
  const auto names = split(header);
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

TEST(SweepRun, OneAndTwoJobsGiveTheSameCsvAndErrorRowsDoNotStopTheSweep) {
  const auto one = scratch_dir("jobs1"), two = scratch_dir("jobs2");
  const SweepSummary s1 = run_in(one, sweep_text("", kAxes), 1);
  const SweepSummary s2 = run_in(two, sweep_text("", kAxes), 2);
  const std::string csv1 = read_text(one / "results.csv");
  const std::string csv2 = read_text(two / "results.csv");
  EXPECT_EQ(csv1, csv2);  // byte for byte
  EXPECT_FALSE(s1.interrupted);
  EXPECT_EQ(s1.evaluated, 8);
  EXPECT_EQ(s1.errors, 4);
  EXPECT_EQ(s2.errors, 4);
  const auto lines = lines_of(csv1);
  ASSERT_EQ(lines.size(), 9u);
  const std::size_t status = column(lines[0], "status");
  const std::size_t neck = column(lines[0], "geometry.neck_radius");
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto cells = split(lines[i]);
    EXPECT_EQ(cells[0], std::to_string(i - 1));  // sorted by design id
    if (cells[neck] == "19") {
      EXPECT_EQ(cells[status], "error") << lines[i];
      EXPECT_NE(lines[i].find("coil depth"), std::string::npos) << lines[i];
    } else {
      EXPECT_EQ(cells[status], "ok") << lines[i];
    }
  }
}

TEST(SweepRun, ReusedMeshGivesTheNumbersOfADirectSolve) {
  // Reference: solve_problem on the same design case file (its own meshing and solver). The
  // sweep meshes once and reuses the solver (symbolic analysis) for the other currents; the CSV
  // cells must equal the direct solve's values formatted the same way (the mesher is
  // deterministic and the reused solver discards its numeric factorisation).
  const auto dir = scratch_dir("reuse");
  const std::string axes = "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 1.0, 1.5]\n";
  const std::string text = sweep_text("", axes);
  const SweepSummary summary = run_in(dir, text, 1);
  EXPECT_EQ(summary.meshes_built, 1);
  EXPECT_EQ(summary.meshes_reused, 0);
  EXPECT_EQ(summary.solvers_reused, 2);  // only the current changes: one solver, analysed once
  const SweepSpec spec = parse_sweep(text, dir / "sweep.toml");
  const DesignGenerator designs(spec);
  const auto lines = lines_of(read_text(dir / "results.csv"));
  ASSERT_EQ(lines.size(), 4u);
  const std::size_t b_avg = column(lines[0], "gap_top.B_avg_T");
  const std::size_t inductance = column(lines[0], "coil.inductance_H");
  for (long long id = 0; id < 3; ++id) {
    const auto direct_case = design_case_via_text(spec, designs.design(id), tiny_valve().string());
    const auto direct = magnetostatics::solve_problem(direct_case.problem);
    const auto cells = split(lines[static_cast<std::size_t>(id) + 1]);
    EXPECT_EQ(cells[b_avg], csv_number(direct.results.gaps.at(0).b.average));
    // The other two gap columns carry the names of docs/quantities.md (issue 34): the mid-line
    // maximum and the area maximum, the same numbers as solve's B_max_midline and B_max_area.
    EXPECT_EQ(cells.at(column(lines[0], "gap_top.B_max_midline_T")),
              csv_number(direct.results.gaps.at(0).line_b.maximum));
    EXPECT_EQ(cells.at(column(lines[0], "gap_top.B_max_area_T")),
              csv_number(direct.results.gaps.at(0).b.maximum));
    EXPECT_EQ(cells[inductance], csv_number(direct.results.circuits.at(0).inductance));
  }
  // The current enters linearly below saturation: a sanity check that the rows differ.
  EXPECT_NE(split(lines[1])[b_avg], split(lines[3])[b_avg]);
}

TEST(SweepRun, ShardsTogetherEqualTheFullSweep) {
  const auto full = scratch_dir("full"), parts = scratch_dir("shards");
  run_in(full, sweep_text("", kAxes), 1);
  std::vector<std::string> rows;
  for (long long i = 0; i < 3; ++i) {
    const SweepSummary s = run_in(parts, sweep_text("", kAxes), 1, Shard{i, 3});
    EXPECT_EQ(s.csv.filename().string(), "results.part-" + std::to_string(i) + "-of-3.csv");
    const auto lines = lines_of(read_text(s.csv));
    for (std::size_t k = 1; k < lines.size(); ++k) {
      EXPECT_EQ(std::stoll(lines[k]) % 3, i);
      rows.push_back(lines[k]);
    }
  }
  std::sort(rows.begin(), rows.end(), [](const std::string& a, const std::string& b) {
    return std::stoll(a) < std::stoll(b);
  });
  const auto expected = lines_of(read_text(full / "results.csv"));
  EXPECT_EQ(rows, std::vector<std::string>(expected.begin() + 1, expected.end()));
}

TEST(SweepRun, ResumeAfterATornRowEqualsAnUninterruptedRun) {
  const auto full = scratch_dir("uninterrupted"), resumed = scratch_dir("resumed");
  run_in(full, sweep_text("", kAxes), 1);
  const std::string complete = read_text(full / "results.csv");
  const auto lines = lines_of(complete);
  // As a killed run leaves it: some finished rows in completion order, then a row cut short.
  write_file(resumed, "results.csv",
             lines[0] + "\n" + lines[3] + "\n" + lines[1] + "\n" + lines[5].substr(0, 10));
  const SweepSummary s = run_in(resumed, sweep_text("", kAxes), 2);
  EXPECT_EQ(s.resumed, 2);
  EXPECT_EQ(s.evaluated, 6);
  EXPECT_EQ(read_text(resumed / "results.csv"), complete);
  // A second run finds everything done, solves nothing and leaves the file as it is.
  const SweepSummary again = run_in(resumed, sweep_text("", kAxes), 2);
  EXPECT_EQ(again.evaluated, 0);
  EXPECT_EQ(read_text(resumed / "results.csv"), complete);
}

TEST(SweepRun, RefusesToResumeAnotherSweepsFile) {
  const auto dir = scratch_dir("other");
  run_in(dir, sweep_text("", "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 1.0]\n"), 1);
  const std::string before = read_text(dir / "results.csv");
  try {
    run_in(dir, sweep_text("", "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 2.0]\n"), 1);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not belong to this sweep"), std::string::npos);
  }
  EXPECT_EQ(read_text(dir / "results.csv"), before);
}

TEST(SweepRun, UnwritableOutputOrTooLittleSpaceIsAnInputErrorAndWritesNothing) {
  const auto dir = scratch_dir("output");
  write_file(dir, "a-file", "x");
  const std::string text = sweep_text("", "[[axis]]\nkey = \"circuit.current\"\nvalues = [1]\n");
  EXPECT_THROW(run_in(dir / "a-file" / "out", text, 1), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "a-file" / "out"));
  // The free-space check with more bytes than any disk has (the sweep's own estimate is
  // compared the same way before the CSV is created).
  try {
    require_free_space(dir, 1e21, "1 CSV row");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("too large for the disk"), std::string::npos);
  }
  EXPECT_NO_THROW(require_free_space(dir, 1.0, "1 CSV row"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);  // only a-file: no CSV, no probe left behind
}

TEST(SweepRun, VtuPerDesign) {
  const auto dir = scratch_dir("vtu");
  const std::string text =
      sweep_text("", "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 1.0]\n",
                 "csv = \"r.csv\"\nvtu = true\n");
  run_in(dir, text, 2);
  EXPECT_GT(std::filesystem::file_size(dir / "r_vtu" / "design-000000.vtu"), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir / "r_vtu" / "design-000001.vtu"), 1000u);
}

TEST(SweepRun, ValveColumnsEqualADirectValveChainAndGrowWithCurrent) {
  // Reference: valve::ValveChain on the same design case (docs/fluid.md); the sweep must pass
  // its pressure drop and coil numbers through unchanged. Physics check: the yield part of the
  // pressure drop grows with the current (tau_y grows with B below saturation).
  const auto dir = scratch_dir("valve");
  const auto base = write_file(
      dir, "valve.toml", read_text(tiny_valve()) + "\n[valve]\nwire = \"AWG 24\"\nflow = 2.0e-6\n");
  const std::string text = "[sweep]\nbase = \"" + base.string() +
                           "\"\n[[axis]]\nkey = \"circuit.current\"\nvalues = [0.25, 1.0]\n";
  const SweepSummary summary = run_in(dir, text, 2, {}, true);
  EXPECT_EQ(summary.errors, 0);
  const auto lines = lines_of(read_text(dir / "results.csv"));
  ASSERT_EQ(lines.size(), 3u);
  const std::size_t dp = column(lines[0], "dp_total_Pa");
  const std::size_t dp_yield = column(lines[0], "dp_yield_Pa");
  const std::size_t resistance = column(lines[0], "coil_resistance_Ohm");
  const std::size_t power = column(lines[0], "coil_power_W");
  ASSERT_LT(power, split(lines[0]).size());
  const SweepSpec spec = parse_sweep(text, dir / "sweep.toml");
  const DesignGenerator designs(spec);
  for (long long id = 0; id < 2; ++id) {
    const auto design_case = design_case_via_text(spec, designs.design(id), base.string());
    const auto options = valve::read_valve_options(design_case);
    valve::ValveChain chain(design_case, options);
    const double current = design_case.problem.circuits.at(0).current;
    const auto point = chain.evaluate({current}, options.flows).at(0);
    const auto cells = split(lines[static_cast<std::size_t>(id) + 1]);
    EXPECT_EQ(cells[dp], csv_number(point.dp_total));
    EXPECT_EQ(cells[resistance], csv_number(chain.coil(current, point.inductance).resistance));
  }
  EXPECT_GT(std::stod(split(lines[2])[dp_yield]), std::stod(split(lines[1])[dp_yield]));
}

}  // namespace
}  // namespace rheomag::sweep
