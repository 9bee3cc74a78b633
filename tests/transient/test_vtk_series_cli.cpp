// `transient --vtk-series DIR --vtk-stride N` on the bundled annular valve (1 A current step,
// 10 equal steps of 5 ms): the first state, every Nth and the last are written, and each .vtu
// holds the eddy-current density J_phi = -sigma dA/dt as a cell array with Lenz's sign.

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kValve = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

/// Runs the step with `stride` into a fresh folder; returns the JSON and the folder.
nlohmann::json run_series(int stride, fs::path& dir) {
  dir = fs::temp_directory_path() /
        ("rheomag_vtk_stride_" + std::to_string(::getpid()) + "_" + std::to_string(stride));
  fs::remove_all(dir);
  const auto run = rheomag::cli_test::run_rheomag(
      "transient '" + kValve + "' --current 1 --duration 0.05 --steps 10 --quiet --json " +
      "--vtk-series '" + dir.string() + "' --vtk-stride " + std::to_string(stride));
  EXPECT_EQ(run.code, 0) << run.err;
  return nlohmann::json::parse(run.out);
}

int vtu_files(const fs::path& dir) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir)) n += entry.path().extension() == ".vtu";
  return n;
}

/// The J_phi cell array of a .vtu file.
std::vector<double> j_phi(const fs::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkDataArray* array = reader->GetOutput()->GetCellData()->GetArray("J_phi");
  std::vector<double> values;
  if (!array) return values;
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i) values.push_back(array->GetTuple1(i));
  return values;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

TEST(VtkSeriesCli, StrideKeepsTheFirstEveryNthAndTheLastState) {
  fs::path all_dir, strided_dir;
  const nlohmann::json all = run_series(1, all_dir);
  const nlohmann::json strided = run_series(4, strided_dir);
  const int states = all["vtk_files"];
  ASSERT_GE(states, 11);  // t = 0 and 10 steps at least
  EXPECT_EQ(vtu_files(all_dir), states);
  // Indices 0, 4, 8, ... and the last one if it is not among them.
  const int expected = (states - 1) / 4 + 1 + ((states - 1) % 4 != 0 ? 1 : 0);
  EXPECT_EQ(strided["vtk_files"].get<int>(), expected);
  EXPECT_EQ(vtu_files(strided_dir), expected);
  // The series lists the last time, 0.05 s.
  std::ifstream pvd(strided_dir / "series.pvd");
  const std::string text((std::istreambuf_iterator<char>(pvd)), {});
  EXPECT_NE(text.find("timestep=\"0.05\""), std::string::npos) << text;
  fs::remove_all(all_dir);
  fs::remove_all(strided_dir);
}

// J_phi = -sigma dA/dt: none at t = 0 (no change yet); after the first step it flows in the
// conducting steel only (the coil is stranded, air and fluid do not conduct), against the rising
// coil current (Lenz: mostly negative where the coil's positive current builds the field), and
// it decays as the field settles (the last state's peak below the first step's).
TEST(VtkSeriesCli, EddyCurrentDensityIsACellArrayWithLenzSign) {
  fs::path dir;
  run_series(1, dir);
  const std::vector<double> first = j_phi(dir / "state_00000.vtu");
  const std::vector<double> step = j_phi(dir / "state_00002.vtu");
  ASSERT_FALSE(first.empty()) << "no J_phi cell array";
  ASSERT_EQ(first.size(), step.size());
  EXPECT_EQ(max_abs(first), 0.0);
  const auto nonzero = std::count_if(step.begin(), step.end(), [](double j) { return j != 0.0; });
  EXPECT_GT(nonzero, 0);
  EXPECT_LT(nonzero, static_cast<long>(step.size()));
  double sum = 0.0;
  for (double j : step) sum += j;
  EXPECT_LT(sum, 0.0);
  int last = vtu_files(dir) - 1;
  char name[32];
  std::snprintf(name, sizeof name, "state_%05d.vtu", last);
  EXPECT_LT(max_abs(j_phi(dir / name)), max_abs(step));
  fs::remove_all(dir);
}
